"""The ParaView GUI's side of TestParaViewGUI.py: runs inside `paraview` (its Python).

setup() runs as the GUI's --script at start: it loads the plugin and shows the mesh as Volume with
ParaView's default mapper ("Projected tetra"); the test's event script then picks "Tiled ray cast"
in the Properties panel, as a user would. record(step) runs from the Python shell, which the event
script drives between its GUI events: it writes what the step saw to <output>/<step>.json (the
mapper's statistics of the last frame drawn, the camera) and, with `screenshot`, the view's image
to <output>/<step>.png and what the exact reference needs to render the same view.

Set by the driver: TRC_GUI_PLUGIN (the plugin), TRC_GUI_MESH (a .vtu), TRC_GUI_OUTPUT (a folder).
"""
import json
import os
import traceback

from paraview.simple import (
    GetActiveViewOrCreate,
    LoadPlugin,
    Render,
    SaveScreenshot,
    SetActiveSource,
    XMLUnstructuredGridReader,
)

import paraview_scene as scene

_state = {}


def setup():
    LoadPlugin(os.environ["TRC_GUI_PLUGIN"], remote=False, ns=globals())
    reader = XMLUnstructuredGridReader(FileName=[os.environ["TRC_GUI_MESH"]])
    reader.UpdatePipeline()
    view = GetActiveViewOrCreate("RenderView")
    view.OrientationAxesVisibility = 0
    # ParaView's FXAA blurs a volume's silhouette against the background for every mapper
    # (pvbatch_render.py); the exact reference has none.
    view.UseFXAA = 0
    if hasattr(view, "UseColorPaletteForBackground"):
        view.UseColorPaletteForBackground = 0
    view.Background = [0.1, 0.1, 0.15]
    array = scene.first_varying_array(reader)
    display, lut, opacity, value_range = scene.show_volume(
        reader, view, array, -1, "Projected tetra", 0.05)
    # Statistics of the frame just drawn, not of an earlier one whose GPU results had arrived.
    display.TiledRayCastSynchronousStatistics = 1
    view.ResetCamera()
    camera = view.GetActiveCamera()
    camera.Azimuth(30.0)
    camera.Elevation(20.0)
    camera.OrthogonalizeViewUp()
    view.ResetCamera()
    SetActiveSource(reader)
    Render(view)
    _state.update(view=view, display=display, array=array, value_range=value_range, lut=lut,
                  opacity=opacity)


def record(step, screenshot=False):
    """Writes the step's JSON (and image); a failure is written to <step>.error, which the
    driver prints (the GUI's Python shell would show it only in its own window)."""
    try:
        _record(step, screenshot)
    except Exception:
        with open(os.path.join(os.environ["TRC_GUI_OUTPUT"], step + ".error"), "w") as f:
            f.write(traceback.format_exc())
        raise


def _record(step, screenshot):
    view, display = _state["view"], _state["display"]
    result = {
        "step": step,
        "mapper": display.GetProperty("SelectMapper").GetData(),
        # The last frame's, drawn by the GUI (an interactive or a still render), before any
        # screenshot renders another.
        "statistics": scene.mapper_statistics(display),
        "view_size": list(view.ViewSize),
    }
    if screenshot:
        size = list(view.ViewSize)
        SaveScreenshot(os.path.join(os.environ["TRC_GUI_OUTPUT"], step + ".png"), view,
                       ImageResolution=size, TransparentBackground=0)
        result.update(scene.describe(view, display, _state["array"], _state["value_range"],
                                     _state["lut"], _state["opacity"], size))
        result["screenshot_statistics"] = scene.mapper_statistics(display)
    with open(os.path.join(os.environ["TRC_GUI_OUTPUT"], step + ".json"), "w") as f:
        json.dump(result, f, indent=1)
