"""A mesh shown as ParaView's Volume representation, and what the exact reference needs of it.

Imported inside ParaView's own Python (pvbatch_render.py under pvbatch, gui_session.py in the
GUI), never by Debian's python3: it uses paraview.simple. The test drivers outside ParaView read
what describe() returns (TestParaViewPlugin.py's make_property() and compare()).
"""
from paraview.simple import (
    ColorBy,
    GetColorTransferFunction,
    GetOpacityTransferFunction,
    Show,
)


def first_varying_array(proxy):
    """The first point array whose values vary: a constant one (post_tets6's Density) would
    make the default opacity ramp zero everywhere, an empty image."""
    for name in proxy.PointData.keys():
        lo, hi = proxy.PointData[name].GetRange(-1)
        if hi > lo:
            return name
    return proxy.PointData.keys()[0]


def diagonal(source):
    """The length of the diagonal of the source's bounds."""
    b = source.GetDataInformation().GetBounds()
    return ((b[1] - b[0]) ** 2 + (b[3] - b[2]) ** 2 + (b[5] - b[4]) ** 2) ** 0.5


def show_volume(source, view, array, component, mapper, unit_fraction, smooth=False):
    """Shows `source` in `view` as Volume, coloured by `array` (its `component`, or the
    magnitude when negative) through ParaView's default colour map and opacity ramp rescaled to
    the array's range, with `mapper` and a unit distance of `unit_fraction` of the diagonal.
    Returns the display, the colour map, the opacity function and the range."""
    lo, hi = source.PointData[array].GetRange(component)
    display = Show(source, view)
    display.SetRepresentationType("Volume")
    if component >= 0:
        ColorBy(display, ("POINTS", array, "XYZ"[component]))
    else:
        ColorBy(display, ("POINTS", array))
    lut = GetColorTransferFunction(array)
    lut.RescaleTransferFunction(lo, hi)
    if smooth:
        lut.Discretize = 0
    opacity = GetOpacityTransferFunction(array)
    opacity.RescaleTransferFunction(lo, hi)
    display.SelectMapper = mapper
    display.ScalarOpacityUnitDistance = unit_fraction * diagonal(source)
    return display, lut, opacity, (lo, hi)


def camera_state(camera):
    return {
        "position": list(camera.GetPosition()),
        "focal_point": list(camera.GetFocalPoint()),
        "view_up": list(camera.GetViewUp()),
        "view_angle": camera.GetViewAngle(),
        "clipping_range": list(camera.GetClippingRange()),
    }


def describe(view, display, array, value_range, lut, opacity, size):
    """What the reference renderer needs to render the view's volume exactly as ParaView set it
    up: camera, background, image size, the colour map (as ParaView evaluates it, sampled at the
    centre of each step, so that the reference can check its own), the opacity function and the
    unit distance."""
    lo, hi = value_range
    # The client-side object is the one rendered in a built-in session.
    ctf = lut.GetClientSideObject()
    steps = int(lut.NumberOfTableValues)
    samples = []
    for k in range(steps):
        s = lo + (hi - lo) * (k + 0.5) / steps
        rgb = [0.0, 0.0, 0.0]
        ctf.GetColor(s, rgb)
        samples.append([s] + rgb)
    return {
        "array": array,
        "range": [lo, hi],
        "size": size,
        "background": list(view.Background),
        "camera": camera_state(view.GetActiveCamera()),
        "unit_distance": display.ScalarOpacityUnitDistance,
        "colors": {
            "rgb_points": list(lut.RGBPoints),
            "color_space": lut.GetProperty("ColorSpace").GetData(),
            "discretize": int(lut.Discretize),
            "number_of_values": steps,
            "samples": samples,
            "class": ctf.GetClassName(),
        },
        "vector_mode": lut.GetProperty("VectorMode").GetData(),
        "vector_component": int(lut.VectorComponent),
        "opacity_points": list(opacity.Points),
    }


def mapper_statistics(display):
    """The tiled ray-cast mapper's summary of the frame it drew last, or None."""
    proxy = display.SMProxy
    if not proxy.GetProperty("TiledRayCastStatistics"):
        return None
    proxy.UpdatePropertyInformation()
    return proxy.GetProperty("TiledRayCastStatistics").GetElement(0)
