"""Machine description and timed child processes (peak memory by /usr/bin/time)."""
import hashlib
import json
import os
import platform
import socket
import subprocess
import sys
import time

TIME = "/usr/bin/time"
# Processes of other work that would disturb the timings.
BUSY_NAMES = ("cgmesh", "ctest", "ninja", "cc1plus", "pvbatch")


def describe_machine():
    model = "unknown"
    with open("/proc/cpuinfo") as cpuinfo:
        for line in cpuinfo:
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    with open("/proc/meminfo") as meminfo:
        memory_kib = int(meminfo.readline().split()[1])
    return {"hostname": socket.gethostname(), "nproc": os.cpu_count(),
            "usableCores": len(os.sched_getaffinity(0)), "cpu": model,
            "memoryGiB": round(memory_kib / 2**20, 1), "kernel": platform.release(),
            "python": sys.version.split()[0]}


def other_work():
    """Command lines of running processes named in BUSY_NAMES that are not ours."""
    own = {os.getpid()}
    found = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit() or int(entry) in own:
            continue
        try:
            with open("/proc/%s/comm" % entry) as handle:
                name = handle.read().strip()
            with open("/proc/%s/stat" % entry) as handle:
                parent = int(handle.read().rsplit(")", 1)[1].split()[1])
            with open("/proc/%s/cmdline" % entry, "rb") as handle:
                command = handle.read().replace(b"\0", b" ").decode(errors="replace").strip()
        except (OSError, ValueError, IndexError):
            continue
        if parent in own:
            continue
        if any(name == busy or name.startswith(busy) for busy in BUSY_NAMES):
            found.append("%s: %s" % (entry, command[:160]))
    return found


def load_average():
    with open("/proc/loadavg") as handle:
        return [float(value) for value in handle.read().split()[:3]]


class RunFailed(RuntimeError):
    pass


def timed(command, log_file, env=None):
    """Runs command under /usr/bin/time; stdout+stderr go to log_file. Returns wall seconds
    and the peak resident memory in KiB (the largest of the process and its waited-for
    children, as getrusage reports it: TetGen worker processes are not summed)."""
    time_file = log_file + ".time"
    print("  $ " + " ".join(command), file=sys.stderr, flush=True)
    start = time.perf_counter()
    with open(log_file, "w") as log:
        result = subprocess.run([TIME, "-f", "%M %e", "-o", time_file] + command,
                                stdout=log, stderr=subprocess.STDOUT, env=env)
    wall = time.perf_counter() - start
    with open(time_file) as handle:
        lines = [line for line in handle.read().splitlines() if line.strip()]
    os.remove(time_file)
    if result.returncode != 0:
        with open(log_file) as log:
            tail = log.read()[-2000:]
        raise RunFailed("%s failed with status %d:\n%s" % (" ".join(command), result.returncode,
                                                          tail))
    peak_kib, _ = lines[-1].split()
    return {"wallSeconds": wall, "peakRssKiB": int(peak_kib)}


def load_json(path):
    with open(path) as handle:
        return json.load(handle)


def file_digest(path):
    digest = hashlib.sha256()
    with open(path, "rb") as handle:
        for block in iter(lambda: handle.read(1 << 22), b""):
            digest.update(block)
    return digest.hexdigest()


def count_warnings(log_file):
    with open(log_file, errors="replace") as handle:
        return sum(1 for line in handle if "warning" in line)
