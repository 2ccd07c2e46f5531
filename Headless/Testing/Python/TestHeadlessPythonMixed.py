"""Python with an X display: X and EGL windows in one interpreter, and a quiet exit.

ctest runs this under xvfb-run. A child interpreter makes vtkRenderWindow() (VTK's X window,
since a display answers) and two vtkHeadlessEGLRenderWindow, renders them in turn, checks each
image, and exits with all three windows still alive, the X context current: interpreter teardown
then destroys them in whatever order it likes. glvnd lets only one of GLX and EGL own the thread,
so every switch and every teardown must hand it over; a mistake shows up as an X BadAccess error
(which ends the process) or as "eglMakeCurrent failed" errors at exit. The child must exit with 0
and print nothing on stderr.
"""
import os
import subprocess
import sys
import unittest

from tiledraycast_testing import main

CHILD = r"""
from vtkmodules.vtkFiltersSources import vtkConeSource
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderer,
                                         vtkRenderWindow, vtkWindowToImageFilter)
import vtkmodules.vtkInteractionStyle
import tiledraycast
from tiledraycast import vtkHeadlessEGLRenderWindow

def scene(window):
    cone = vtkConeSource()
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(cone.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    window.AddRenderer(renderer)
    window.SetSize(120, 100)
    window.SetMultiSamples(0)

def lit_pixels(window):
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    scalars = grab.GetOutput().GetPointData().GetScalars()
    return sum(1 for i in range(scalars.GetNumberOfTuples()) if scalars.GetValue(3 * i) > 100)

x = vtkRenderWindow()
assert x.IsA("vtkXOpenGLRenderWindow"), x.GetClassName()
egl = [vtkHeadlessEGLRenderWindow(), vtkHeadlessEGLRenderWindow()]
for window in [x] + egl:
    scene(window)
counts = [lit_pixels(w) for w in (x, egl[0], x, egl[1], egl[0], x)]
assert min(counts) > 500 and max(counts) == min(counts), counts
print("lit pixels per render:", counts)
"""


class TestHeadlessPythonMixed(unittest.TestCase):
    def test_x_and_egl_windows_share_the_interpreter(self):
        self.assertTrue(os.environ.get("DISPLAY"), "ctest runs this test under xvfb-run")
        child = subprocess.run([sys.executable, "-c", CHILD], capture_output=True, text=True,
                               timeout=120)
        sys.stdout.write(child.stdout)
        self.assertEqual(child.returncode, 0, child.stderr)
        self.assertEqual(child.stderr.strip(), "", "the interpreter must exit quietly")


if __name__ == "__main__":
    main()
