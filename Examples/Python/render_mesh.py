#!/usr/bin/python3
"""Render a tetrahedral mesh with TiledRayCast, the way a pvpython script would.

Reads a mesh (.vtu, .pvtu, legacy .vtk, Exodus .ex2/.e/.exo), picks a point or cell array,
derives a colour and opacity transfer function from the array's volume-weighted histogram (the
value that fills most of the volume, such as a free stream, is transparent; values away from it
are coloured cool below and warm above it, and more opaque the farther they are), renders the
volume with vtkTiledRayCastVolumeMapper over a dark background with a scalar bar and a caption
(mesh size, frame time), writes a PNG file, and prints what the mesh builder found and what the
mapper did.

    /usr/bin/python3 Examples/Python/render_mesh.py Testing/Data/Meshes/bluntfin_tets.vtu \\
        --output bluntfin.png --size 512

With no X display, the window is the headless EGL one (the 'tiledraycast' package registers it).
"""
import argparse
import math
import os
import re
import sys
import time

from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkCommonDataModel import (
    vtkCompositeDataSet,
    vtkDataSet,
    vtkPiecewiseFunction,
    vtkUnstructuredGrid,
)
from vtkmodules.vtkFiltersCore import vtkAppendFilter, vtkPointDataToCellData
from vtkmodules.vtkFiltersVerdict import vtkCellSizeFilter
from vtkmodules.vtkIOExodus import vtkExodusIIReader
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOLegacy import vtkGenericDataObjectReader
from vtkmodules.vtkIOXML import vtkXMLPUnstructuredGridReader, vtkXMLUnstructuredGridReader
from vtkmodules.vtkRenderingAnnotation import vtkScalarBarActor
from vtkmodules.vtkRenderingCore import (
    vtkColorTransferFunction,
    vtkRenderer,
    vtkRenderWindow,
    vtkTextActor,
    vtkVolume,
    vtkVolumeProperty,
    vtkWindowToImageFilter,
)
import vtkmodules.vtkRenderingFreeType  # noqa: F401  (text of the caption and the scalar bar)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (OpenGL implementations)
import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401

import tiledraycast
from tiledraycast import vtkTiledRayCastVolumeMapper

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_MESH = os.path.join(HERE, "..", "..", "Testing", "Data", "Meshes", "bluntfin_tets.vtu")

MODES = {
    "partial": vtkTiledRayCastVolumeMapper.PARTIAL_PRE_INTEGRATION,
    "3d": vtkTiledRayCastVolumeMapper.PRE_INTEGRATION_3D,
    "2d": vtkTiledRayCastVolumeMapper.PRE_INTEGRATION_2D,
    "automatic": vtkTiledRayCastVolumeMapper.AUTOMATIC_INTEGRATION,
}
LAYOUTS = {
    "compact": vtkTiledRayCastVolumeMapper.COMPACT_LAYOUT,
    "paper": vtkTiledRayCastVolumeMapper.PAPER_LAYOUT,
}
EXTENSIONS = {
    ".vtu": "VTK XML unstructured grid",
    ".pvtu": "VTK XML parallel unstructured grid",
    ".vtk": "VTK legacy data set",
    ".ex2": "Exodus II",
    ".exo": "Exodus II",
    ".e": "Exodus II",
}
# Image sizes: the scalar bar and the caption need some room; 16384 is the largest render
# target llvmpipe (and most GPUs) allocate.
MIN_SIZE, MAX_SIZE = 64, 16384
# Below this size the scalar bar and the caption would cover the volume: they are left out.
OVERLAY_SIZE = 256
BACKGROUND = (0.08, 0.08, 0.11)
HISTOGRAM_BINS = 256
MAX_HISTOGRAM_CELLS = 250000


class MeshError(Exception):
    """A mesh that cannot be read or rendered: the message says why."""


class ErrorCollector:
    """Catches the VTK errors an object reports, so that they can be given in one message."""

    CallDataType = "string0"  # VTK passes the message to the observer as a str

    def __init__(self, vtk_object):
        self.messages = []
        vtk_object.AddObserver(vtkCommand.ErrorEvent, self)
        executive = vtk_object.GetExecutive() if hasattr(vtk_object, "GetExecutive") else None
        if executive is not None:
            executive.AddObserver(vtkCommand.ErrorEvent, self)

    def __call__(self, caller, event, message=None):
        self.messages.append(str(message).strip() if message else "an error")

    def first(self):
        """The first message's text, without VTK's location and object address."""
        if not self.messages:
            return ""
        return re.sub(r"^\w+ \(0x[0-9a-fA-F]+\): ", "", self.messages[0].splitlines()[-1])


class ProgressPrinter:
    """Prints a filter's progress to stderr as percentages, throttled: nothing for work that
    ends within `delay` seconds, then at most one line every `interval` seconds, and 100 % at the
    end of whatever was announced."""

    def __init__(self, label, delay=0.5, interval=0.5, stream=sys.stderr, clock=time.monotonic):
        self.label = label
        self.delay = delay
        self.interval = interval
        self.stream = stream
        self.clock = clock
        self.start = None
        self.last = None

    def __call__(self, caller, event=None):
        self.update(caller.GetProgress())

    def update(self, fraction):
        now = self.clock()
        if fraction <= 0.0 or self.start is None:
            self.start, self.last = now, None
        if fraction >= 1.0:
            if self.last is not None:
                self._print(1.0)
            self.start, self.last = None, None
            return
        if now - self.start < self.delay:
            return
        if self.last is None or now - self.last >= self.interval:
            self.last = now
            self._print(fraction)

    def _print(self, fraction):
        self.stream.write(f"{self.label}: {100.0 * fraction:3.0f} %\n")
        self.stream.flush()


def integer_in(low, high, what):
    """An argparse type: an integer in [low, high], with a message that says so."""

    def parse(text):
        try:
            value = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"{what} must be an integer (got '{text}')")
        if not low <= value <= high:
            raise argparse.ArgumentTypeError(
                f"{what} must be between {low} and {high} (got {value})")
        return value

    return parse


def to_unstructured_grid(data, path):
    """A vtkUnstructuredGrid from any data set or composite data set (blocks merged, shared
    points merged so that block interfaces are not boundaries)."""
    if isinstance(data, vtkUnstructuredGrid):
        return data
    append = vtkAppendFilter()
    if isinstance(data, vtkCompositeDataSet):
        iterator = data.NewIterator()
        iterator.InitTraversal()
        while not iterator.IsDoneWithTraversal():
            block = iterator.GetCurrentDataObject()
            if isinstance(block, vtkDataSet) and block.GetNumberOfCells() > 0:
                append.AddInputData(block)
            iterator.GoToNextItem()
        if append.GetNumberOfInputConnections(0) == 0:
            raise MeshError(f"{path}: no block holds any cells")
        append.MergePointsOn()
    elif isinstance(data, vtkDataSet):
        append.AddInputData(data)
    else:
        kind = data.GetClassName() if data else "nothing"
        raise MeshError(f"{path}: holds {kind}, not a data set with cells")
    append.Update()
    return append.GetOutput()


def read_mesh(path, time_step=None):
    """Reads `path` by its extension; returns (grid, a line saying what was read)."""
    extension = os.path.splitext(path)[1].lower()
    if extension not in EXTENSIONS:
        known = ", ".join(sorted(EXTENSIONS))
        raise MeshError(f"{path}: unknown extension '{extension}' (this reads {known})")
    if not os.path.isfile(path):
        raise MeshError(f"{path}: no such file")
    note = EXTENSIONS[extension]
    if extension == ".vtu":
        reader = vtkXMLUnstructuredGridReader()
    elif extension == ".pvtu":
        reader = vtkXMLPUnstructuredGridReader()
    elif extension == ".vtk":
        reader = vtkGenericDataObjectReader()
    else:
        reader = vtkExodusIIReader()
    errors = ErrorCollector(reader)
    reader.SetFileName(path)
    if isinstance(reader, vtkExodusIIReader):
        note = setup_exodus(reader, path, time_step)
    elif time_step is not None:
        raise MeshError(f"--time-step is for Exodus files; {path} is a {note} file")
    reader.Update()
    if errors.messages:
        raise MeshError(f"{path}: cannot be read as a {EXTENSIONS[extension]} file "
                        f"({errors.first()})")
    grid = to_unstructured_grid(reader.GetOutputDataObject(0), path)
    if grid.GetNumberOfCells() == 0:
        raise MeshError(f"{path}: no cells")
    return grid, note


def setup_exodus(reader, path, time_step):
    """Every element block and every nodal and element variable, at the asked time step."""
    reader.UpdateInformation()
    reader.SetAllArrayStatus(vtkExodusIIReader.ELEM_BLOCK, 1)
    reader.SetAllArrayStatus(vtkExodusIIReader.NODAL, 1)
    blocks = reader.GetNumberOfObjects(vtkExodusIIReader.ELEM_BLOCK)
    steps = reader.GetNumberOfTimeSteps()
    if time_step is not None and not 0 <= time_step < max(steps, 1):
        raise MeshError(f"{path}: --time-step {time_step} is out of range "
                        f"(the file has {steps} time steps, 0 to {max(steps - 1, 0)})")
    step = time_step or 0
    reader.SetTimeStep(step)
    return f"Exodus II, {blocks} element blocks, time step {step} of {steps} (0-based)"


def find_array(grid, name, association):
    """The array to render: (association, array). `association` is 'point', 'cell' or None
    (point data first). Without a name: the active scalars, else the first numeric array."""
    places = [("point", grid.GetPointData()), ("cell", grid.GetCellData())]
    if association:
        places = [p for p in places if p[0] == association]
    if name:
        found = [(where, data.GetArray(name)) for where, data in places if data.GetArray(name)]
        if not found:
            available = describe_arrays(grid) or "none"
            raise MeshError(f"no {association + ' ' if association else ''}array '{name}' "
                            f"(arrays: {available})")
        return found[0]
    for where, data in places:
        if data.GetScalars() is not None:
            return where, data.GetScalars()
    for where, data in places:
        for i in range(data.GetNumberOfArrays()):
            array = data.GetArray(i)
            if array is not None and array.GetName():
                return where, array
    raise MeshError("the mesh has no numeric point or cell array to render")


def describe_arrays(grid):
    names = []
    for where, data in (("point", grid.GetPointData()), ("cell", grid.GetCellData())):
        for i in range(data.GetNumberOfArrays()):
            if data.GetArray(i) is not None and data.GetArrayName(i):
                names.append(f"{data.GetArrayName(i)} ({where})")
    return ", ".join(names)


def volume_histogram(grid, association, array):
    """A histogram of the array's value weighted by cell volume (point values averaged over each
    cell), from at most MAX_HISTOGRAM_CELLS cells spread over the mesh: what fills the volume,
    not where the points crowd (boundary layers). Returns (low, high, weights per bin)."""
    component = -1 if array.GetNumberOfComponents() > 1 else 0
    low, high = array.GetRange(component)
    if not (math.isfinite(low) and math.isfinite(high)) or high <= low:
        return low, high, []
    part = vtkUnstructuredGrid()
    part.CopyStructure(grid)
    if association == "point":
        part.GetPointData().SetScalars(array)  # as scalars: the array may have no name
        to_cells = vtkPointDataToCellData()
        to_cells.SetInputData(part)
        source = to_cells.GetOutputPort()
    else:
        part.GetCellData().SetScalars(array)
        source = None
    sizes = vtkCellSizeFilter()
    if source is not None:
        sizes.SetInputConnection(source)
    else:
        sizes.SetInputData(part)
    sizes.ComputeVertexCountOff()
    sizes.ComputeLengthOff()
    sizes.ComputeAreaOff()
    sizes.Update()
    cells = sizes.GetOutput().GetCellData()
    values, volumes = cells.GetScalars(), cells.GetArray("Volume")
    bins = [0.0] * HISTOGRAM_BINS
    count = values.GetNumberOfTuples()
    scale = HISTOGRAM_BINS / (high - low)
    for i in range(0, count, max(1, count // MAX_HISTOGRAM_CELLS)):
        tup = values.GetTuple(i)
        value = tup[0] if component == 0 else math.sqrt(sum(c * c for c in tup))
        if math.isfinite(value):
            bins[min(HISTOGRAM_BINS - 1, max(0, int((value - low) * scale)))] += abs(
                volumes.GetValue(i))
    return low, high, bins


def quantile(low, high, bins, q):
    """The value below which a fraction q of the histogram's weight lies (linear in a bin)."""
    total = sum(bins)
    target, acc = q * total, 0.0
    width = (high - low) / len(bins)
    for i, weight in enumerate(bins):
        if acc + weight >= target and weight > 0:
            return low + width * (i + (target - acc) / weight)
        acc += weight
    return high


def make_transfer_functions(grid, association, array):
    """Colour and opacity from the volume-weighted histogram: the most common value (the
    background of the data, such as a free stream) is transparent and grey; below it a cool
    ramp, above it a warm one, both more opaque the farther from it (the last 0.5 % of the volume
    at either end is clamped). Returns (colour, opacity, most common value)."""
    low, high, bins = volume_histogram(grid, association, array)
    if not bins or sum(bins) <= 0:
        centre = low if math.isfinite(low) else 0.0
        low, high = centre - 0.5, centre + 0.5
        bins = [1.0]
    width = (high - low) / len(bins)
    mode = low + width * (max(range(len(bins)), key=bins.__getitem__) + 0.5)
    lo = min(quantile(low, high, bins, 0.005), mode)
    hi = max(quantile(low, high, bins, 0.995), mode)
    # A band around the most common value stays fully transparent: 2 % of the clamped range.
    band = 0.02 * (hi - lo)
    color = vtkColorTransferFunction()
    color.SetColorSpaceToDiverging()
    opacity = vtkPiecewiseFunction()
    # Cool to warm (Moreland's diverging map), white-ish at the most common value, over the
    # whole range of the array (so the scalar bar shows it), clamped beyond the quantiles.
    for value, rgb in ((low, (0.23, 0.30, 0.75)), (lo, (0.23, 0.30, 0.75)),
                       (mode, (0.87, 0.87, 0.87)), (hi, (0.71, 0.02, 0.15)),
                       (high, (0.71, 0.02, 0.15))):
        color.AddRGBPoint(value, *rgb)
    # Opacity grows as the square of the distance from the mode (piecewise linear in 4 steps).
    for side_end, peak in ((lo, 0.35), (hi, 1.0)):
        if abs(side_end - mode) <= band:
            continue
        start = mode + math.copysign(band, side_end - mode)
        for t in (0.0, 0.25, 0.5, 0.75, 1.0):
            opacity.AddPoint(start + t * (side_end - start), peak * t * t)
    opacity.AddPoint(mode, 0.0)
    return color, opacity, mode


def add_overlays(renderer, color, title, size):
    """The scalar bar (the array's name and range) and the caption (filled in after a frame)."""
    bar = vtkScalarBarActor()
    bar.SetLookupTable(color)
    bar.SetTitle(title)
    bar.SetNumberOfLabels(5)
    bar.SetMaximumNumberOfColors(256)
    bar.SetLabelFormat("%-#6.3g")
    bar.SetOrientationToVertical()
    bar.SetPosition(0.84, 0.18)
    bar.SetWidth(0.15)
    bar.SetBarRatio(0.3)
    bar.SetHeight(0.65)
    bar.UnconstrainedFontSizeOn()
    for text in (bar.GetTitleTextProperty(), bar.GetLabelTextProperty()):
        text.SetColor(0.92, 0.92, 0.92)
        text.SetFontSize(max(10, size // 40))
        text.ShadowOff()
        text.ItalicOff()
    bar.GetTitleTextProperty().BoldOn()
    renderer.AddActor2D(bar)
    caption = vtkTextActor()
    caption.GetTextProperty().SetColor(0.92, 0.92, 0.92)
    caption.GetTextProperty().SetFontSize(max(10, size // 40))
    caption.SetPosition(max(4, size // 60), max(4, size // 60))
    renderer.AddActor2D(caption)
    return caption


def parse_arguments(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("mesh", nargs="?", default=DEFAULT_MESH,
                        help="a mesh file: " + ", ".join(sorted(EXTENSIONS)))
    parser.add_argument("--output", default="tiledraycast.png", help="PNG file to write")
    parser.add_argument("--size", type=integer_in(MIN_SIZE, MAX_SIZE, "--size"), default=512,
                        help=f"image width and height in pixels ({MIN_SIZE} to {MAX_SIZE}; "
                             f"the scalar bar and the caption from {OVERLAY_SIZE} up)")
    parser.add_argument("--array", default=None,
                        help="point or cell array to render (default: the active scalars, "
                             "else the first array; point data first)")
    parser.add_argument("--association", choices=["point", "cell"], default=None,
                        help="look for --array only in the point or only in the cell data")
    parser.add_argument("--time-step", type=integer_in(0, 2 ** 31 - 1, "--time-step"),
                        default=None, help="Exodus files: the time step to render (0-based)")
    parser.add_argument("--mode", choices=sorted(MODES), default="automatic",
                        help="integration: the cheapest within 1/255 of exact (the mapper's "
                             "default), partial pre-integration (exact), 3D or 2D table")
    parser.add_argument("--layout", choices=sorted(LAYOUTS), default="compact")
    parser.add_argument("--pipeline", choices=["automatic", "compute", "fragment"],
                        default="automatic",
                        help="compute shaders (OpenGL 4.3), the paper's fragment pipeline, or "
                             "compute where the context has it")
    parser.add_argument("--tets-per-pass", type=integer_in(0, 2 ** 31 - 1, "--tets-per-pass"),
                        default=None,
                        help="fragment pipeline: tetrahedra per ray-casting pass (0: unlimited)")
    parser.add_argument("--tile-size", type=integer_in(8, MAX_SIZE, "--tile-size"),
                        default=None, help="fragment pipeline: tile side in pixels")
    parser.add_argument("--azimuth", type=float, default=30.0)
    parser.add_argument("--elevation", type=float, default=20.0)
    parser.add_argument("--frames", type=integer_in(1, 100000, "--frames"), default=1,
                        help="render this many frames (the caption gives the last one's time)")
    return parser.parse_args(argv)


def make_mapper(grid, association, array, args):
    mapper = vtkTiledRayCastVolumeMapper()
    mapper.SetInputData(grid)
    if array.GetName():
        if association == "point":
            mapper.SetScalarModeToUsePointFieldData()
        else:
            mapper.SetScalarModeToUseCellFieldData()
        mapper.SelectScalarArray(array.GetName())
    elif association == "point":
        mapper.SetScalarModeToUsePointData()
    else:
        mapper.SetScalarModeToUseCellData()
    if array.GetNumberOfComponents() > 1:
        mapper.SetVectorModeToMagnitude()
    mapper.SetIntegrationMode(MODES[args.mode])
    mapper.SetMeshLayout(LAYOUTS[args.layout])
    {"automatic": mapper.SetPipelineToAutomatic, "compute": mapper.SetPipelineToCompute,
     "fragment": mapper.SetPipelineToFragment}[args.pipeline]()
    if args.tets_per_pass is not None:
        mapper.SetTetsPerPass(args.tets_per_pass)
    if args.tile_size is not None:
        mapper.SetTileSize(args.tile_size)
    mapper.SynchronousStatisticsOn()
    mapper.AddObserver(vtkCommand.ProgressEvent, ProgressPrinter("building the mesh"))
    return mapper


def render(grid, association, array, args):
    """Renders the frames, then one more with the caption that gives their times; returns
    (window, mapper, seconds of each timed frame)."""
    color, opacity, _ = make_transfer_functions(grid, association, array)
    prop = vtkVolumeProperty()
    prop.SetColor(color)
    prop.SetScalarOpacity(opacity)
    prop.SetInterpolationTypeToLinear()
    # An attenuation of 1 per 1/30 of the mesh's diagonal where the opacity function is 1.
    prop.SetScalarOpacityUnitDistance(grid.GetLength() / 30.0)
    mapper = make_mapper(grid, association, array, args)
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    renderer = vtkRenderer()
    renderer.AddVolume(volume)
    renderer.SetBackground(*BACKGROUND)
    renderer.ResetCamera()
    camera = renderer.GetActiveCamera()
    camera.Azimuth(args.azimuth)
    camera.Elevation(args.elevation)
    camera.OrthogonalizeViewUp()
    renderer.ResetCameraClippingRange()
    title = array.GetName() or "scalars"
    if array.GetNumberOfComponents() > 1:
        title += " (magnitude)"
    caption = None
    if args.size >= OVERLAY_SIZE:
        caption = add_overlays(renderer, color, title, args.size)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(args.size, args.size)
    window.AddRenderer(renderer)
    seconds = []
    for _ in range(args.frames):
        start = time.perf_counter()
        window.Render()
        seconds.append(time.perf_counter() - start)
    stats = mapper.GetStatistics()
    if caption is None:
        return window, mapper, seconds
    caption.SetInput(
        f"{os.path.basename(args.mesh)}\n"
        f"{mapper.GetValidationReport().GetNumberOfTetrahedra():,} tetrahedra, "
        f"{grid.GetNumberOfPoints():,} points\n"
        f"{args.size}x{args.size} px, frame {1000.0 * seconds[-1]:.0f} ms "
        f"(GPU {stats.GetTotalGPUTime():.0f} ms)")
    window.Render()
    return window, mapper, seconds


def report(window, mapper, args, note, association, array, seconds):
    stats = mapper.GetStatistics()
    print(f"tiledraycast {tiledraycast.__version__}, window {window.GetClassName()}")
    # The renderer line of the capabilities report (the EGL window puts EGL lines first).
    renderer_line = next((line.split(":", 1)[1].strip()
                          for line in window.ReportCapabilities().splitlines()
                          if line.startswith("OpenGL renderer string")), "(unknown)")
    print(f"OpenGL: {renderer_line}")
    print(f"mesh {os.path.basename(args.mesh)} ({note}): "
          f"{mapper.GetValidationReport().GetSummary()}")
    low, high = array.GetRange(-1 if array.GetNumberOfComponents() > 1 else 0)
    components = (f", {array.GetNumberOfComponents()} components: magnitude"
                  if array.GetNumberOfComponents() > 1 else "")
    print(f"array: {array.GetName() or '(unnamed)'} ({association} data{components}), "
          f"range {low:g} to {high:g}")
    # Tets per pass and tile size are the fragment pipeline's settings only.
    fragment = (f", {mapper.GetTetsPerPass()} tets per pass, tiles of {mapper.GetTileSize()} px"
                if stats.GetPipeline() == "Fragment" else "")
    print(f"mapper: {mapper.GetPipelineAsString()} pipeline, "
          f"{mapper.GetIntegrationModeAsString()} integration, "
          f"{mapper.GetMeshLayoutAsString()} layout{fragment}")
    print(f"render: {stats.GetSummary()}")
    later = (f", frame {len(seconds)}: {1000.0 * seconds[-1]:.1f} ms" if len(seconds) > 1 else "")
    print(f"frame 1 (builds the mesh): {1000.0 * seconds[0]:.1f} ms{later}")
    print(f"wrote {args.output}")


def main(argv):
    args = parse_arguments(argv)
    try:
        grid, note = read_mesh(args.mesh, args.time_step)
        association, array = find_array(grid, args.array, args.association)
    except MeshError as error:
        print(f"error: {error}", file=sys.stderr)
        return 1
    window, mapper, seconds = render(grid, association, array, args)
    stats = mapper.GetStatistics()
    if not stats.GetRendered():
        print("error: nothing was rendered: " + mapper.GetValidationReport().GetSummary(),
              file=sys.stderr)
        return 1
    capture = vtkWindowToImageFilter()
    capture.SetInput(window)
    capture.ReadFrontBufferOff()
    writer = vtkPNGWriter()
    errors = ErrorCollector(writer)
    writer.SetFileName(args.output)
    writer.SetInputConnection(capture.GetOutputPort())
    writer.Write()
    if errors.messages or not os.path.isfile(args.output):
        print(f"error: could not write {args.output} ({errors.first()})", file=sys.stderr)
        return 1
    report(window, mapper, args, note, association, array, seconds)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
