#!/usr/bin/python3
"""tools/cost_model.py's fit, verdict and rendering on synthetic repetitions (no simulation, a
second): times made exactly from known costs must give those costs back, a scene off by more than
the factor must count as a miss, --from must render the document it is given, and bad input must
exit 2 naming the field."""
import json
import os
import subprocess
import sys
import tempfile
import unittest

sys.dont_write_bytecode = True
from tools import cost_model as cm  # noqa: E402

# Seconds per unit, the costs the synthetic times are made of.
TRUE = {"slip_events": 80e-6, "slip_starts": 6e-6, "samples": 1.5e-6}


def rep(events, starts, samples, slow=1.0):
    work = {"slip_events": events, "slip_starts": starts, "samples": samples, "block_steps": 50 * starts,
            "stretch_samples": 1000, "stepping_s": 0.0, "event_location_s": 0.0, "switching_s": 0.0,
            "quiet_s": 0.0, "sampling_s": 0.0}
    wall = slow * sum(c * work[t] for t, c in TRUE.items())
    work.update(stepping_s=0.25 * wall, event_location_s=0.15 * wall, switching_s=0.3 * wall,
                quiet_s=0.1 * wall, sampling_s=0.1 * wall)
    return {"wall_s": wall, "work": work}


def scene(name, kind, counts, slow=1.0):
    return {"name": name, "set": kind, "args": [], "reps": [rep(*c, slow=slow) for c in counts]}


def synthetic(slow_validation=(1.0,) * 6):
    """Calibration scenes whose counts vary independently; six validation scenes, each slowed down
    by the given factor against the true costs."""
    calib = [scene(f"c{i}", "calibration", [(e, s, m), (e + 10, s + 300, m + 500)])
             for i, (e, s, m) in enumerate([(100, 5000, 1000), (800, 4000, 50000), (300, 20000, 10000),
                                            (1500, 8000, 100000), (200, 12000, 2000)])]
    valid = [scene(f"v{i}", "validation", [(400 + 50 * i, 9000, 30000 + 1000 * i)] * 3, slow)
             for i, slow in enumerate(slow_validation)]
    return calib + valid


def document(scenes):
    doc = {"tool": "tools/cost_model.py", "reps": 3, "seed": 5,
           "machine": {"cores": 2, "date": "2026-01-01 00:00 UTC", "commit": "abc1234", "dirty": False}}
    doc.update(cm.analyze(scenes))
    return doc


class Fit(unittest.TestCase):
    def test_exact_times_give_the_costs_back(self):
        doc = document(synthetic())
        self.assertEqual(doc["fit"]["form"], "headline")
        for t, c in TRUE.items():
            self.assertAlmostEqual(doc["fit"]["coefficients_us"][t], 1e6 * c, places=6)
        self.assertEqual(doc["verdict"], {"within": 6, "of": 6, "needed": 5, "factor": 2.0, "met": True})

    def test_factor_boundary_and_verdict(self):
        # 2.0 is within (inclusive), 2.01 and 1/2.01 are not: 4 of 6 within, fewer than 5, not met.
        doc = document(synthetic((1.0, 2.0, 2.01, 1 / 2.01, 0.5, 1.0)))
        within = {s["name"]: s["within"] for s in doc["scenes"] if s["set"] == "validation"}
        self.assertEqual(within, {"v0": True, "v1": True, "v2": False, "v3": False, "v4": True, "v5": True})
        self.assertFalse(doc["verdict"]["met"])

    def test_floor_and_breakdown(self):
        s = document(synthetic())["scenes"][0]
        self.assertAlmostEqual(s["over_floor"], 4.0)
        self.assertAlmostEqual(s["breakdown_pct"]["other_s"], 10.0)

    def test_no_validation_scene_is_bad_input(self):
        with self.assertRaises(cm.BadInput):
            cm.analyze([s for s in synthetic() if s["set"] == "calibration"])


class Render(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.json = os.path.join(self.dir.name, "cost_model.json")
        with open(self.json, "w") as f:
            json.dump(document(synthetic()), f)

    def tearDown(self):
        self.dir.cleanup()

    def tool(self, *args):
        # The tool as its callers run it, with this test's environment (PYTHONPATH: the root).
        return subprocess.run([sys.executable, "-m", "tools.cost_model", *args], capture_output=True, text=True,
                              env=dict(os.environ, PYTHONDONTWRITEBYTECODE="1"))

    def test_from_prints_the_block_and_writes_the_page(self):
        page = os.path.join(self.dir.name, "cost.md")
        with open(page, "w") as f:
            f.write(f"## Cost\n\nprose\n\n{cm.BEGIN}\nold\n{cm.END}\n\nafter\n")
        p = self.tool("--from", self.json, "--print", "--page", page, "--write")
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertIn("| v3 | validation |", p.stdout)
        self.assertIn("6 of 6 scenes within a factor of 2", p.stdout)
        with open(page) as f:
            text = f.read()
        self.assertNotIn("\nold\n", text)
        self.assertTrue(text.startswith("## Cost\n\nprose\n\n") and text.endswith(f"{cm.END}\n\nafter\n"))
        self.assertIn(p.stdout.strip(), text)

    def test_bad_input_exits_2_naming_the_field(self):
        for args, field in ((["--from", self.json, "--reps", "0"], "--reps"),
                            (["--springblock", os.path.join(self.dir.name, "nothing")], "--springblock"),
                            (["--from", os.path.join(self.dir.name, "missing.json")], "--from"),
                            (["--from", self.json, "--page", self.json, "--write"], "--page")):
            p = self.tool(*args)
            self.assertEqual(p.returncode, 2, args)
            self.assertIn(field, p.stderr, args)
        broken = os.path.join(self.dir.name, "broken.json")
        with open(broken, "w") as f:
            json.dump({"machine": {}, "reps": 1, "scenes": []}, f)
        p = self.tool("--from", broken)
        self.assertEqual((p.returncode, "'fit'" in p.stderr), (2, True), p.stderr)


if __name__ == "__main__":
    unittest.main()
