"""Render a tetrahedral mesh with no X server and say which OpenGL did it.

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 \
        Examples/Python/headless_render.py [--mesh FILE.vtu] [--size 512] [--frames 10] [--output out.png]

After `import tiledraycast`, a plain vtkRenderWindow() is the EGL window when there is no X display
(a GPU through EGL's device platform, else Mesa's llvmpipe through the surfaceless platform).
The volume is drawn with VTK's vtkProjectedTetrahedraMapper, so this runs whatever else of
TiledRayCast is built. Module/run-on-gpu.sh runs it on the GPU machine.
"""
import argparse
import os
import sys
import time

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
from vtkmodules.vtkRenderingVolume import vtkProjectedTetrahedraMapper
import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401  (OpenGL implementation of the mapper)

import tiledraycast  # noqa: F401  (vtkRenderWindow() becomes the EGL window without X)

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_MESH = os.path.join(HERE, "..", "..", "Testing", "Data", "Meshes", "spx_vistrails.vtu")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--mesh", default=DEFAULT_MESH)
    parser.add_argument("--size", type=int, default=512)
    parser.add_argument("--frames", type=int, default=10)
    parser.add_argument("--output", default="headless_render.png")
    args = parser.parse_args()

    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(args.mesh)
    reader.Update()
    grid = reader.GetOutput()
    if grid.GetNumberOfCells() == 0:
        sys.exit("cannot read a mesh from %s" % args.mesh)
    low, high = grid.GetPointData().GetScalars().GetRange()

    color = vtkColorTransferFunction()
    color.AddRGBPoint(low, 0.1, 0.2, 1.0)
    color.AddRGBPoint(0.5 * (low + high), 0.2, 1.0, 0.3)
    color.AddRGBPoint(high, 1.0, 0.2, 0.1)
    opacity = vtkPiecewiseFunction()
    opacity.AddPoint(low, 0.05)
    opacity.AddPoint(high, 0.8)
    prop = vtkVolumeProperty()
    prop.SetColor(color)
    prop.SetScalarOpacity(opacity)
    bounds = grid.GetBounds()
    prop.SetScalarOpacityUnitDistance(0.1 * max(bounds[1] - bounds[0], bounds[3] - bounds[2],
                                                bounds[5] - bounds[4]))

    mapper = vtkProjectedTetrahedraMapper()
    mapper.SetInputConnection(reader.GetOutputPort())
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    renderer = vtkRenderer()
    renderer.SetBackground(0.1, 0.1, 0.1)
    renderer.AddVolume(volume)
    renderer.ResetCamera()

    window = vtkRenderWindow()
    window.AddRenderer(renderer)
    window.SetSize(args.size, args.size)
    window.SetMultiSamples(0)
    start = time.perf_counter()
    window.Render()
    first = time.perf_counter() - start

    print("window: %s" % window.GetClassName())
    if window.IsA("vtkHeadlessEGLRenderWindow"):
        if not window.HasContext():
            sys.exit("no EGL context: %s" % window.GetInitializationError())
        print("EGL platform: %s (device %d); EGL %s, %s"
              % (window.GetPlatformInUse(), window.GetDeviceIndexInUse(),
                 window.GetEGLVersion(), window.GetEGLVendor()))
        print("EGL devices:\n  " + window.GetDeviceDescriptions().strip().replace("\n", "\n  "))
        print("GL_VENDOR:   %s" % window.GetGLVendor())
        print("GL_RENDERER: %s" % window.GetGLRenderer())
        print("GL_VERSION:  %s" % window.GetGLVersion())
    else:
        print(window.ReportCapabilities().split("OpenGL extensions")[0].strip())

    camera = renderer.GetActiveCamera()
    times = []
    for _ in range(args.frames):
        camera.Azimuth(360.0 / max(args.frames, 1))
        start = time.perf_counter()
        window.Render()
        window.WaitForCompletion()
        times.append(time.perf_counter() - start)
    print("mesh: %s, %d tets; %dx%d; first render %.3f s; %d frames of vtkProjectedTetrahedraMapper: "
          "median %.4f s" % (os.path.basename(args.mesh), grid.GetNumberOfCells(), args.size,
                             args.size, first, len(times), sorted(times)[len(times) // 2]
                             if times else 0.0))

    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    writer = vtkPNGWriter()
    writer.SetInputConnection(grab.GetOutputPort())
    writer.SetFileName(args.output)
    writer.Write()
    print("wrote %s" % args.output)


if __name__ == "__main__":
    main()
