"""The cut_volumes experiment without measuring: the OBJ its mesh panel cuts with is a closed,
outward-facing mesh within the model in plan that opens its top, the box opens from above, and
--report-only on the committed data states each case's target verdict as its ratio decides it.
Run by ctest (label cpu): /usr/bin/python3 -m unittest cut_volumes_test."""
import collections
import json
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

REPO = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
sys.path.insert(0, os.path.join(REPO, "experiments", "cut_volumes"))
import scenes  # noqa: E402

# Petra's bounds as `cutaway inspect --json` gives them (rounded): kilometres across, a few
# hundred metres thick, depths growing downwards.
BOUNDS = {"min": [-22.0, -24.1, 1946.1], "max": [3900.0, 4226.7, 2209.6]}


def signed_volume(vertices, faces):
    """Sum over the faces of the tetrahedra with the origin: positive for outward faces."""
    total = 0.0
    for face in faces:
        a, b, c = (vertices[i - 1] for i in face)
        total += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                  a[2] * (b[0] * c[1] - b[1] * c[0])) / 6
    return total


class SceneTest(unittest.TestCase):
    def test_icosahedron_is_closed_and_faces_outwards(self):
        vertices, faces = scenes.icosahedron([10, 20, 30], [3, 2, 1])
        edges = collections.Counter((a, b) for face in faces for a, b in zip(face, face[1:] + face[:1]))
        # Closed and consistently oriented: every directed edge once, its reverse once.
        self.assertEqual(len(faces), 20)
        for (a, b), count in edges.items():
            self.assertEqual(count, 1)
            self.assertEqual(edges[(b, a)], 1)
        # An icosahedron inscribed in the unit sphere has volume 2.536 (5/12 (3 + sqrt 5) a^3,
        # a = 1.0515); scaled by 3 x 2 x 1. 1e-3 relative: the formula's digits, not a tolerance.
        self.assertAlmostEqual(signed_volume(vertices, faces) / (2.53615 * 6), 1.0, places=3)

    def test_mesh_obj_lies_within_the_model_in_plan_and_opens_its_top(self):
        folder = tempfile.mkdtemp(prefix="cutaway-scenes-")
        try:
            spec = scenes.write_mesh_obj(BOUNDS, folder)
            with open(spec[len("mesh:"):]) as f:
                points = [[float(v) for v in line.split()[1:]] for line in f if line.startswith("v ")]
        finally:
            shutil.rmtree(folder)
        for axis in range(2):
            self.assertGreaterEqual(min(p[axis] for p in points), BOUNDS["min"][axis])
            self.assertLessEqual(max(p[axis] for p in points), BOUNDS["max"][axis])
        # Above the top (smaller depth) so that the cut opens the surface; not through the bottom.
        self.assertLess(min(p[2] for p in points), BOUNDS["min"][2])
        self.assertLess(max(p[2] for p in points), BOUNDS["max"][2])

    def test_box_opens_from_above_the_top(self):
        values = [float(v) for v in scenes.box_spec(BOUNDS)[len("box:"):].split(",")]
        self.assertLess(values[2], BOUNDS["min"][2])  # depths grow downwards: above the top is less
        self.assertLess(values[5], BOUNDS["max"][2])
        for axis in range(2):
            self.assertGreater(values[axis], BOUNDS["min"][axis])
            self.assertLess(values[3 + axis], BOUNDS["max"][axis])


class ReportTest(unittest.TestCase):
    def test_report_states_each_target_as_the_ratio_decides_it(self):
        scratch = tempfile.mkdtemp(prefix="cutaway-cut-volumes-")
        try:
            folder = os.path.join(scratch, "results", "cut_volumes")
            os.makedirs(folder)
            shutil.copy(os.path.join(REPO, "results", "cut_volumes", "cut_volumes.json"), folder)
            result = subprocess.run(["/usr/bin/python3", os.path.join(REPO, "experiments", "cut_volumes", "run.py"),
                                     "--report-only", "--out", scratch], capture_output=True, text=True)
            self.assertEqual(result.returncode, 0, result.stderr)
            with open(os.path.join(folder, "README.md")) as f:
                readme = f.read()
            with open(os.path.join(folder, "cut_volumes.json")) as f:
                rows = json.load(f)["cost"]
        finally:
            shutil.rmtree(scratch)
        for row in rows:
            line = next(line for line in readme.splitlines() if line.startswith(f"| {row['case']} |"))
            self.assertIn(f"{row['ratio_to_none']:.3f}", line)
            if "target" in row:
                verdict = "holds" if row["ratio_to_none"] <= row["target"] else "MISSED"
                self.assertIn(verdict, line)


if __name__ == "__main__":
    unittest.main()
