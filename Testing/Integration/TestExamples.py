"""Runs the scripts of examples/ as a user would: the paraview.simple example under pvbatch on a
private X server (refines the FinFET, colours by ColorId, saves a screenshot, which must not be
blank), and the plain-VTK example under /usr/bin/python3 with the wrapped module."""
import argparse
import os
import subprocess
import sys

from image_checks import check_not_blank, start_xvfb, stop


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--examples", required=True)
    parser.add_argument("--pvbatch", required=True)
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--pythonpath", required=True)
    parser.add_argument("--data", required=True)
    parser.add_argument("--scratch", required=True)
    options = parser.parse_args()
    os.makedirs(options.scratch, exist_ok=True)

    screenshot = os.path.join(options.scratch, "finfet-colors.png")
    if os.path.exists(screenshot):
        os.remove(screenshot)
    server, display = start_xvfb()
    try:
        subprocess.run([options.pvbatch, os.path.join(options.examples, "refine_and_render.py"),
                        options.data, screenshot, "--plugin", options.plugin,
                        "--region-array", "Material"],
                       env=dict(os.environ, DISPLAY=display), check=True, timeout=300)
    finally:
        stop(server)
    error = check_not_blank(screenshot)

    refined = os.path.join(options.scratch, "finfet-refined.vtu")
    subprocess.run([sys.executable, os.path.join(options.examples, "refine_with_vtk.py"),
                    options.data, refined, "--region-array", "Material", "--threads", "1"],
                   env=dict(os.environ, PYTHONPATH=options.pythonpath), check=True, timeout=300)
    if not os.path.isfile(refined):
        error = error or "refine_with_vtk.py wrote no " + refined
    if error:
        print(error, file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
