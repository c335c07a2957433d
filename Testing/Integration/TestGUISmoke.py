"""GUI smoke test: the real ParaView GUI on a private Xvfb runs GUISmokeScript.py (loads the
plugin, refines the FinFET, saves a screenshot, writes the output cell count; refines it again in
a box set through the box widget's properties). The screenshot must not be blank and the counts
must equal those of the command line with the same parameters (the box as --refine-box).

The GUI gets a private HOME and XDG_CONFIG_HOME with ShowWelcomeDialog=0, so that neither the
user's settings nor the modal welcome dialog get in the way. It does not exit by itself after
--script: the driver waits for the script's done file and then ends the GUI (and the Xvfb) it
started. With --window-screenshot FILE the whole screen, GUI panels included, is captured too
(needs python3-pil; used for the README picture).
"""
import argparse
import json
import os
import subprocess
import sys
import time

from image_checks import check_not_blank, start_xvfb, stop

# pqWelcomeDialog reads GeneralSettings.ShowWelcomeDialog; the plain key is the settings proxy's.
SETTINGS = "[General]\nGeneralSettings.ShowWelcomeDialog=0\nShowWelcomeDialog=0\n"


def command_line_cell_count(options, extra=()):
    stats = os.path.join(options.scratch, "cli-stats.json")
    subprocess.run([options.cgmesh, "refine", options.data,
                    os.path.join(options.scratch, "cli-refined.vtu"), "--region-array", "Material",
                    "--partitions", "64", "--edge-length-factor", "0.5", "--threads", "1",
                    "--stats", stats] + list(extra), check=True, stdout=subprocess.DEVNULL,
                   timeout=300)
    with open(stats) as stats_file:
        return json.load(stats_file)["output"]["cells"]


def run_gui(options, files):
    home = os.path.join(options.scratch, "home")
    config = os.path.join(home, ".config")
    os.makedirs(os.path.join(config, "ParaView"), exist_ok=True)
    with open(os.path.join(config, "ParaView", "ParaView5.11.0.ini"), "w") as settings:
        settings.write(SETTINGS)
    server, display = start_xvfb()
    environment = dict(os.environ, DISPLAY=display, HOME=home, XDG_CONFIG_HOME=config,
                       XDG_RUNTIME_DIR=options.scratch,
                       CGMESH_GUI_PLUGIN=options.plugin, CGMESH_GUI_DATA=options.data,
                       CGMESH_GUI_SCREENSHOT=files["screenshot"], CGMESH_GUI_COUNT=files["count"],
                       CGMESH_GUI_DONE=files["done"])
    with open(files["log"], "w") as log:
        gui = subprocess.Popen([options.paraview, "--script=" + options.script], env=environment,
                               stdout=log, stderr=subprocess.STDOUT)
    try:
        deadline = time.monotonic() + options.timeout
        while not os.path.exists(files["done"]):
            if gui.poll() is not None:
                return "paraview exited with status %d before the script finished" % gui.returncode
            if time.monotonic() > deadline:
                return "the GUI script did not finish within %d s" % options.timeout
            time.sleep(0.5)
        if options.window_screenshot:
            time.sleep(2)  # let the GUI repaint its panels after the script
            from PIL import ImageGrab
            screen = ImageGrab.grab(xdisplay=display)
            # The main window does not fill the screen: keep the window, not the black around it.
            screen.crop(screen.convert("L").point(lambda level: 255 if level else 0).getbbox()) \
                .save(options.window_screenshot)
        return None
    finally:
        stop(gui)
        stop(server)


def main():
    parser = argparse.ArgumentParser()
    for name in ("paraview", "script", "plugin", "cgmesh", "data", "scratch"):
        parser.add_argument("--" + name, required=True)
    parser.add_argument("--timeout", type=int, default=240)
    parser.add_argument("--window-screenshot")
    options = parser.parse_args()
    os.makedirs(options.scratch, exist_ok=True)
    files = {name: os.path.join(options.scratch, file_name) for name, file_name in (
        ("screenshot", "gui-view.png"), ("count", "gui-cells.txt"), ("done", "gui-done.txt"),
        ("log", "paraview.log"))}
    for path in files.values():
        if os.path.exists(path):
            os.remove(path)

    error = run_gui(options, files)
    if error:
        with open(files["log"]) as log:
            print(log.read()[-4000:], file=sys.stderr)
        print(error, file=sys.stderr)
        return 1
    error = check_not_blank(files["screenshot"])
    with open(files["count"]) as count_file:
        gui_cells = int(count_file.readline())
        gui_box_cells, box = count_file.readline().split()
        gui_box_cells = int(gui_box_cells)
    cli_cells = command_line_cell_count(options)
    cli_box_cells = command_line_cell_count(options, ["--refine-box", box])
    print("output cells: GUI %d, command line %d; in the box widget's box %s: GUI %d, command "
          "line %d" % (gui_cells, cli_cells, box, gui_box_cells, cli_box_cells))
    if gui_cells != cli_cells:
        error = error or "the GUI's filter gave %d cells, the command line %d" % (gui_cells,
                                                                                 cli_cells)
    if gui_box_cells != cli_box_cells or not cli_cells > gui_box_cells > cli_cells // 8:
        error = error or ("in the box the GUI's filter gave %d cells, the command line %d (%d "
                          "without the box)" % (gui_box_cells, cli_box_cells, cli_cells))
    if error:
        print(error, file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
