"""Runs the scripts of examples/ as a user would: the paraview.simple examples under pvbatch on a
private X server (refines the FinFET, colours by ColorId, saves a screenshot, which must not be
blank; refines it to a size field made with the Calculator, which must put 90% of the edges
within bounds, and saves a picture coloured by EdgeLengthRatio), and the plain-VTK example under
/usr/bin/python3 with the wrapped module."""
import argparse
import os
import re
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

    # The size-field example: Calculator -> size field -> adaptation -> EdgeLengthRatio picture.
    # Its printed summary must show the mesh refined, the passes converged and 90% or more of
    # the edges within [h/sqrt2, sqrt2 h].
    sized = os.path.join(options.scratch, "finfet-size-field.png")
    if os.path.exists(sized):
        os.remove(sized)
    server, display = start_xvfb()
    try:
        run = subprocess.run([options.pvbatch, os.path.join(options.examples,
                                                            "refine_to_size_field.py"),
                              options.data, sized, "--plugin", options.plugin, "--threads", "2"],
                             env=dict(os.environ, DISPLAY=display), check=True, timeout=300,
                             stdout=subprocess.PIPE, text=True)
    finally:
        stop(server)
    print(run.stdout, end="")
    error = error or check_not_blank(sized)
    summary = re.search(r"(\d+) -> (\d+) cells.*\((converged|iteration limit)\), "
                        r"EdgesWithinSizeBounds ([0-9.]+)", run.stdout)
    if not summary:
        error = error or "refine_to_size_field.py printed no summary"
    elif not (int(summary.group(2)) > int(summary.group(1)) and summary.group(3) == "converged"
              and float(summary.group(4)) >= 0.9):
        error = error or "size-field example: " + summary.group(0)

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
