"""Costs of the render windows: EGL (no X) against VTK's X window, on whatever OpenGL is here.

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Benchmarks/headless_windows.py
    PYTHONPATH=build/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 Benchmarks/headless_windows.py

For each window kind available (EGL always, X when a display answers) it prints: the time to get a
context, the first render of the lit test scene, the median frame time at 300x300 and 1024x1024
(render + glFinish), the median read-back of a 1024x1024 image (GetPixelData), and for EGL the cost of switching
between two windows (two renders alternating, against the same window twice). Figures in
docs/headless.md come from this script.
"""
import statistics
import time

from vtkmodules.vtkCommonCore import vtkUnsignedCharArray
from vtkmodules.vtkFiltersSources import vtkConeSource, vtkSphereSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkLight, vtkPolyDataMapper, vtkRenderer
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

import tiledraycast  # noqa: F401
from tiledraycast import vtkHeadlessEGLRenderWindow, vtkHeadlessObjectFactory

FRAMES = 30


def scene(window, size):
    renderer = vtkRenderer()
    renderer.SetBackground(0.1, 0.2, 0.4)
    sphere = vtkSphereSource()
    sphere.SetCenter(-0.6, 0, 0)
    sphere.SetRadius(0.5)
    sphere.SetThetaResolution(48)
    sphere.SetPhiResolution(32)
    cone = vtkConeSource()
    cone.SetCenter(0.7, 0, 0)
    cone.SetResolution(40)
    for source in (sphere, cone):
        mapper = vtkPolyDataMapper()
        mapper.SetInputConnection(source.GetOutputPort())
        actor = vtkActor()
        actor.SetMapper(mapper)
        renderer.AddActor(actor)
    light = vtkLight()
    light.SetLightTypeToHeadlight()
    renderer.AddLight(light)
    renderer.ResetCamera()
    window.AddRenderer(renderer)
    window.SetSize(size, size)
    window.SetMultiSamples(0)
    return renderer


def median_frame(window, renderer, frames=FRAMES):
    times = []
    for _ in range(frames):
        renderer.GetActiveCamera().Azimuth(3.0)
        start = time.perf_counter()
        window.Render()
        window.WaitForCompletion()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def measure(kind, make):
    window = make()
    start = time.perf_counter()
    if kind == "EGL":
        ok = window.EnsureContext()
    else:
        window.SetSize(8, 8)
        window.Render()  # VTK's X window creates its context in its first Render()
        ok = True
    context = time.perf_counter() - start
    if not ok:
        print("%s: no context" % kind)
        return
    renderer = scene(window, 300)
    start = time.perf_counter()
    window.Render()
    window.WaitForCompletion()
    first = time.perf_counter() - start
    small = median_frame(window, renderer)
    window.SetSize(1024, 1024)
    large = median_frame(window, renderer)
    pixels = vtkUnsignedCharArray()
    grab_times = []
    for _ in range(10):
        start = time.perf_counter()
        window.GetPixelData(0, 0, 1023, 1023, 0, pixels, 0)
        grab_times.append(time.perf_counter() - start)
    renderer_string = (window.GetGLRenderer() if kind == "EGL"
                       else window.ReportCapabilities().split("renderer string:")[1].split("\n")[0].strip())
    print("%-4s %-36s context %6.1f ms | first render %6.1f ms | frame 300^2 %6.2f ms | "
          "frame 1024^2 %6.2f ms | read 1024^2 %6.2f ms"
          % (kind, renderer_string[:36], 1e3 * context, 1e3 * first, 1e3 * small, 1e3 * large,
             1e3 * statistics.median(grab_times)))
    return window


def switching():
    """Two EGL windows rendering in turn pay eglMakeCurrent at every frame."""
    windows = [vtkHeadlessEGLRenderWindow(), vtkHeadlessEGLRenderWindow()]
    renderers = [scene(w, 300) for w in windows]
    for w in windows:
        w.Render()
    same = median_frame(windows[0], renderers[0], 2 * FRAMES)
    times = []
    for i in range(2 * FRAMES):
        w = windows[i % 2]
        renderers[i % 2].GetActiveCamera().Azimuth(3.0)
        start = time.perf_counter()
        w.Render()
        w.WaitForCompletion()
        times.append(time.perf_counter() - start)
    print("EGL  two windows in turn: frame 300^2 %.2f ms, one window: %.2f ms"
          % (1e3 * statistics.median(times), 1e3 * same))


if __name__ == "__main__":
    measure("EGL", vtkHeadlessEGLRenderWindow)
    if vtkHeadlessObjectFactory.HasUsableDisplay():
        from tiledraycast import vtkHeadlessXOpenGLRenderWindow
        measure("X", vtkHeadlessXOpenGLRenderWindow)
    switching()
