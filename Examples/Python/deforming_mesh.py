#!/usr/bin/env python3
"""Play a deforming tetrahedral mesh headless and write one PNG per frame.

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 \
        Examples/Python/deforming_mesh.py [--mesh FILE.vtu] [--size 512] [--frames 24] \
        [--mode wave|invert] [--point-update automatic|cpu|gpu] [--output-dir frames]

Every point of the mesh moves every frame: "wave" sends a travelling wave along x through z,
"invert" flattens the mesh along z, turns it inside out and brings it back (every tetrahedron
inverts and recovers; the mapper reorients them, as normal service). After each move the grid is
marked modified and the window rendered: vtkTiledRayCastVolumeMapper updates only the points of
its GPU layout when the topology is unchanged, on the GPU (the input's coordinates uploaded as
they are) or on the CPU (PointUpdate; automatic: the GPU where the renderer is one). Prints each
frame's time split as the mapper's statistics report it, and what it rebuilt where. No X server is needed (`import tiledraycast` makes vtkRenderWindow() the
EGL window).
"""
import argparse
import math
import os
import sys
import time

from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction, vtkUnstructuredGrid
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
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

import tiledraycast
from tiledraycast import vtkTiledRayCastStatistics, vtkTiledRayCastVolumeMapper

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_MESH = os.path.join(HERE, "..", "..", "Testing", "Data", "Meshes", "bluntfin_tets.vtu")


def deform(rest, points, centre, size, mode, phase):
    """Moves every point of `points` from its rest position `rest` (a list of tuples)."""
    for i, (x, y, z) in enumerate(rest):
        if mode == "wave":
            z += 0.01 * size * math.sin(6.0 * (x - centre[0]) / size + phase)
        else:
            z = centre[2] + (z - centre[2]) * math.cos(phase)
        points.SetPoint(i, x, y, z)
    points.Modified()


def rebuilt(flags):
    """What the mapper's statistics say it rebuilt of the mesh (MeshRebuild flags), in words."""
    if flags & vtkTiledRayCastStatistics.MeshRebuildTopology:
        return "rebuilt whole on the CPU"
    words = []
    if flags & vtkTiledRayCastStatistics.MeshRebuildPointsOnGPU:
        words.append("points moved on the GPU")
    if flags & vtkTiledRayCastStatistics.MeshRebuildPoints:
        words.append("points rebuilt on the CPU")
    if flags & vtkTiledRayCastStatistics.MeshRebuildScalars:
        words.append("scalars rebuilt")
    return ", ".join(words) or "unchanged"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--mesh", default=DEFAULT_MESH)
    parser.add_argument("--size", type=int, default=512)
    parser.add_argument("--frames", type=int, default=24)
    parser.add_argument("--mode", choices=("wave", "invert"), default="wave")
    parser.add_argument("--point-update", choices=("automatic", "cpu", "gpu"), default="automatic")
    parser.add_argument("--output-dir", default="frames")
    args = parser.parse_args()
    if args.size <= 0 or args.frames <= 0:
        sys.exit("--size and --frames must be positive")

    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(args.mesh)
    reader.Update()
    source = reader.GetOutput()
    if source.GetNumberOfCells() == 0 or source.GetPointData().GetScalars() is None:
        sys.exit("no cells or no point scalars in %s" % args.mesh)
    grid = vtkUnstructuredGrid()
    grid.ShallowCopy(source)
    points = vtkPoints()
    points.SetDataTypeToDouble()
    points.SetNumberOfPoints(source.GetNumberOfPoints())
    rest = [source.GetPoint(i) for i in range(source.GetNumberOfPoints())]
    for i, p in enumerate(rest):
        points.SetPoint(i, p)
    grid.SetPoints(points)
    bounds = source.GetBounds()
    centre = [0.5 * (bounds[2 * k] + bounds[2 * k + 1]) for k in range(3)]
    size = source.GetLength()

    low, high = source.GetPointData().GetScalars().GetRange()
    color = vtkColorTransferFunction()
    color.AddRGBPoint(low, 0.1, 0.3, 1.0)
    color.AddRGBPoint(low + 0.4 * (high - low), 0.2, 0.9, 0.4)
    color.AddRGBPoint(high, 1.0, 0.2, 0.1)
    opacity = vtkPiecewiseFunction()
    opacity.AddPoint(low, 0.05)
    opacity.AddPoint(high, 0.6)
    prop = vtkVolumeProperty()
    prop.SetColor(color)
    prop.SetScalarOpacity(opacity)
    prop.SetScalarOpacityUnitDistance(0.05 * size)

    mapper = vtkTiledRayCastVolumeMapper()
    mapper.SetInputData(grid)
    mapper.SynchronousStatisticsOn()  # this frame's GPU time, for the printout
    mapper.SetPointUpdate({"automatic": vtkTiledRayCastVolumeMapper.AUTOMATIC_POINT_UPDATE,
                           "cpu": vtkTiledRayCastVolumeMapper.CPU_POINT_UPDATE,
                           "gpu": vtkTiledRayCastVolumeMapper.GPU_POINT_UPDATE}[args.point_update])
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    renderer = vtkRenderer()
    renderer.SetBackground(0.08, 0.08, 0.12)
    renderer.AddVolume(volume)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(args.size, args.size)
    window.AddRenderer(renderer)
    renderer.ResetCamera()
    renderer.GetActiveCamera().Azimuth(30)
    renderer.GetActiveCamera().Elevation(20)
    renderer.ResetCameraClippingRange()

    os.makedirs(args.output_dir, exist_ok=True)
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ShouldRerenderOff()  # the frame is rendered already
    grab.ReadFrontBufferOff()
    writer = vtkPNGWriter()
    writer.SetInputConnection(grab.GetOutputPort())
    stats = mapper.GetStatistics()
    for frame in range(args.frames):
        start = time.perf_counter()
        deform(rest, points, centre, size, args.mode, 2.0 * math.pi * frame / args.frames)
        grid.Modified()
        moved = time.perf_counter()
        window.Render()
        done = time.perf_counter()
        # The statistics describe the frame just rendered: read them before anything renders again.
        line = ("frame %d: move %.1f ms, render %.1f ms (mesh %s in %.1f ms, GPU %.1f ms, "
                "%.2f MB uploaded)" % (frame, 1000 * (moved - start), 1000 * (done - moved),
                                       rebuilt(stats.GetMeshRebuild()),
                                       1000 * stats.GetMeshBuildTime(), stats.GetTotalGPUTime(),
                                       stats.GetUploadedBytes() / 2.0**20))
        grab.Modified()
        path = os.path.join(args.output_dir, "frame_%03d.png" % frame)
        writer.SetFileName(path)
        writer.Write()
        print(line + " -> " + path)
    renderer_line = [l for l in window.ReportCapabilities().splitlines() if "renderer string" in l]
    print("%d frames of %s (%s) in %s; %s" % (args.frames, os.path.basename(args.mesh), args.mode,
                                             args.output_dir,
                                             renderer_line[0].strip() if renderer_line else ""))


if __name__ == "__main__":
    main()
