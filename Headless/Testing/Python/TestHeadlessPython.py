"""Python without an X display: `vtkRenderWindow()` is the EGL window once tiledraycast is imported.

ctest runs this with DISPLAY removed from the environment. It checks that
- importing tiledraycast installs the factory, and vtkRenderWindow() gives vtkHeadlessEGLRenderWindow;
- that window renders the test scene of the C++ tests (Testing/Cxx/HeadlessTestScene.h, rebuilt
  here line by line) and matches the same baseline, TestHeadlessEGLWindow.png;
- vtkRenderWindowInteractor() needs no X, and its Start() returns;
- VTK_DEFAULT_OPENGL_WINDOW and vtkHeadlessObjectFactory.SetBackend() work from Python.
"""
import os
import unittest

from vtkmodules.vtkFiltersSources import vtkConeSource, vtkSphereSource
from vtkmodules.vtkRenderingCore import (
    vtkActor,
    vtkLight,
    vtkPolyDataMapper,
    vtkRenderer,
    vtkRenderWindow,
    vtkRenderWindowInteractor,
)
from vtkmodules.vtkTestingRendering import vtkTesting
import vtkmodules.vtkInteractionStyle  # noqa: F401  (default interactor style)

import tiledraycast  # noqa: F401  (installs the headless factory)
from tiledraycast import vtkHeadlessEGLRenderWindow, vtkHeadlessObjectFactory
from tiledraycast_testing import data_directory, main, temporary_directory

# This module's data (ctest passes it with -D): the baseline of the C++ window tests.
DATA = data_directory(os.path.join(os.path.dirname(__file__), "..", "Data"))


def add_test_scene(window):
    """HeadlessTestScene::Add of the C++ tests."""
    renderer = vtkRenderer()
    renderer.SetBackground(0.1, 0.2, 0.4)

    sphere = vtkSphereSource()
    sphere.SetCenter(-0.6, 0.0, 0.0)
    sphere.SetRadius(0.5)
    sphere.SetThetaResolution(48)
    sphere.SetPhiResolution(32)
    sphere_mapper = vtkPolyDataMapper()
    sphere_mapper.SetInputConnection(sphere.GetOutputPort())
    sphere_actor = vtkActor()
    sphere_actor.SetMapper(sphere_mapper)
    sphere_actor.GetProperty().SetColor(0.9, 0.3, 0.2)
    sphere_actor.GetProperty().SetSpecular(0.5)
    sphere_actor.GetProperty().SetSpecularPower(30.0)
    renderer.AddActor(sphere_actor)

    cone = vtkConeSource()
    cone.SetCenter(0.7, 0.0, 0.0)
    cone.SetHeight(1.0)
    cone.SetRadius(0.45)
    cone.SetResolution(40)
    cone.SetDirection(0.0, 1.0, 0.0)
    cone_mapper = vtkPolyDataMapper()
    cone_mapper.SetInputConnection(cone.GetOutputPort())
    cone_actor = vtkActor()
    cone_actor.SetMapper(cone_mapper)
    cone_actor.GetProperty().SetColor(0.3, 0.8, 0.3)
    renderer.AddActor(cone_actor)

    headlight = vtkLight()
    headlight.SetLightTypeToHeadlight()
    headlight.SetIntensity(0.7)
    renderer.AddLight(headlight)
    scene_light = vtkLight()
    scene_light.SetLightTypeToSceneLight()
    scene_light.SetPosition(3.0, 3.0, 3.0)
    scene_light.SetFocalPoint(0.0, 0.0, 0.0)
    scene_light.SetColor(1.0, 0.9, 0.8)
    scene_light.SetIntensity(0.6)
    renderer.AddLight(scene_light)

    renderer.ResetCamera()
    renderer.GetActiveCamera().Azimuth(20.0)
    renderer.GetActiveCamera().Elevation(15.0)

    window.AddRenderer(renderer)
    window.SetSize(300, 300)
    window.SetMultiSamples(0)
    return renderer


class TestHeadlessPython(unittest.TestCase):
    def setUp(self):
        self.assertNotIn("DISPLAY", os.environ, "ctest runs this test without DISPLAY")
        os.environ.pop("VTK_DEFAULT_OPENGL_WINDOW", None)
        vtkHeadlessObjectFactory.SetBackend("auto")

    def test_render_window_is_egl_and_matches_baseline(self):
        self.assertTrue(vtkHeadlessObjectFactory.IsInstalled())
        self.assertFalse(vtkHeadlessObjectFactory.HasUsableDisplay())
        window = vtkRenderWindow()
        self.assertEqual(window.GetClassName(), "vtkHeadlessEGLRenderWindow")
        add_test_scene(window)
        window.Render()
        self.assertTrue(window.HasContext(), window.GetInitializationError())
        print("Python EGL window: %s platform, %s, %s"
              % (window.GetPlatformInUse(), window.GetGLRenderer(), window.GetGLVersion()))
        self.assertTrue(window.GetGLRenderer())

        testing = vtkTesting()
        for arg in ("-V", os.path.join(DATA, "Baseline", "TestHeadlessEGLWindow.png"),
                    "-T", temporary_directory()):
            testing.AddArgument(arg)
        testing.SetRenderWindow(window)
        self.assertEqual(testing.RegressionTest(0.15), vtkTesting.PASSED)

    def test_interactor_needs_no_x(self):
        window = vtkRenderWindow()
        window.AddRenderer(vtkRenderer())
        interactor = vtkRenderWindowInteractor()
        self.assertEqual(interactor.GetClassName(), "vtkGenericRenderWindowInteractor")
        interactor.SetRenderWindow(window)
        interactor.Initialize()
        interactor.Start()  # returns at once: there is no event loop without a window system

    def test_environment_and_api_choices(self):
        os.environ["VTK_DEFAULT_OPENGL_WINDOW"] = "vtkOSOpenGLRenderWindow"
        window = vtkRenderWindow()
        self.assertEqual(window.GetClassName(), "vtkHeadlessEGLRenderWindow")
        self.assertEqual(window.GetPlatform(), vtkHeadlessEGLRenderWindow.PLATFORM_SURFACELESS)
        del os.environ["VTK_DEFAULT_OPENGL_WINDOW"]

        self.assertTrue(vtkHeadlessObjectFactory.SetBackend("vtkEGLRenderWindow"))
        self.assertEqual(vtkHeadlessObjectFactory.GetBackend(), "EGL")
        self.assertEqual(vtkHeadlessObjectFactory.GetResolvedWindowClassName(),
                         "vtkHeadlessEGLRenderWindow")
        self.assertEqual(vtkRenderWindow().GetPlatform(),
                         vtkHeadlessEGLRenderWindow.PLATFORM_AUTOMATIC)
        self.assertTrue(vtkHeadlessObjectFactory.SetBackend("auto"))
        self.assertEqual(vtkHeadlessObjectFactory.GetBackend(), "auto")


if __name__ == "__main__":
    main()
