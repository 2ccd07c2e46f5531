"""ParaView 5.11 with the TiledRayCast plugin, checked against the exact reference renderer.

Runs under Debian's /usr/bin/python3 (VTK 9.1 and the 'tiledraycast' package of this build) and
starts `xvfb-run -a pvbatch pvbatch_render.py` from the private ParaView root
(ParaView/fetch-paraview.sh) for each rendering:
  --case meshes  two meshes (bluntfin_tets: one boundary layer seen from outside; spx_vistrails:
                 non-convex, several layers), each with "Tiled ray cast" and "Projected tetra", in
                 ParaView's default set-up (its discretized "Cool to Warm" map, 256 steps, its
                 linear opacity ramp): ours against the reference through the same camera and
                 transfer function, with the scene tests' bounds; Projected tetra's difference
                 printed for comparison
  --case mixed   a mixed-cell mesh (a clipped Wavelet: hexahedra, wedges, pyramids, tetrahedra)
                 with the discretized map, coloured by component Y of a vector array (the
                 VectorMode/VectorComponent the representation forwards): no warning, against
                 the reference of the same mesh split into tetrahedra as ParaView splits it, told
                 the same component
Any warning or error that pvbatch prints fails the test, ParaView's own included (the plugin's
Volume representation used to cost twelve of ParaView's deprecation warnings per representation:
vtkTiledRayCastVolumeSubProxyOverride).
Exit status 125 (a ctest skip, with the reason) when the private root or the plugin is missing.
"""
import argparse
import json
import os
import re
import subprocess
import sys
import time

from vtkmodules.vtkCommonCore import vtkUnsignedCharArray
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPiecewiseFunction
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
from vtkmodules.vtkRenderingCore import (
    vtkCamera,
    vtkColorTransferFunction,
    vtkVolumeProperty,
)
from tiledraycast import vtkTetReferenceRenderer

WARNING = re.compile(r"WARN\||ERR\||Warning|ERROR|Error", re.IGNORECASE)

# Bounds on ours against the reference, in 1/255 (as the scene tests': Testing/Cxx
# TiledRayCastTestScene.h): RMSE, 99.9th percentile, maximum.
BOUNDS = (0.75, 1.0, 2.0)


def skipped(options, program):
    """Why the test cannot run here (printed, then the ctest skip status 125), or None: the
    private root's `program` or the plugin missing."""
    if not os.path.exists(os.path.join(options.root, "usr", "bin", program)):
        print("SKIP: no private ParaView root at %s (ParaView/fetch-paraview.sh could not fetch "
              "it here: see the setup test's output)" % options.root)
        return 125
    if not os.path.exists(options.plugin):
        print("SKIP: the plugin %s was not built (see the setup test's output)" % options.plugin)
        return 125
    return None


def run_pvbatch(options, name, extra):
    output = os.path.join(options.temp, name)
    env = dict(os.environ)
    lib = os.path.join(options.root, "usr", "lib", "x86_64-linux-gnu")
    env["LD_LIBRARY_PATH"] = lib + (":" + env["LD_LIBRARY_PATH"] if env.get("LD_LIBRARY_PATH") else "")
    # ParaView's own vtkmodules first: the system's VTK 9.1 ones must not be imported by pvbatch.
    env["PYTHONPATH"] = os.path.join(options.root, "usr", "lib", "python3", "dist-packages")
    env.pop("PV_PLUGIN_PATH", None)
    command = [
        "xvfb-run", "-a", "-s", "-screen 0 1280x1024x24",
        os.path.join(options.root, "usr", "bin", "pvbatch"),
        os.path.join(os.path.dirname(os.path.abspath(__file__)), "pvbatch_render.py"),
        "--plugin", options.plugin, "--output", output,
    ] + extra
    start = time.perf_counter()
    for attempt in range(3):
        done = subprocess.run(command, env=env, stdout=subprocess.PIPE,
                              stderr=subprocess.STDOUT, text=True, timeout=600)
        # Two xvfb-run -a started at once (other suites on the machine) may pick the same
        # display: pvbatch then aborts creating its window. Only that is retried.
        if done.returncode == 0 or "CreateAWindow" not in done.stdout:
            break
        print("pvbatch could not open its X window (attempt %d); again" % (attempt + 1))
        print("\n".join(l for l in done.stdout.splitlines() if "ERR" in l or "rror" in l)[:2000])
    print(done.stdout.strip())
    print("pvbatch: %.1f s" % (time.perf_counter() - start))
    if done.returncode != 0:
        raise RuntimeError("pvbatch failed (%d) for %s" % (done.returncode, name))
    warnings = []
    for line in done.stdout.splitlines():
        if line.startswith("statistics:"):
            continue
        if WARNING.search(line):
            warnings.append(line)
    with open(output + ".json") as f:
        result = json.load(f)
    return output, result, warnings


def make_property(result):
    colors = result["colors"]
    space = colors["color_space"]
    if colors["discretize"]:
        # A discretized map is piecewise constant: restated here as a plain colour function with
        # a step (two nodes at one scalar) at each of ParaView's steps and ParaView's own colour
        # on each (sampled at the step's centre by pvbatch_render.py). The reference integrates
        # that exactly, and fast; rebuilt with VTK 9.1's own discretizable class, it would
        # integrate 256 discontinuities adaptively (minutes on two cores).
        ctf = vtkColorTransferFunction()
        ctf.AllowDuplicateScalarsOn()
        lo, hi = result["range"]
        samples = colors["samples"]
        n = len(samples)
        ctf.AddRGBPoint(lo, *samples[0][1:])
        for k in range(1, n):
            step = lo + (hi - lo) * k / n
            ctf.AddRGBPoint(step, *samples[k - 1][1:])
            ctf.AddRGBPoint(step, *samples[k][1:])
        ctf.AddRGBPoint(hi, *samples[-1][1:])
    else:
        ctf = vtkColorTransferFunction()
        p = colors["rgb_points"]
        for i in range(0, len(p), 4):
            ctf.AddRGBPoint(*p[i:i + 4])
        {"RGB": ctf.SetColorSpaceToRGB, "HSV": ctf.SetColorSpaceToHSV,
         "Lab": ctf.SetColorSpaceToLab, "Diverging": ctf.SetColorSpaceToDiverging,
         "Step": ctf.SetColorSpaceToStep}[space]()
    # The map as restated here against ParaView's own evaluation of it, step by step.
    worst = 0.0
    for s, r, g, b in colors["samples"]:
        rgb = [0.0, 0.0, 0.0]
        ctf.GetColor(s, rgb)
        worst = max(worst, abs(rgb[0] - r), abs(rgb[1] - g), abs(rgb[2] - b))
    opacity = vtkPiecewiseFunction()
    p = result["opacity_points"]
    for i in range(0, len(p), 4):
        opacity.AddPoint(*p[i:i + 4])
    prop = vtkVolumeProperty()
    prop.SetColor(ctf)
    prop.SetScalarOpacity(opacity)
    prop.SetScalarOpacityUnitDistance(result["unit_distance"])
    return prop, worst


def load_rgb(path):
    """A screenshot's RGB only (ParaView may write RGBA), as an image to compare."""
    png = vtkPNGReader()
    png.SetFileName(path)
    png.Update()
    image = png.GetOutput()
    source = image.GetPointData().GetScalars()
    rgb = vtkUnsignedCharArray()
    rgb.SetName("RGB")
    rgb.SetNumberOfComponents(3)
    rgb.SetNumberOfTuples(source.GetNumberOfTuples())
    for c in range(3):
        rgb.CopyComponent(c, source, c)
    out = vtkImageData()
    out.SetDimensions(image.GetDimensions())
    out.GetPointData().SetScalars(rgb)
    return out


def compare(output, result, mesh_file):
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(mesh_file)
    reader.Update()
    prop, map_difference = make_property(result)
    camera = vtkCamera()
    c = result["camera"]
    camera.SetPosition(c["position"])
    camera.SetFocalPoint(c["focal_point"])
    camera.SetViewUp(c["view_up"])
    camera.SetViewAngle(c["view_angle"])
    camera.SetClippingRange(c["clipping_range"])
    reference = vtkTetReferenceRenderer()
    reference.SetInputData(reader.GetOutput())
    selection = reference.GetScalarSelection()
    selection.SetScalarModeToUsePointFieldData()
    selection.SelectScalarArray(result["array"])
    # A component or the magnitude, as ParaView's map says.
    if result["vector_mode"] == "Component":
        selection.SetVectorModeToComponent()
    else:
        selection.SetVectorModeToMagnitude()
    selection.SetVectorComponent(result["vector_component"])
    reference.SetVolumeProperty(prop)
    reference.SetCamera(camera)
    size = result["size"]  # pixels: a square's side, or [width, height]
    reference.SetImageSize(*(size if isinstance(size, list) else (size, size)))
    start = time.perf_counter()
    if not reference.Render():
        raise RuntimeError("the reference renderer failed")
    print("reference: %.1f s" % (time.perf_counter() - start))
    expected = vtkImageData()
    vtkTetReferenceRenderer.ConvertToUnsignedChar(
        reference.GetOutput(), result["background"], expected)
    actual = load_rgb(output + ".png")
    stats = [0.0, 0.0, 0.0]
    if not vtkTetReferenceRenderer.CompareImages(actual, expected, stats):
        raise RuntimeError("images cannot be compared")
    return stats, map_difference


def check(name, stats, map_difference, bounded):
    print("%s vs exact reference (1/255): RMSE %.3f, 99.9th percentile %.1f, max %.1f%s"
          % (name, stats[0], stats[1], stats[2],
             " (bounds %.2f, %.1f, %.1f)" % BOUNDS if bounded else " (not bounded)"))
    ok = map_difference <= 1.0 / 255 + 1e-9
    if not ok:
        print("%s: the colour map rebuilt for the reference differs from ParaView's by %.4f"
              % (name, map_difference))
    if bounded:
        ok = ok and all(s <= b for s, b in zip(stats, BOUNDS))
    return ok


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--root", required=True)
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--case", choices=("meshes", "mixed"), required=True)
    parser.add_argument("-D", dest="data", required=True)
    parser.add_argument("-T", dest="temp", required=True)
    parser.add_argument("--size", type=int, default=200)
    options = parser.parse_args()
    skip = skipped(options, "pvbatch")
    if skip:
        return skip
    ok = True
    if options.case == "meshes":
        for mesh in ("bluntfin_tets", "spx_vistrails"):
            mesh_file = os.path.join(options.data, "Meshes", mesh + ".vtu")
            for mapper, tag in (("Tiled ray cast", "trc"), ("Projected tetra", "pt")):
                name = "ParaView_%s_%s" % (mesh, tag)
                output, result, warnings = run_pvbatch(
                    options, name, ["--mesh", mesh_file, "--mapper", mapper,
                                    "--size", str(options.size)])
                stats, map_difference = compare(output, result, mesh_file)
                ours = mapper == "Tiled ray cast"
                ok = check("%s, %s" % (mesh, mapper), stats, map_difference, ours) and ok
                if ours:
                    if warnings:
                        print("%s: warnings:\n%s" % (name, "\n".join(warnings)))
                        ok = False
                    if not result["statistics"]:
                        print("%s: no statistics from the TiledRayCastStatistics property" % name)
                        ok = False
    else:
        name = "ParaView_mixed_trc"
        output, result, warnings = run_pvbatch(
            options, name, ["--mesh", "mixed", "--size", str(options.size)])
        types = result["cell_types"]
        print("mixed mesh: VTK cell types %s, colour map %s (discretize %d, %d steps), "
              "array %s, vector mode %s %d"
              % (types, result["colors"]["class"], result["colors"]["discretize"],
                 result["colors"]["number_of_values"], result["array"], result["vector_mode"],
                 result["vector_component"]))
        if (len(types) < 2 or not result["colors"]["discretize"]
                or result["vector_mode"] != "Component" or result["vector_component"] != 1):
            print("the mixed case is not a mixed mesh, coloured by a vector component through "
                  "a discretized map")
            ok = False
        if warnings:
            print("warnings:\n" + "\n".join(warnings))
            ok = False
        stats, map_difference = compare(output, result, output + "_tets.vtu")
        ok = check("mixed mesh, Tiled ray cast", stats, map_difference, True) and ok
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
