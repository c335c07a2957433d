"""Helpers shared by the rendering tests: a private X server and a not-blank check for PNGs."""
import os
import socket
import subprocess
import time

from vtkmodules.vtkIOImage import vtkPNGReader


def start_xvfb(geometry="1280x1024x24", attempts=3):
    """Starts Xvfb on a display number it picks itself (-displayfd: no race between tests that
    start servers at the same time) and returns (process, ":N") once its socket accepts
    connections. A server that exits or never opens its socket (seen on fresh machines while an
    outer xvfb-run starts its own) is replaced, up to `attempts` times. -noreset: an X server
    resets when its last client leaves, and a client that connects during the reset is refused;
    the readiness probe below is such a last client, and pvbatch connecting right after it failed
    with "bad X server connection"."""
    last_error = "Xvfb did not start"
    for _ in range(attempts):
        read_end, write_end = os.pipe()
        server = subprocess.Popen(["Xvfb", "-displayfd", str(write_end), "-screen", "0", geometry,
                                   "-nolisten", "tcp", "-noreset"], pass_fds=(write_end,),
                                  stderr=subprocess.DEVNULL)
        os.close(write_end)
        with os.fdopen(read_end) as reader:
            number = reader.readline().strip()
        if number and _accepts_connections(server, number):
            return server, ":" + number
        last_error = "Xvfb on display :%s did not accept connections" % (number or "?")
        stop(server)
    raise RuntimeError(last_error)


def _accepts_connections(server, number, seconds=10.0):
    """True once the server's Unix socket takes a connection, False if it exits or times out."""
    path = "/tmp/.X11-unix/X" + number
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        if server.poll() is not None:
            return False
        with socket.socket(socket.AF_UNIX, socket.SOCK_STREAM) as probe:
            try:
                probe.connect(path)
                return True
            except OSError:
                pass
        time.sleep(0.05)
    return False


def stop(process, seconds=10):
    """Terminates a process this test started, waiting for it to go."""
    if process.poll() is None:
        process.terminate()
        try:
            process.wait(seconds)
        except subprocess.TimeoutExpired:
            process.kill()
            process.wait()


def image_summary(png_file):
    """(width, height, share of pixels that differ from the corner pixel, distinct colours)."""
    reader = vtkPNGReader()
    reader.SetFileName(png_file)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    scalars = image.GetPointData().GetScalars()
    components = min(scalars.GetNumberOfComponents(), 3)
    pixels = [tuple(int(scalars.GetComponent(i, c)) for c in range(components))
              for i in range(0, scalars.GetNumberOfTuples())]
    background = pixels[0]
    differing = sum(1 for pixel in pixels if pixel != background)
    return width, height, differing / max(len(pixels), 1), len(set(pixels))


def check_not_blank(png_file, minimum_share=0.05, minimum_colours=16):
    """Returns an error message, or None when the PNG exists and shows something."""
    if not os.path.isfile(png_file) or os.path.getsize(png_file) == 0:
        return "no image " + png_file
    width, height, share, colours = image_summary(png_file)
    if share < minimum_share or colours < minimum_colours:
        return "%s looks blank: %dx%d, %.1f%% non-background pixels, %d colours" % (
            png_file, width, height, 100 * share, colours)
    print("%s: %dx%d, %.1f%% non-background pixels, %d colours" % (
        png_file, width, height, 100 * share, colours))
    return None
