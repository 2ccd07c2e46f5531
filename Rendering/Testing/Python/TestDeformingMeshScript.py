"""Examples/Python/deforming_mesh.py run as a user runs it: both motions on spx_vistrails for a
few frames; each writes one PNG per frame at the asked size, and says per frame what the mapper
rebuilt (the points only: well under the first frame's upload) and drew. Bad sizes are refused.
"""
import os
import re
import subprocess
import sys
import tempfile
import unittest

from vtkmodules.vtkIOImage import vtkPNGReader

SOURCE = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
SCRIPT = os.path.join(SOURCE, "Examples", "Python", "deforming_mesh.py")
MESH = os.path.join(SOURCE, "Testing", "Data", "Meshes", "spx_vistrails.vtu")


def run(*args):
    environment = {k: v for k, v in os.environ.items() if k != "DISPLAY"}
    result = subprocess.run([sys.executable, SCRIPT, "--mesh", MESH] + list(args),
                            capture_output=True, text=True, timeout=600, env=environment)
    return result.returncode, result.stdout, result.stderr


class DeformingMeshScript(unittest.TestCase):
    def test_motions(self):
        for mode in ("wave", "invert"):
            with tempfile.TemporaryDirectory() as out:
                code, stdout, stderr = run("--mode", mode, "--frames", "4", "--size", "96",
                                           "--output-dir", out)
                self.assertEqual(code, 0, stderr)
                frames = sorted(os.listdir(out))
                self.assertEqual(frames, ["frame_%03d.png" % i for i in range(4)])
                reader = vtkPNGReader()
                reader.SetFileName(os.path.join(out, frames[-1]))
                reader.Update()
                self.assertEqual(reader.GetOutput().GetDimensions()[:2], (96, 96))
                uploads = [float(m) for m in re.findall(r"([0-9.]+) MB uploaded", stdout)]
                self.assertEqual(len(uploads), 4, stdout)
                # Frame 0 uploads the whole mesh; a points-only rebuild uploads the points.
                self.assertGreater(uploads[0], 0.0)
                self.assertTrue(any(u < uploads[0] for u in uploads[1:]), stdout)

    def test_bad_size(self):
        code, _, stderr = run("--size", "0", "--frames", "2")
        self.assertNotEqual(code, 0)
        self.assertIn("must be positive", stderr)


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0]])  # ctest's -D and -T arguments are not needed here
