"""Examples/Python/deforming_mesh.py run as a user runs it: both motions on spx_vistrails for a
few frames; each writes one PNG per frame at the asked size, and says per frame what the mapper
rebuilt (the points only: well under the first frame's upload), where (the GPU or the CPU, as
--point-update asks) and drew. Bad sizes are refused.
"""
import os
import re
import sys
import tempfile
import unittest

from tiledraycast_testing import (example_script, main, mesh_path, png_size,
                                  run_without_display)

SCRIPT = example_script("deforming_mesh.py")
MESH = mesh_path("spx_vistrails.vtu")


def run(*args):
    return run_without_display([sys.executable, SCRIPT, "--mesh", MESH] + list(args))


class DeformingMeshScript(unittest.TestCase):
    def test_motions(self):
        for mode in ("wave", "invert"):
            with tempfile.TemporaryDirectory() as out:
                code, stdout, stderr = run("--mode", mode, "--frames", "4", "--size", "96",
                                           "--output-dir", out)
                self.assertEqual(code, 0, stderr)
                frames = sorted(os.listdir(out))
                self.assertEqual(frames, ["frame_%03d.png" % i for i in range(4)])
                self.assertEqual(png_size(os.path.join(out, frames[-1])), (96, 96))
                uploads = [float(m) for m in re.findall(r"([0-9.]+) MB uploaded", stdout)]
                self.assertEqual(len(uploads), 4, stdout)
                # Frame 0 uploads the whole mesh; a points-only rebuild uploads the points.
                self.assertGreater(uploads[0], 0.0)
                self.assertTrue(any(u < uploads[0] for u in uploads[1:]), stdout)

    def test_point_update(self):
        for where, said in (("gpu", "points moved on the GPU"), ("cpu", "points rebuilt on the CPU")):
            with tempfile.TemporaryDirectory() as out:
                code, stdout, stderr = run("--point-update", where, "--frames", "3", "--size", "64",
                                           "--output-dir", out)
                self.assertEqual(code, 0, stderr)
                lines = [line for line in stdout.splitlines() if line.startswith("frame ")]
                self.assertEqual(len(lines), 3, stdout)
                self.assertIn("rebuilt whole on the CPU", lines[0])
                for line in lines[1:]:
                    self.assertIn(said, line)

    def test_bad_size(self):
        code, _, stderr = run("--size", "0", "--frames", "2")
        self.assertNotEqual(code, 0)
        self.assertIn("must be positive", stderr)


if __name__ == "__main__":
    main()
