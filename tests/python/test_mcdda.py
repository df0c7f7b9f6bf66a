"""The Python module `mcdda` (docs/python.md): models from files and dicts, overrides, checks,
mesh and fields as NumPy arrays, runs with progress, stopping, errors and the GIL released."""

import os
import threading
import time
import unittest

import numpy as np

import mcdda

EXAMPLES = os.environ.get("MCDDA_EXAMPLES_DIR", os.path.join(os.path.dirname(__file__), "..", "..", "examples"))
INCLINE = os.path.join(EXAMPLES, "incline-stable.json")
STATIC = ["/analysis/type=\"static\"", "/analysis/time_step=1"]


def square_block():
    """A 10 m square of rock on rollers, as a dict laid out like the model file."""
    return {
        "format": "mcdda-model", "version": 1,
        "materials": [{"name": "rock", "young_modulus": 1e9, "poisson_ratio": 0.25,
                       "unit_weight": 25e3, "cohesion": 1e6, "friction_angle": 35}],
        "regions": [{"name": "block", "material": "rock",
                     "boundary": [[0, 0], [10, 0], [10, 10], [0, 10]]}],
        "rollers": [{"name": "base", "from": [0, 0], "to": [10, 0], "fixed": "y"},
                    {"name": "side", "from": [0, 0], "to": [0, 10], "fixed": "x"}],
        "mesh": {"size": 2.0},
        "analysis": {"type": "static", "steps": 2, "time_step": 1},
    }


class StrengthReductionTest(unittest.TestCase):
    def test_wedge_factor_of_safety_and_trials(self):
        # The planar wedge: F = tan 20° / tan 30° = 0.630 (docs/plasticity.md).
        a = mcdda.Analysis.from_file(os.path.join(EXAMPLES, "slope-wedge.json"))
        a.set({"/analysis/type": "strength_reduction", "/analysis/steps": 1})
        r = a.run()
        f = r["factor_of_safety"]
        self.assertTrue(f["found"])
        self.assertAlmostEqual(f["value"], 0.6304, delta=0.01 * 0.6304)
        self.assertEqual(f["value"], f["converged"])
        self.assertGreater(f["not_converged"], f["converged"])
        self.assertEqual(f["trials"], len(f["table"]))
        self.assertEqual(f["non_associated_flow"], "associated")  # the rock is elastic
        self.assertEqual(f["table"][0]["factor"], 1.0)
        self.assertFalse(f["table"][0]["stands"])
        self.assertEqual(r["status"], "completed")


class ModelTest(unittest.TestCase):
    def test_version(self):
        self.assertRegex(mcdda.__version__, r"^\d+\.\d+\.\d+$")

    def test_dict_model_meshes_into_arrays(self):
        a = mcdda.Analysis.from_dict(square_block())
        self.assertEqual([d for d in a.mesh() if d["severity"] == "error"], [])
        self.assertTrue(a.ok)
        m = a.mesh_arrays()
        self.assertEqual(m["nodes"].shape[1], 2)
        self.assertEqual(m["triangles"].shape[1], 3)
        self.assertEqual(m["triangles"].dtype, np.int32)
        self.assertAlmostEqual(float(m["area"].sum()), 100.0, places=9)
        self.assertTrue((m["area"] > 0).all())
        self.assertLess(int(m["triangles"].max()), m["nodes"].shape[0])

    def test_crack_faces_are_listed_with_their_joint(self):
        a = mcdda.Analysis.from_file(os.path.join(EXAMPLES, "griffith-crack.json"))
        m = a.mesh_arrays()
        faces = m["crack_faces"]
        self.assertEqual(faces.shape[1], 2)
        self.assertEqual(faces.shape[0], m["crack_face_joint"].shape[0])
        self.assertTrue((m["crack_face_joint"] == 0).all())
        ends = m["nodes"][faces]
        # Both faces of the 2 m crack along y = 0, from x = -1 to 1.
        self.assertTrue(np.allclose(ends[:, :, 1], 0.0))
        length = np.hypot(*(ends[:, 1, :] - ends[:, 0, :]).T).sum()
        self.assertAlmostEqual(float(length), 4.0, places=9)
        # Each face runs one way (its side of the block on its left) and has its own nodes: the
        # two faces share only the tips.
        forward = ends[:, 1, 0] > ends[:, 0, 0]
        one, other = set(faces[forward].ravel()), set(faces[~forward].ravel())
        self.assertGreater(len(one), 40)
        shared = one & other
        self.assertEqual(len(shared), 2)
        self.assertTrue(np.allclose(sorted(abs(m["nodes"][list(shared), 0])), [1.0, 1.0]))

    def test_overrides_by_dict_and_by_list(self):
        a = mcdda.Analysis.from_file(INCLINE)
        a.set({"/materials/0/young_modulus": 2e9, "/analysis/steps": 7})
        a.set(["/joint_materials/0/friction_angle=33"])
        model = a.to_dict()
        self.assertEqual(model["materials"][0]["young_modulus"], 2e9)
        self.assertEqual(model["analysis"]["steps"], 7)
        self.assertEqual(model["joint_materials"][0]["friction_angle"], 33)

    def test_bad_input_names_the_place(self):
        with self.assertRaises(mcdda.ModelError) as caught:
            mcdda.Analysis.from_dict({"format": "mcdda-model", "version": 1, "materials": []})
        self.assertIn("/materials", str(caught.exception))
        a = mcdda.Analysis.from_dict(square_block())
        with self.assertRaises(mcdda.ModelError):
            a.set({"/materials/0/cohesion": "strong"})
        self.assertEqual(a.to_dict()["materials"][0]["cohesion"], 1e6)  # unchanged
        a.set({"/materials/0/poisson_ratio": 0.5})
        errors = [d for d in a.check() if d["severity"] == "error"]
        self.assertTrue(any(d["path"] == "/materials/0/poisson_ratio" for d in errors), errors)
        self.assertFalse(a.ok)
        with self.assertRaises(mcdda.ModelError):
            a.run()
        with self.assertRaises(mcdda.ModelError):
            mcdda.Analysis.from_file("/nonexistent/model.json")


class RunTest(unittest.TestCase):
    def test_run_gives_history_and_fields(self):
        a = mcdda.Analysis.from_file(INCLINE, STATIC + ["/analysis/steps=4", "/analysis/output_every=2"])
        heard = []
        r = a.run(progress=lambda p: heard.append(p["step"]))
        self.assertEqual(r["status"], "completed", r["message"])
        self.assertEqual(r["exit_code"], 0)
        self.assertEqual(heard, [1, 2, 3, 4])
        np.testing.assert_array_equal(r["history"]["step"], [1, 2, 3, 4])
        self.assertEqual([f["step"] for f in r["fields"]], [2, 4])
        m = a.mesh_arrays()
        last = r["fields"][-1]
        self.assertEqual(last["displacement"].shape, m["nodes"].shape)
        self.assertEqual(last["stress"].shape, (m["triangles"].shape[0], 4))
        largest = np.hypot(last["displacement"][:, 0], last["displacement"][:, 1]).max()
        self.assertAlmostEqual(largest, r["history"]["max_displacement"][-1], places=15)

    def test_ground_water_gives_pore_pressure_and_effective_stress(self):
        # The square under a lake 2 m deep, saturated 25 kN/m³, against the dry square weighing
        # γ′ = 25 − 9.81 kN/m³: the same effective stresses; the pore pressure is γw × depth.
        wet = square_block()
        wet["materials"][0]["saturated_unit_weight"] = 25e3
        wet["water"] = {"piezometric_line": [[0, 12], [10, 12]]}
        wet["gravity"] = [0, -9.81]
        wet["analysis"]["geometry"] = "initial"  # pore pressures on the undeformed mesh, as compared below
        dry = square_block()
        dry["analysis"]["geometry"] = "initial"
        dry["materials"][0]["unit_weight"] = 25e3 - 9810
        dry["gravity"] = [0, -9.81]
        a = mcdda.Analysis.from_dict(wet)
        r = a.run()
        self.assertEqual(r["status"], "completed", r["message"])
        d = mcdda.Analysis.from_dict(dry).run()
        w, f = r["fields"][-1], d["fields"][-1]
        m = a.mesh_arrays()
        centroid_y = m["nodes"][m["triangles"][:, :3], 1].mean(axis=1)
        np.testing.assert_allclose(w["pore_pressure"], 9810 * (12 - centroid_y), rtol=1e-9)
        scale = np.abs(f["effective_stress"]).max()
        np.testing.assert_allclose(w["effective_stress"], f["effective_stress"], atol=1e-6 * scale)
        np.testing.assert_array_equal(f["effective_stress"], f["stress"])  # dry: the same
        total = w["effective_stress"].copy()
        total[:, :3] -= w["pore_pressure"][:, None]
        np.testing.assert_allclose(w["stress"], total, atol=1e-9 * scale)
        self.assertEqual(w["pore_pressure"].shape, (m["triangles"].shape[0],))
        self.assertFalse(f["pore_pressure"].any())

    def test_progress_returning_false_stops(self):
        a = mcdda.Analysis.from_file(INCLINE, ["/analysis/steps=50"])
        r = a.run(progress=lambda p: p["step"] < 2)
        self.assertEqual(r["status"], "cancelled")
        self.assertEqual(r["exit_code"], 130)
        self.assertEqual(r["steps"], 2)

    def test_error_in_progress_is_raised_after_the_step(self):
        a = mcdda.Analysis.from_file(INCLINE, ["/analysis/steps=50"])

        def failing(p):
            raise RuntimeError("stop at %d" % p["step"])
        with self.assertRaisesRegex(RuntimeError, "stop at 1"):
            a.run(progress=failing)

    def test_gil_released_while_solving(self):
        a = mcdda.Analysis.from_file(INCLINE, ["/analysis/steps=30"])
        ticks = []
        running = threading.Event()
        done = threading.Event()

        def tick():
            running.wait()
            while not done.is_set():
                ticks.append(1)
                time.sleep(0.001)
        thread = threading.Thread(target=tick)
        thread.start()
        marks = []  # ticks counted when each callback begins and ends

        def progress(p):
            running.set()
            marks.append(len(ticks))
            marks.append(len(ticks))
        a.run(progress=progress)
        done.set()
        thread.join()
        # The other thread ticked while the solver computed the steps (between one callback's end
        # and the next one's beginning): the solver does not hold the GIL.
        # (Without the release a tick may still slip in at each callback: one per step at most.)
        steps = len(marks) // 2
        while_solving = sum(marks[k + 1] - marks[k] for k in range(1, len(marks) - 1, 2))
        self.assertGreater(while_solving, 3 * steps, marks)

    def test_files_written_when_asked(self):
        import tempfile
        with tempfile.TemporaryDirectory() as folder:
            a = mcdda.Analysis.from_dict(square_block())
            r = a.run(output_folder=folder, name="square")
            self.assertEqual(r["status"], "completed", r["message"])
            for name in ("square.pvd", "history.csv", "summary.json"):
                self.assertTrue(os.path.exists(os.path.join(folder, name)), name)

    def test_parameter_study(self):
        """The study of docs/python.md: joint friction against the 40° incline."""
        statuses = {}
        for phi in (30, 45):
            a = mcdda.Analysis.from_file(INCLINE, STATIC + ["/analysis/steps=10"])
            a.set({"/joint_materials/0/friction_angle": phi})
            statuses[phi] = a.run()["status"]
        self.assertEqual(statuses[45], "completed")
        self.assertNotEqual(statuses[30], "completed")

    def test_shaking_histories_and_permanent_displacement(self):
        """Newmark's sliding block: the point's motion, the base's record, what the shaking left."""
        a = mcdda.Analysis.from_file(os.path.join(EXAMPLES, "newmark-sliding-block.json"), ["/analysis/steps=600"])
        r = a.run()
        self.assertEqual(r["status"], "completed", r["message"])
        h = r["history"]
        for key in ("ux", "uy", "vx", "vy", "ax", "ay"):
            self.assertEqual(len(h["block:" + key]), 600, key)
            self.assertEqual(len(h["base:" + key]), 600, key)
        # The base follows the record: 0.3 g at its peaks.
        self.assertAlmostEqual(max(h["base:ax"]), 0.3 * 9.81, delta=0.01)
        # The block slides down the joint (towards -x) and ends where the summary says.
        self.assertLess(h["block:ux"][-1], -0.01)
        largest = r["permanent_displacement"]["largest"]
        ux, uy = r["permanent_displacement"]["points"]["block"]
        self.assertGreaterEqual(largest, (ux * ux + uy * uy) ** 0.5 - 1e-12)
        self.assertAlmostEqual(ux, h["block:ux"][-1], delta=1e-9)


if __name__ == "__main__":
    unittest.main()
