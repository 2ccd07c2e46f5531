"""What the Python tests of TiledRayCast share, as VTK's tests share vtkmodules.test.Testing.

ctest runs every Python test as

    /usr/bin/python3 <Test>.py -D <data directory> -T <temporary directory> [more arguments]

with this folder on PYTHONPATH next to the build tree's 'tiledraycast' package
(tiledraycast_add_python_test, Module/cmake/TiledRayCastTesting.cmake), so a test writes

    from tiledraycast_testing import main, read_mesh, volume_property
    ...
    if __name__ == "__main__":
        main()

It holds what several tests did alike: the command line, the meshes of the data directory, a
volume property from a colour and an opacity ramp, a volume alone in an off-screen window, and
the example scripts run as a user runs them. Only tests import it: the examples in
Examples/Python are standalone scripts that users copy, and ParaView's pvbatch script runs in
ParaView's own Python.
"""
import os
import subprocess
import sys
import tempfile
import unittest

from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
from vtkmodules.vtkRenderingCore import (
    vtkColorTransferFunction,
    vtkRenderer,
    vtkRenderWindow,
    vtkVolume,
    vtkVolumeProperty,
)

# The source tree: this file is its Testing/Python/tiledraycast_testing.py.
SOURCE_DIRECTORY = os.path.abspath(os.path.join(os.path.dirname(__file__), os.pardir, os.pardir))


# --- The command line ---------------------------------------------------------------------------

def argument(flag, default=None):
    """The value after `flag` on the command line, else `default` (also when `flag` ends the
    line). ctest passes -D and -T to every test, and --classes to TestPythonImport."""
    args = sys.argv[1:]
    return args[args.index(flag) + 1] if flag in args[:-1] else default


def data_directory(default=os.path.join(SOURCE_DIRECTORY, "Testing", "Data")):
    """The data directory after -D (the meshes in Meshes/, baselines in Baseline/), else
    `default`: the source tree's Testing/Data, so that a test also runs by hand."""
    return argument("-D", default)


def temporary_directory():
    """The directory after -T, where a test may write (the build tree's Testing/Temporary), else
    the system's temporary directory."""
    return argument("-T", tempfile.gettempdir())


def main():
    """Runs the tests of the calling script (`if __name__ == "__main__": main()`).

    unittest sees only the script's name: the arguments ctest passes are read by the functions
    above, and unittest would take them for test names, or refuse them."""
    unittest.main(module="__main__", argv=[sys.argv[0]])


# --- Meshes and the scene of a volume -----------------------------------------------------------

def mesh_path(name):
    """Meshes/<name> of the data directory."""
    return os.path.join(data_directory(), "Meshes", name)


def mesh_reader(name):
    """A vtkXMLUnstructuredGridReader of Meshes/<name>, updated: GetOutput() is the grid, and
    its output port feeds a pipeline."""
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(mesh_path(name))
    reader.Update()
    return reader


def read_mesh(name):
    """The vtkUnstructuredGrid of Meshes/<name>."""
    return mesh_reader(name).GetOutput()


def ramp_point(scalar_range, fraction):
    """The scalar at `fraction` of `scalar_range` (lo, hi): (1 - f) lo + f hi, which is lo at 0,
    hi at 1 and 0.5 (lo + hi) at 0.5 to the last bit (halving is exact), the points the tests
    had written out."""
    lo, hi = scalar_range
    return (1.0 - fraction) * lo + fraction * hi


def volume_property(scalar_range, colors, opacities, unit_distance=None):
    """A vtkVolumeProperty from ramps over `scalar_range` (lo, hi).

    colors: (fraction, (r, g, b)) points, or None for VTK's default colour; opacities:
    (fraction, opacity) points; a fraction places its point at ramp_point(scalar_range,
    fraction). unit_distance: the scalar opacity unit distance, None for VTK's 1."""
    prop = vtkVolumeProperty()
    if colors is not None:
        color = vtkColorTransferFunction()
        for fraction, rgb in colors:
            color.AddRGBPoint(ramp_point(scalar_range, fraction), *rgb)
        prop.SetColor(color)
    opacity = vtkPiecewiseFunction()
    for fraction, value in opacities:
        opacity.AddPoint(ramp_point(scalar_range, fraction), value)
    prop.SetScalarOpacity(opacity)
    if unit_distance is not None:
        prop.SetScalarOpacityUnitDistance(unit_distance)
    return prop


def offscreen_window(mapper, prop, size, multisamples=None):
    """The volume of `mapper` and `prop` alone in a size x size off-screen window, camera reset;
    returns (volume, renderer, window). multisamples: the window's, None for VTK's default. The
    caller has imported an OpenGL implementation (`import tiledraycast` does)."""
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    renderer = vtkRenderer()
    renderer.AddVolume(volume)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    if multisamples is not None:
        window.SetMultiSamples(multisamples)
    window.SetSize(size, size)
    window.AddRenderer(renderer)
    renderer.ResetCamera()
    return volume, renderer, window


# --- The example scripts, run as a user runs them -----------------------------------------------

def example_script(name):
    """Examples/Python/<name> of the source tree."""
    return os.path.join(SOURCE_DIRECTORY, "Examples", "Python", name)


def run_without_display(command, timeout=600):
    """Runs `command` (a list) with DISPLAY removed from the environment, as on a machine with
    no X server; returns (exit status, stdout, stderr)."""
    environment = {k: v for k, v in os.environ.items() if k != "DISPLAY"}
    result = subprocess.run(command, capture_output=True, text=True, timeout=timeout,
                            env=environment)
    return result.returncode, result.stdout, result.stderr


def png_size(path):
    """(width, height) of the PNG image at `path`."""
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput().GetDimensions()[:2]
