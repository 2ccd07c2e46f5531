#!/usr/bin/python3
"""Render a tetrahedral mesh with TiledRayCast, the way a pvpython script would.

Reads a .vtu file, sets a colour and opacity transfer function over the chosen point array,
renders it with vtkTiledRayCastVolumeMapper to a PNG file, and prints what the mesh builder
found and what the mapper did.

    /usr/bin/python3 Examples/Python/render_mesh.py Testing/Data/Meshes/bluntfin_tets.vtu \\
        --output bluntfin.png --size 512

With no X display, the window is the headless EGL one (the 'tiledraycast' package registers it).
"""
import argparse
import os
import sys

from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
from vtkmodules.vtkRenderingCore import (
    vtkColorTransferFunction,
    vtkRenderer,
    vtkRenderWindow,
    vtkVolume,
    vtkVolumeProperty,
    vtkWindowToImageFilter,
)
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
}
LAYOUTS = {
    "compact": vtkTiledRayCastVolumeMapper.COMPACT_LAYOUT,
    "paper": vtkTiledRayCastVolumeMapper.PAPER_LAYOUT,
}


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("mesh", nargs="?", default=DEFAULT_MESH, help="a .vtu file of tetrahedra")
    parser.add_argument("--output", default="tiledraycast.png", help="PNG file to write")
    parser.add_argument("--size", type=int, default=512, help="image width and height")
    parser.add_argument("--array", default=None, help="point array to render (default: active)")
    parser.add_argument("--mode", choices=sorted(MODES), default="partial",
                        help="integration: partial pre-integration, 3D or 2D table")
    parser.add_argument("--layout", choices=sorted(LAYOUTS), default="compact")
    parser.add_argument("--pipeline", choices=["automatic", "compute", "fragment"],
                        default="automatic",
                        help="compute shaders (OpenGL 4.3), the paper's fragment pipeline, or "
                             "compute where the context has it")
    parser.add_argument("--tets-per-pass", type=int, default=None,
                        help="fragment pipeline: tetrahedra per ray-casting pass (0: unlimited)")
    parser.add_argument("--tile-size", type=int, default=None,
                        help="fragment pipeline: tile side in pixels")
    parser.add_argument("--azimuth", type=float, default=30.0)
    parser.add_argument("--elevation", type=float, default=20.0)
    parser.add_argument("--frames", type=int, default=1, help="render this many frames")
    args = parser.parse_args(argv)

    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(args.mesh)
    reader.Update()
    grid = reader.GetOutput()
    if grid.GetNumberOfCells() == 0:
        print(f"{args.mesh}: no cells", file=sys.stderr)
        return 1
    point_data = grid.GetPointData()
    scalars = point_data.GetArray(args.array) if args.array else point_data.GetScalars()
    if scalars is None:
        print(f"{args.mesh}: no point array {args.array or '(active)'}", file=sys.stderr)
        return 1
    low, high = scalars.GetRange()
    mid = 0.5 * (low + high)

    # Like a ParaView colour map: cool to warm, opacity rising with the value.
    color = vtkColorTransferFunction()
    color.AddRGBPoint(low, 0.23, 0.30, 0.75)
    color.AddRGBPoint(mid, 0.87, 0.87, 0.87)
    color.AddRGBPoint(high, 0.71, 0.02, 0.15)
    opacity = vtkPiecewiseFunction()
    opacity.AddPoint(low, 0.0)
    opacity.AddPoint(mid, 0.2)
    opacity.AddPoint(high, 0.9)
    prop = vtkVolumeProperty()
    prop.SetColor(color)
    prop.SetScalarOpacity(opacity)
    x0, x1, y0, y1, z0, z1 = grid.GetBounds()
    diagonal = ((x1 - x0) ** 2 + (y1 - y0) ** 2 + (z1 - z0) ** 2) ** 0.5
    prop.SetScalarOpacityUnitDistance(0.05 * diagonal)

    mapper = vtkTiledRayCastVolumeMapper()
    mapper.SetInputData(grid)
    if args.array:
        mapper.SetScalarModeToUsePointFieldData()
        mapper.SelectScalarArray(args.array)
    mapper.SetIntegrationMode(MODES[args.mode])
    mapper.SetMeshLayout(LAYOUTS[args.layout])
    {"automatic": mapper.SetPipelineToAutomatic, "compute": mapper.SetPipelineToCompute,
     "fragment": mapper.SetPipelineToFragment}[args.pipeline]()
    if args.tets_per_pass is not None:
        mapper.SetTetsPerPass(args.tets_per_pass)
    if args.tile_size is not None:
        mapper.SetTileSize(args.tile_size)
    mapper.SynchronousStatisticsOn()

    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    renderer = vtkRenderer()
    renderer.AddVolume(volume)
    renderer.SetBackground(1.0, 1.0, 1.0)
    renderer.ResetCamera()
    camera = renderer.GetActiveCamera()
    camera.Azimuth(args.azimuth)
    camera.Elevation(args.elevation)
    renderer.ResetCameraClippingRange()
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(args.size, args.size)
    window.AddRenderer(renderer)
    for _ in range(max(1, args.frames)):
        window.Render()

    stats = mapper.GetStatistics()
    if not stats.GetRendered():
        print("nothing was rendered: " + mapper.GetValidationReport().GetSummary(),
              file=sys.stderr)
        return 1
    capture = vtkWindowToImageFilter()
    capture.SetInput(window)
    capture.ReadFrontBufferOff()
    writer = vtkPNGWriter()
    writer.SetFileName(args.output)
    writer.SetInputConnection(capture.GetOutputPort())
    writer.Write()

    print(f"tiledraycast {tiledraycast.__version__}, window {window.GetClassName()}")
    # The renderer line of the capabilities report (the EGL window puts EGL lines first).
    renderer_line = next((line.split(":", 1)[1].strip()
                          for line in window.ReportCapabilities().splitlines()
                          if line.startswith("OpenGL renderer string")), "(unknown)")
    print(f"OpenGL: {renderer_line}")
    print(f"mesh {os.path.basename(args.mesh)}: {mapper.GetValidationReport().GetSummary()}")
    # Tets per pass and tile size are the fragment pipeline's settings only.
    fragment = (f", {mapper.GetTetsPerPass()} tets per pass, tiles of {mapper.GetTileSize()} px"
                if stats.GetPipeline() == "Fragment" else "")
    print(f"mapper: {mapper.GetPipelineAsString()} pipeline, "
          f"{mapper.GetIntegrationModeAsString()} integration, "
          f"{mapper.GetMeshLayoutAsString()} layout{fragment}")
    print(f"render: {stats.GetSummary()}")
    print(f"wrote {args.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
