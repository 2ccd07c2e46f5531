"""Renders a mesh in ParaView's Volume representation and writes what the reference needs.

Run by pvbatch (ParaView 5.11), alone or under mpirun, from TestParaViewPlugin.py,
TestParaViewMPI.py and ParaView/benchmark.sh:
  [mpirun -np N] pvbatch pvbatch_render.py --plugin TiledRayCast.so --mesh mesh.vtu|.pvtu
                                           --output prefix [options]
Writes prefix.png (the view, exactly --size pixels) and prefix.json: camera, background, colour
map and opacity function as ParaView set them up, the unit distance, frame times, the mapper's
statistics, the number of ranks and the cells each rank read. --mesh mixed builds a mixed-cell
mesh instead (ParaView's Wavelet, clipped: hexahedra, wedges, pyramids, tetrahedra, with a vector
array "vec" = (20 x, RTData, z) coloured by its Y component) and also writes prefix_tets.vtu, the
same mesh split into tetrahedra as ParaView's representation splits it, for the reference. A
.pvtu is read by ParaView's partitioned reader, each rank its own pieces.

Under MPI ParaView composites the ranks' images after its FXAA pass is switched off for them and
applies FXAA to the composited image: volume silhouettes, sharp against the transparent background
of the composite, are then blurred (up to 10/255 on comb6teeth, the same for every mapper), which a
single rank never does to a volume. --fxaa off (the default here) renders without it.
"""
import argparse
import json
import sys
import time

from paraview.simple import (
    Calculator,
    Clip,
    Connect,
    ProgrammableFilter,
    RedistributeDataSet,
    GetSettingsProxy,
    GetActiveViewOrCreate,
    Hide,
    LoadPlugin,
    Render,
    SaveData,
    SaveScreenshot,
    Tetrahedralize,
    Wavelet,
    XMLPartitionedUnstructuredGridReader,
    XMLUnstructuredGridReader,
)
from paraview import servermanager
from paraview.modules.vtkRemotingCore import vtkProcessModule

from paraview_scene import describe, first_varying_array, mapper_statistics, show_volume

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--mesh", required=True,
                    help="a .vtu or .pvtu file, 'mixed', or 'wavelet:N' (made on the ranks)")
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
parser.add_argument("--background", default="0.1,0.1,0.15", help="r,g,b")
parser.add_argument("--fxaa", choices=("on", "off"), default="off",
                    help="ParaView's FXAA (its default is on; see the module's description)")
parser.add_argument("--use-data-partitions", action="store_true",
                    help="render the pieces where the reader put them (Volume representation's "
                         "UseDataPartitions), no redistribution")
parser.add_argument("--split-boundary-cells", type=int, choices=(0, 1), default=1,
                    help="the representation's TiledRayCastSplitBoundaryCells")
parser.add_argument("--time-redistribution", action="store_true",
                    help="also time ParaView's RedistributeDataSet filter (cells split at the "
                         "partition planes, as the view redistributes them) on its own")
parser.add_argument("--synchronous-statistics", action="store_true",
                    help="the representation's TiledRayCastSynchronousStatistics: every frame "
                         "waits for its GPU timers and counts (frame_statistics then per frame)")
parser.add_argument("--empty-view", action="store_true",
                    help="time the --frames frames with the volume hidden: what ParaView's view, "
                         "its compositing and this script cost a frame, apart from any mapper")
parser.add_argument("--connect", default=None, metavar="HOST:PORT",
                    help="run as a client (pvpython) of a pvserver there, which renders (its "
                         "ranks, remote rendering forced); the server must have the plugin on "
                         "PV_PLUGIN_PATH")
args = parser.parse_args()

if args.connect:
    host, port = args.connect.rsplit(":", 1)
    # The server loaded the plugin at its start (PV_PLUGIN_PATH): it must, for its initializer
    # to tell ParaView that a rank without X renders (EGL). Loading it there again fails.
    Connect(host, int(port))
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
elif args.mesh.startswith("wavelet:"):
    # Generated piece by piece: ParaView's Wavelet gives each rank its own block of the extent
    # (-n..n)^3, tetrahedralized there; no rank ever holds the whole mesh. Each piece is a box:
    # with --use-data-partitions it is rendered where it was made, never redistributed.
    n = int(args.mesh.split(":", 1)[1])
    source = Tetrahedralize(Input=Wavelet(WholeExtent=[-n, n, -n, n, -n, n]))
    types = None
elif args.mesh.endswith(".pvtu"):
    source = XMLPartitionedUnstructuredGridReader(FileName=[args.mesh])
    types = None
else:
    source = XMLUnstructuredGridReader(FileName=[args.mesh])
    types = None
start = time.perf_counter()
source.UpdatePipeline()
read_s = time.perf_counter() - start
info = source.GetDataInformation()
ranks = (servermanager.ActiveConnection.GetNumberOfDataPartitions() if args.connect
         else vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions())
# The cells each rank read, before any redistribution (each rank's own pieces of a .pvtu),
# gathered on rank 0 by a programmable filter that runs on every rank.
RANK_CELLS = """
from vtkmodules.vtkCommonCore import vtkIdTypeArray
from vtkmodules.vtkParallelCore import vtkMultiProcessController
controller = vtkMultiProcessController.GetGlobalController()
mine = vtkIdTypeArray()
mine.InsertNextValue(self.GetInput().GetNumberOfCells())
everyone = vtkIdTypeArray()
controller.Gather(mine, everyone, 0)
everyone.SetName("RankCells")
self.GetOutput().GetFieldData().AddArray(everyone)
"""
COPY_CELLS = """
from vtkmodules.vtkCommonDataModel import vtkCellArray
grid = self.GetInput()
out = self.GetOutput()
out.ShallowCopy(grid)
cells = vtkCellArray()
cells.DeepCopy(grid.GetCells())
out.SetCells(grid.GetCellTypesArray(), cells)
"""
ranks_cells = None
if ranks > 1:
    counter = ProgrammableFilter(Input=source, OutputDataSetType="vtkPolyData", Script=RANK_CELLS)
    counts = servermanager.Fetch(counter, 0).GetFieldData().GetArray("RankCells")
    ranks_cells = [int(counts.GetValue(i)) for i in range(counts.GetNumberOfTuples())]
if args.mesh.startswith("wavelet:") and ranks == 1:
    # The whole generated mesh, for the reference outside ParaView.
    SaveData(args.output + "_tets.vtu", proxy=source)

array = args.array or ("vec" if args.mesh == "mixed" else first_varying_array(source))
component = 1 if args.mesh == "mixed" else -1  # the Y component of "vec", or the magnitude

view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [args.size, args.size]
view.OrientationAxesVisibility = 0
view.UseFXAA = 1 if args.fxaa == "on" else 0
if args.connect:
    # Rendered on the server's ranks whatever the data's size (below ParaView's threshold the
    # client would fetch the geometry and render it itself).
    GetSettingsProxy("RenderViewSettings").RemoteRenderThreshold = 0
if hasattr(view, "UseColorPaletteForBackground"):
    view.UseColorPaletteForBackground = 0
view.Background = [float(c) for c in args.background.split(",")]
display, lut, opacity, value_range = show_volume(
    source, view, array, component, args.mapper, args.unit_fraction, args.smooth)
display.UseDataPartitions = 1 if args.use_data_partitions else 0
display.TiledRayCastSplitBoundaryCells = args.split_boundary_cells
if args.synchronous_statistics:
    display.TiledRayCastSynchronousStatistics = 1

view.ResetCamera()
camera = view.GetActiveCamera()
camera.Azimuth(args.azimuth)
camera.Elevation(args.elevation)
camera.OrthogonalizeViewUp()
view.ResetCamera()

start = time.perf_counter()
Render(view)
first = time.perf_counter() - start
SaveScreenshot(args.output + ".png", view, ImageResolution=[args.size, args.size],
               TransparentBackground=0)
reference_scene = describe(view, display, array, value_range, lut, opacity, args.size)

if args.empty_view:
    Hide(source, view)


def statistics_of_last_frame():
    """Our mapper's summary of the frame just drawn (rank 0's), or None."""
    return None if args.empty_view else mapper_statistics(display)


times = []
frame_statistics = []
for _ in range(args.frames):
    camera.Azimuth(360.0 / args.frames)
    start = time.perf_counter()
    Render(view)
    times.append(time.perf_counter() - start)
    # Read after the clock stopped: what each timed frame did, for the slow ones.
    frame_statistics.append(statistics_of_last_frame())

redistribution_s = None
if args.time_redistribution and ranks > 1:
    # The cells copied first, as the plugin's representation copies them (ParaView 5.11's
    # redistribution crashes on three or more ranks on its XML readers' cell arrays), then
    # redistributed as the view redistributes them for the plugin: split at the planes.
    copied = ProgrammableFilter(Input=source, OutputDataSetType="vtkUnstructuredGrid",
                                Script=COPY_CELLS)
    copied.UpdatePipeline()
    redistributed = RedistributeDataSet(Input=copied)
    redistributed.BoundaryMode = "Split cells"
    start = time.perf_counter()
    redistributed.UpdatePipeline()
    redistribution_s = time.perf_counter() - start

statistics = statistics_of_last_frame()

result = {
    "mesh": args.mesh,
    "mapper": args.mapper,
    "cell_types": sorted(types) if types is not None else None,
    "ranks": ranks,
    "ranks_cells": ranks_cells,
    "cells": info.GetNumberOfCells(),
    "fxaa": args.fxaa,
    "use_data_partitions": args.use_data_partitions,
    "split_boundary_cells": args.split_boundary_cells,
    "read_s": read_s,
    "redistribution_s": redistribution_s,
    "first_frame_s": first,
    "frame_s": times,
    "statistics": statistics,
    "frame_statistics": frame_statistics,
}
# Described after the first frame, whose camera the screenshot has.
result.update(reference_scene)
with open(args.output + ".json", "w") as f:
    json.dump(result, f, indent=1)
print("rendered %s with %s on %d rank(s): first frame %.3f s%s" % (args.mesh, args.mapper, ranks, first,
      ", then %.3f s a frame (median of %d)" % (sorted(times)[len(times) // 2], len(times))
      if times else ""))
if statistics:
    print("statistics:", statistics)
sys.stdout.flush()
