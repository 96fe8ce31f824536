#!/usr/bin/python3
"""tools/sweep_cost.py on synthetic benchmark documents (no sweep is run): the per-unit costs and
the 10^6-unit model must follow from the numbers given, each goal's verdict must turn when its
number crosses it, --write must replace only the block between the markers, and a missing or
malformed file must exit 2 without touching the page."""
import copy
import json
import os
import sys
import tempfile
import unittest

sys.dont_write_bytecode = True
from tools import sweep_cost as sc  # noqa: E402

MACHINE = {"cores": 2, "date": "2026-01-01 00:00 UTC", "commit": "abc1234", "dirty": False}
MEMORY = {"machine": MACHINE, "load_start": [1.0, 1.0, 1.0], "load_end": [1.5, 1.0, 1.0], "threads": 2,
          "rows": [{"units": 100000, "peak_rss_mb": 12.0, "wall_s": 9.0},
                   {"units": 1000000, "peak_rss_mb": 30.0, "wall_s": 90.0}]}
SCALING = {"machine": MACHINE, "load_start": [2.0, 2.0, 2.0], "load_end": [2.0, 2.0, 2.0],
           "sweep": "examples/sweep_scaling.toml",
           "pairs": [{"one_rank_s": 8.0, "two_ranks_s": 4.0}, {"one_rank_s": 9.0, "two_ranks_s": 5.0}],
           "unit_wall_s": [0.01, 0.02, 0.03, 0.1],
           "tiny": [{"batch_ms": 50, "units": 20000, "computed_units": 20000, "wall_s": 0.5, "messages": 20,
                     "message_s": 0.03, "checkpoint_s": 0.05, "units_by_rank_1": 10000, "record_bytes": 500.0,
                     "results_bytes_per_unit": 550.0},
                    {"batch_ms": 0, "units": 20000, "computed_units": 20000, "wall_s": 0.6, "messages": 6000,
                     "message_s": 0.018, "checkpoint_s": 0.05, "units_by_rank_1": 6000, "record_bytes": 500.0,
                     "results_bytes_per_unit": 550.0}]}


class PerUnit(unittest.TestCase):
    def test_rank0_costs(self):
        c = sc.rank0(SCALING["tiny"][0])
        self.assertAlmostEqual(c["message_us"], 3.0)          # 0.03 s over rank 1's 10,000 units
        self.assertAlmostEqual(c["checkpoint_us"], 2.5)       # 0.05 s over 20,000 units
        self.assertAlmostEqual(c["total_us"], 4.0)            # 0.08 s over 20,000 units
        self.assertAlmostEqual(c["per_message_us"], 1500.0)   # 20 messages

    def test_model(self):
        m = sc.model(MEMORY, SCALING)
        self.assertAlmostEqual(m["c_s"], 4e-6)
        self.assertAlmostEqual(m["mean_unit_s"], 0.04)
        self.assertAlmostEqual(m["saturation_unit_s"], 1000 * 4e-6)
        self.assertAlmostEqual(m["busy_at_mean"], 4e-3 / 0.04)
        self.assertAlmostEqual(m["per_rank_s"], 1e6 * 0.04 / 1000)
        self.assertAlmostEqual(m["output_bytes"], 550e6)
        self.assertAlmostEqual(m["memory_mb"], 30.0)  # the largest measured sweep is the model's size
        self.assertAlmostEqual(sc.growth_per_unit(MEMORY["rows"]), 18 * 1048576 / 900000)


class Verdicts(unittest.TestCase):
    def test_goals_turn(self):
        text = sc.block(MEMORY, SCALING)
        self.assertIn("(goal: under 50 MB): **met**", text)
        self.assertIn("(goal: at most 7 µs): **met**", text)
        heavy, slow = copy.deepcopy(MEMORY), copy.deepcopy(SCALING)
        heavy["rows"][1]["peak_rss_mb"] = 62.5
        slow["tiny"][0]["checkpoint_s"] = 0.12  # (0.03 + 0.12) / 20000 = 7.5 us
        text = sc.block(heavy, slow)
        self.assertIn("(goal: under 50 MB): **not met**", text)
        self.assertIn("(goal: at most 7 µs): **not met**", text)


class Page(unittest.TestCase):
    def files(self, d, memory=MEMORY, scaling=SCALING):
        paths = [os.path.join(d, n) for n in ("m.json", "s.json", "page.md")]
        for p, doc in zip(paths, (memory, scaling)):
            with open(p, "w") as f:
                f.write(doc if isinstance(doc, str) else json.dumps(doc))
        with open(paths[2], "w") as f:
            f.write(f"before\n{sc.BEGIN}\nold\n{sc.END}\nafter\n")
        return ["--memory", paths[0], "--scaling", paths[1], "--page", paths[2]], paths[2]

    def test_write_replaces_the_block_only(self):
        with tempfile.TemporaryDirectory() as d:
            args, page = self.files(d)
            self.assertEqual(sc.main(args + ["--write"]), 0)
            text = open(page).read()
            self.assertTrue(text.startswith("before\n") and text.endswith("\nafter\n"))
            self.assertNotIn("\nold\n", text)
            self.assertIn("| 1 | 8.00 s | 4.00 s | 2.00 |", text)

    def test_bad_input_exits_2_and_leaves_the_page(self):
        with tempfile.TemporaryDirectory() as d:
            broken = copy.deepcopy(SCALING)
            del broken["tiny"]
            for memory, scaling in ((MEMORY, broken), ("{not json", SCALING)):
                args, page = self.files(d, memory, scaling)
                before = open(page).read()
                self.assertEqual(sc.main(args + ["--write"]), 2)
                self.assertEqual(open(page).read(), before)


if __name__ == "__main__":
    unittest.main()
