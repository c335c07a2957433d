"""Stress test of the TetGen worker pool through the command line: `cgmesh refine --method
delaunay` on a FinFET with 64 partitions, with the worker processes killed on chosen partitions
(the test hook CGMESH_TEST_KILL_TETGEN_PARTITIONS: a worker given a call for one of them kills
itself with SIGKILL), three times each at 2 and 4 threads. Every run must succeed; the partitions
that fall back to templates must be exactly the chosen ones, each after a worker death; every
other partition must still be refined by TetGen (the dead workers were replaced); the output must
be valid and conserve the material volumes; and all six output files must be identical."""
import argparse
import json
import os
import shutil
import subprocess
import sys

from TestCommandLine import digest, region_volumes

FAILURES = []
KILLED = [0, 9, 23, 42, 63]
REPEATS = 3


def check(condition, message):
    if not condition:
        FAILURES.append(message)
        print("check failed: " + message, file=sys.stderr)


def refine(cgmesh, mesh, output, threads, killed):
    """Runs the refinement; returns (completed process, statistics or None)."""
    environment = dict(os.environ)
    environment.pop("CGMESH_TEST_KILL_TETGEN_PARTITIONS", None)
    if killed:
        environment["CGMESH_TEST_KILL_TETGEN_PARTITIONS"] = ",".join(str(p) for p in killed)
    stats = output + ".json"
    result = subprocess.run(
        [cgmesh, "refine", mesh, output, "--region-array", "Material", "--method", "delaunay",
         "--partitions", "64", "--volume-factor", "0.3", "--threads", str(threads),
         "--stats", stats],
        capture_output=True, text=True, env=environment)
    if result.returncode != 0:
        return result, None
    with open(stats) as handle:
        return result, json.load(handle)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--cgmesh", required=True)
    parser.add_argument("--scratch", required=True)
    options = parser.parse_args()
    cgmesh, scratch = options.cgmesh, options.scratch
    shutil.rmtree(scratch, ignore_errors=True)
    os.makedirs(scratch)
    finfet = os.path.join(scratch, "finfet.vtu")
    result = subprocess.run([cgmesh, "generate", "finfet", finfet, "--cells", "6000"],
                            capture_output=True, text=True)
    check(result.returncode == 0, "generate finfet: " + result.stderr)

    # Without deaths no partition falls back or needs a second attempt, so every fallback and
    # retry below comes from a death.
    baseline = os.path.join(scratch, "baseline.vtu")
    result, statistics = refine(cgmesh, finfet, baseline, 2, [])
    check(statistics is not None, "baseline run failed: " + result.stderr)
    if statistics is None:
        return 1
    check(statistics["partitions"] == 64, "baseline: %d partitions" % statistics["partitions"])
    check(statistics["delaunayFallbacks"] == 0 and statistics["tetgenRetries"] == 0,
          "baseline: %d fallbacks, %d retries" % (statistics["delaunayFallbacks"],
                                                   statistics["tetgenRetries"]))
    baseline_points = statistics["tetgenPoints"]

    digests = {}
    for threads in (2, 4):
        for repeat in range(REPEATS):
            name = "killed-%dt-%d" % (threads, repeat)
            output = os.path.join(scratch, name + ".vtu")
            result, statistics = refine(cgmesh, finfet, output, threads, KILLED)
            check(statistics is not None, "%s: the run failed: %s" % (name, result.stderr))
            if statistics is None:
                continue
            digests[name] = digest(output)
            check(sorted(statistics["fallbackPartitions"]) == KILLED,
                  "%s: fallback partitions %s, not the killed %s"
                  % (name, statistics["fallbackPartitions"], KILLED))
            # Each killed partition: the call dies, the second attempt dies too.
            check(statistics["tetgenRetries"] == len(KILLED),
                  "%s: %d retries" % (name, statistics["tetgenRetries"]))
            # The other 59 partitions still went through TetGen, on replaced workers.
            check(0 < statistics["tetgenPoints"] < baseline_points,
                  "%s: %d TetGen points (baseline %d)"
                  % (name, statistics["tetgenPoints"], baseline_points))
            fallbacks = [warning for warning in statistics["warnings"]
                         if warning["kind"] == "delaunay-fallback"]
            check(sorted(warning["partition"] for warning in fallbacks) == KILLED and all(
                "the TetGen process stopped unexpectedly (TetGen aborted on this partition, "
                "SIGABRT)" in warning["text"]
                for warning in fallbacks),
                "%s: fallback warnings %s" % (name, fallbacks))
            for partition in KILLED:
                check("partition %d: Delaunay refinement failed" % partition in result.stderr,
                      "%s: stderr does not name partition %d" % (name, partition))

    check(len(digests) == 2 * REPEATS and len(set(digests.values())) == 1,
          "the outputs differ: %s" % digests)
    check(digest(baseline) not in digests.values(),
          "the outputs with deaths equal the one without (no partition fell back?)")
    before, _ = region_volumes(cgmesh, finfet)
    after, status = region_volumes(cgmesh, os.path.join(scratch, "killed-4t-0.vtu"))
    check(status == 0, "cgmesh check: the output with deaths is not a valid conforming mesh")
    check(len(before) > 1 and before.keys() == after.keys() and all(
        abs(after[region] - volume) <= 1e-9 * volume for region, volume in before.items()),
        "region volumes %s != input %s" % (after, before))

    if FAILURES:
        print("%d checks failed" % len(FAILURES), file=sys.stderr)
        return 1
    print("worker deaths on partitions %s: %d runs at 2 and 4 threads, identical outputs"
          % (KILLED, len(digests)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
