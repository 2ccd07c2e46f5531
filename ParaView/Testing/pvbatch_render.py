"""Renders a mesh in ParaView's Volume representation and writes what the reference needs.

Run by pvbatch (ParaView 5.11) from TestParaViewPlugin.py and from ParaView/benchmark.sh:
  pvbatch pvbatch_render.py --plugin TiledRayCast.so --mesh mesh.vtu --output prefix [options]
Writes prefix.png (the view, exactly --size pixels) and prefix.json: camera, background, colour
map and opacity function as ParaView set them up, the unit distance, frame times, the mapper's
statistics. --mesh mixed builds a mixed-cell mesh instead (ParaView's Wavelet, clipped: hexahedra,
wedges, pyramids, tetrahedra, with a vector array "vec" = (20 x, RTData, z) coloured by its Y
component) and also writes prefix_tets.vtu, the same mesh split into tetrahedra
as ParaView's representation splits it, for the reference.
"""
import argparse
import json
import sys
import time

from paraview.simple import (
    Calculator,
    Clip,
    ColorBy,
    GetColorTransferFunction,
    GetOpacityTransferFunction,
    GetActiveViewOrCreate,
    LoadPlugin,
    Render,
    SaveData,
    SaveScreenshot,
    Show,
    Tetrahedralize,
    Wavelet,
    XMLUnstructuredGridReader,
)
from paraview import servermanager

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--mesh", required=True, help="a .vtu file, or 'mixed'")
parser.add_argument("--array", default=None, help="point array to colour by (default: the first)")
parser.add_argument("--mapper", default="Tiled ray cast")
parser.add_argument("--size", type=int, default=256)
parser.add_argument("--output", required=True)
parser.add_argument("--unit-fraction", type=float, default=0.05,
                    help="scalar opacity unit distance as a fraction of the bounds' diagonal")
parser.add_argument("--smooth", action="store_true",
                    help="turn the colour map's discretization off (ParaView's default is on)")
parser.add_argument("--frames", type=int, default=0,
                    help="frames timed after the first, the camera turning 360/frames degrees each")
parser.add_argument("--azimuth", type=float, default=30.0)
parser.add_argument("--elevation", type=float, default=20.0)
args = parser.parse_args()

LoadPlugin(args.plugin, remote=False, ns=globals())

if args.mesh == "mixed":
    wavelet = Wavelet(WholeExtent=[-8, 8, -8, 8, -8, 8])
    source = Clip(Input=wavelet, ClipType="Plane")
    source.ClipType.Origin = [0.3, 0.2, 0.1]
    source.ClipType.Normal = [1.0, 0.7, 0.4]
    source.Crinkleclip = 0
    # A vector array coloured by one component: what the representation forwards to the
    # mapper as VectorMode/VectorComponent.
    source = Calculator(Input=source, ResultArrayName="vec",
                        Function="20*coordsX*iHat + RTData*jHat + coordsZ*kHat")
    source.UpdatePipeline()
    types = set()
    data = servermanager.Fetch(source)
    for i in range(data.GetNumberOfCells()):
        types.add(data.GetCellType(i))
    # Split as the representation does (vtkVolumeRepresentationPreprocessor: the same triangle
    # filter as Tetrahedralize), for the reference outside ParaView.
    SaveData(args.output + "_tets.vtu", proxy=Tetrahedralize(Input=source))
else:
    source = XMLUnstructuredGridReader(FileName=[args.mesh])
    types = None
source.UpdatePipeline()
info = source.GetDataInformation()
array = args.array or ("vec" if args.mesh == "mixed" else source.PointData.keys()[0])
component = 1 if args.mesh == "mixed" else -1  # the Y component of "vec", or the magnitude
lo, hi = source.PointData[array].GetRange(component)
b = info.GetBounds()
diagonal = ((b[1] - b[0]) ** 2 + (b[3] - b[2]) ** 2 + (b[5] - b[4]) ** 2) ** 0.5

view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [args.size, args.size]
view.OrientationAxesVisibility = 0
if hasattr(view, "UseColorPaletteForBackground"):
    view.UseColorPaletteForBackground = 0
view.Background = [0.1, 0.1, 0.15]
display = Show(source, view)
display.SetRepresentationType("Volume")
if component >= 0:
    ColorBy(display, ("POINTS", array, "XYZ"[component]))
else:
    ColorBy(display, ("POINTS", array))
lut = GetColorTransferFunction(array)
lut.RescaleTransferFunction(lo, hi)
if args.smooth:
    lut.Discretize = 0
opacity = GetOpacityTransferFunction(array)
opacity.RescaleTransferFunction(lo, hi)
display.SelectMapper = args.mapper
display.ScalarOpacityUnitDistance = args.unit_fraction * diagonal

view.ResetCamera()
camera = view.GetActiveCamera()
camera.Azimuth(args.azimuth)
camera.Elevation(args.elevation)
camera.OrthogonalizeViewUp()
view.ResetCamera()

start = time.perf_counter()
Render(view)
first = time.perf_counter() - start
camera_state = {
    "position": list(camera.GetPosition()),
    "focal_point": list(camera.GetFocalPoint()),
    "view_up": list(camera.GetViewUp()),
    "view_angle": camera.GetViewAngle(),
    "clipping_range": list(camera.GetClippingRange()),
}
SaveScreenshot(args.output + ".png", view, ImageResolution=[args.size, args.size],
               TransparentBackground=0)

times = []
for _ in range(args.frames):
    camera.Azimuth(360.0 / args.frames)
    start = time.perf_counter()
    Render(view)
    times.append(time.perf_counter() - start)

display.SMProxy.UpdatePropertyInformation()
statistics = None
if display.SMProxy.GetProperty("TiledRayCastStatistics"):
    statistics = display.SMProxy.GetProperty("TiledRayCastStatistics").GetElement(0)

# The colour map as ParaView evaluates it (the client-side object is the one rendered in a
# built-in session), sampled at the centre of each step, so the reference can check its own.
ctf = lut.GetClientSideObject()
steps = int(lut.NumberOfTableValues)
samples = []
for k in range(steps):
    s = lo + (hi - lo) * (k + 0.5) / steps
    rgb = [0.0, 0.0, 0.0]
    ctf.GetColor(s, rgb)
    samples.append([s] + rgb)

result = {
    "mesh": args.mesh,
    "mapper": args.mapper,
    "array": array,
    "range": [lo, hi],
    "cell_types": sorted(types) if types is not None else None,
    "size": args.size,
    "background": list(view.Background),
    "camera": camera_state,
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
    "first_frame_s": first,
    "frame_s": times,
    "statistics": statistics,
}
with open(args.output + ".json", "w") as f:
    json.dump(result, f, indent=1)
print("rendered %s with %s: first frame %.3f s%s" % (args.mesh, args.mapper, first,
      ", then %.3f s a frame (median of %d)" % (sorted(times)[len(times) // 2], len(times))
      if times else ""))
if statistics:
    print("statistics:", statistics)
sys.stdout.flush()
