"""ParaView's GUI (5.11 or 5.13) with the TiledRayCast plugin, as a user meets it, against the exact reference.

Runs under Debian's /usr/bin/python3 and starts `paraview` from the private ParaView root under
xvfb-run (Xvfb with -noreset), with a fresh settings folder (no welcome dialog), gui_setup.py as its
start-up script and an event script of ParaView's own GUI testing (QtTesting) that:
  - checks that the Output Messages window stayed closed (no warning: loading the plugin and
    showing the mesh as Volume used to print 24 of ParaView's deprecation warnings);
  - picks "Tiled ray cast" in the Properties panel's "Select Mapper" combo box, checks that the
    box holds it and that the panel shows the plugin's section (its integration mode; its
    advanced settings hidden);
  - grabs the view's image (gui_session.record, from the GUI's Python shell);
  - drags the mouse across the view (a rotation through the GUI, its interactive renders),
    reads the mapper's statistics while the button is held, releases it, and grabs the view
    again;
  - checks again that no Output Messages window opened.
Then checks: both images against the exact reference (the scene tests' bounds); the frames
drawn during the drag at a coarser image sample distance than 1 (ParaView's interactive renders
ask for 5 frames a second; llvmpipe draws the full frame slower than that), the still frame
after it at 1; the camera turned by the drag.
Exit status 125 (a ctest skip, with the reason) when the private root or the plugin is missing.
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import time

import TestParaViewPlugin as single  # noqa: E402 (the colour map and reference set-up)

MAIN = "pqClientMainWindow"
PANEL = (MAIN + "/propertiesDock/propertiesPanel/scrollArea/qt_scrollarea_viewport/"
         "scrollAreaWidgetContents/DisplayFrame/ProxyPanel")
VIEW = (MAIN + "/centralwidget/MultiViewWidget/CoreWidget/qt_tabwidget_stackedwidget/"
        "MultiViewWidget1/Container/Frame.0/CentralWidgetFrame/Viewport")
SHELL = MAIN + "/pythonShellDock/pythonShell/consoleWidget"
OUTPUT_MESSAGES = MAIN + "/outputWidgetDock"

# The drag: from the view's centre to the right, in steps of 2% of its width.
DRAG = [(0.5 + 0.02 * k, 0.5) for k in range(8)]


def event(obj, command, arguments):
    return '  <pqevent object="%s" command="%s" arguments="%s" />' % (obj, command, arguments)


def check(obj, prop, value):
    return '  <pqcheck object="%s" property="%s" arguments="%s" />' % (obj, prop, value)


def python(statement):
    return event(SHELL, "executeCommand", statement)


def event_script():
    lines = [
        check(OUTPUT_MESSAGES, "visible", "false"),
        event(PANEL + "/SelectMapper/ComboBox", "activated", "Tiled ray cast"),
        check(PANEL + "/SelectMapper/ComboBox", "currentText", "Tiled ray cast"),
        check(PANEL + "/TiledRayCastIntegrationMode", "visible", "true"),
        check(PANEL + "/TiledRayCastPipeline", "visible", "false"),
        python("import gui_session; gui_session.record('still', True)"),
    ]
    x, y = DRAG[0]
    lines.append(event(VIEW, "mousePress", "(%g,%g,1,1,0)" % (x, y)))
    for x, y in DRAG[1:]:
        lines.append(event(VIEW, "mouseMove", "(%g,%g,1,1,0)" % (x, y)))
    lines.append(python("gui_session.record('interactive')"))
    lines.append(event(VIEW, "mouseRelease", "(%g,%g,1,0,0)" % DRAG[-1]))
    lines.append(python("gui_session.record('released', True)"))
    lines.append(check(OUTPUT_MESSAGES, "visible", "false"))
    return '<?xml version="1.0" ?>\n<pqevents>\n%s\n</pqevents>\n' % "\n".join(lines)


def run_paraview(options, output):
    """Runs the GUI with the event script; returns its exit status and what it printed."""
    config = os.path.join(output, "config")
    os.makedirs(os.path.join(config, "ParaView"))
    # A first start shows a modal welcome dialog, which would block the event script.
    # The settings file is named after ParaView's version, which the private root records
    # (ParaView/fetch-paraview.sh writes the package's, e.g. 5.13.2+dfsg-3).
    with open(os.path.join(options.root, ".complete")) as f:
        version = re.match(r"(\d+\.\d+\.\d+)", f.read().strip())
    if not version:
        raise SystemExit("cannot read ParaView's version from %s/.complete" % options.root)
    with open(os.path.join(config, "ParaView", "ParaView%s.ini" % version.group(1)), "w") as f:
        f.write("[General]\nGeneralSettings.ShowWelcomeDialog=false\n")
    events = os.path.join(output, "events.xml")
    with open(events, "w") as f:
        f.write(event_script())
    here = os.path.dirname(os.path.abspath(__file__))
    env = dict(os.environ)
    env["LD_LIBRARY_PATH"] = os.path.join(options.root, "usr", "lib", "x86_64-linux-gnu")
    env["PYTHONPATH"] = os.pathsep.join(
        [os.path.join(options.root, "usr", "lib", "python3", "dist-packages"), here])
    env["XDG_CONFIG_HOME"] = config
    env["TRC_GUI_PLUGIN"] = options.plugin
    env["TRC_GUI_MESH"] = options.mesh_file
    env["TRC_GUI_OUTPUT"] = output
    env.pop("PV_PLUGIN_PATH", None)
    command = [
        "xvfb-run", "-a", "-s", "-noreset -screen 0 1280x1024x24",
        os.path.join(options.root, "usr", "bin", "paraview"),
        "--script=" + os.path.join(here, "gui_setup.py"),
        "--test-script=" + events, "--exit",
    ]
    start = time.perf_counter()
    done = subprocess.run(command, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          text=True, timeout=options.timeout)
    print("paraview: %.1f s, exit status %d" % (time.perf_counter() - start, done.returncode))
    return done.returncode, done.stdout


def sample_distance(statistics):
    """The image sample distance the statistics' frame was drawn at (1 unless they say)."""
    found = re.search(r"image sample distance ([0-9.]+)", statistics or "")
    return float(found.group(1)) if found else 1.0


def load(output, step):
    """What gui_session.record wrote at `step`, or None (with the reason printed)."""
    error = os.path.join(output, step + ".error")
    if os.path.exists(error):
        with open(error) as f:
            print("the GUI's record of step %s failed:\n%s" % (step, f.read()))
        return None
    try:
        with open(os.path.join(output, step + ".json")) as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        print("no record of step %s: %s" % (step, e))
        return None


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--root", required=True)
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--case", default="gui")
    parser.add_argument("--mesh", default="bluntfin_tets")
    parser.add_argument("-D", dest="data", required=True)
    parser.add_argument("-T", dest="temp", required=True)
    parser.add_argument("--timeout", type=int, default=600)
    options = parser.parse_args()
    skip = single.skipped(options, "paraview")
    if skip:
        return skip
    options.mesh_file = os.path.join(options.data, "Meshes", options.mesh + ".vtu")
    output = os.path.join(options.temp, "ParaView_gui")
    shutil.rmtree(output, ignore_errors=True)
    os.makedirs(output)

    status, printed = run_paraview(options, output)
    # What the GUI printed on its terminal: QtTesting's failures ("critical:"), Python errors
    # from the shell, anything of VTK's or ParaView's that is a warning or an error.
    complaints = [line for line in printed.splitlines()
                  if single.WARNING.search(line) or line.startswith("critical")
                  or "Traceback" in line]
    ok = status == 0 and not complaints
    if not ok:
        print("the GUI's event script failed (exit status %d):\n%s"
              % (status, "\n".join(complaints) or printed[-4000:]))
        return 1

    still, interactive, released = (load(output, s) for s in ("still", "interactive", "released"))
    if not (still and interactive and released):
        return 1
    distances = [sample_distance(r["statistics"]) for r in (still, interactive, released)]
    print("mapper %s; image sample distance: before the drag %g, during it %g, after it %g"
          % (still["mapper"], *distances))
    print("statistics during the drag: %s" % interactive["statistics"])
    print("statistics after it: %s" % released["statistics"])
    if still["mapper"] != "Tiled ray cast" or not still["statistics"]:
        print("the view was not drawn by the tiled ray-cast mapper")
        ok = False
    if not (distances[1] > 1.0 and distances[2] == 1.0):
        print("the drag's frames are not coarser than the still frame after it")
        ok = False
    if still["camera"]["position"] == released["camera"]["position"]:
        print("the drag did not turn the camera")
        ok = False
    for step, result in (("still", still), ("released", released)):
        stats, map_difference = single.compare(os.path.join(output, step), result,
                                               options.mesh_file)
        ok = single.check("GUI view %s (%dx%d)" % ((step,) + tuple(result["size"])), stats,
                          map_difference, True) and ok
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
