#!/usr/bin/python3
"""tools/design_cost.py on a synthetic design_query.json (no query is run): the block must carry
what the query printed verbatim, the stage times and the recheck's distances computed from the
numbers given, and a malformed file must exit 2 without touching the page."""
import json
import os
import sys
import tempfile
import unittest

sys.dont_write_bytecode = True
from tools import design_cost as dc  # noqa: E402

DOC = {"machine": {"cores": 2, "date": "2026-01-01 00:00 UTC", "commit": "abc1234", "dirty": False},
       "load_start": [1.0, 1, 1], "load_end": [2.0, 1, 1], "threads": 2,
       "command": ["springblock", "design", "--N", "360", "--out", "design.json"],
       "printed": "design: periodic family\n1   periodic:5,15  0.6492\n", "cpu_s": 80.0, "wall_s": 41.5,
       "classes_cpu_s": 0.0, "rungs": [{"candidates": 3600, "cpu_s": 60.0}, {"candidates": 900, "cpu_s": 10.0}],
       "answers": [{"pattern": "periodic:5,15", "mu_s": 0.6492, "reps": 80}],
       "recheck": {"pattern": "periodic:5,15", "reps": 20, "seed": 2026, "mu_s": 0.6454, "mu_s_sem": 0.003,
                   "target": {"mu_s": {"lo": 0.65, "hi": 0.65, "text": "0.65"}, "mu_d": None, "ratio": None},
                   "published": {"row": "pat0_r17", "mu_s": 0.649, "mu_s_err": 0.004}}}


class Block(unittest.TestCase):
    def test_numbers_follow_from_the_file(self):
        text = dc.block(DOC)
        self.assertIn("1   periodic:5,15  0.6492\n```", text)
        self.assertIn("41.5 s of wall time and 80.0 s of CPU time", text)
        self.assertIn("70.0 s in the 2 rungs", text)
        self.assertIn("the rest, 10.0 s, in the fresh verification", text)
        self.assertIn("-1.5 standard errors from the target 0.65", text)      # (0.6454 - 0.65) / 0.003
        self.assertIn("-0.7 combined standard errors away", text)            # -0.0036 / 0.005

    def test_no_published_value_and_an_interval_target(self):
        doc = json.loads(json.dumps(DOC))
        doc["recheck"]["published"] = None
        doc["recheck"]["target"]["mu_s"] = {"lo": 0.6, "hi": 0.7, "text": "0.6:0.7"}
        text = dc.block(doc)
        self.assertNotIn("the paper prints", text)
        self.assertNotIn("from the target", text)

    def test_bad_file_exits_2_and_leaves_the_page(self):
        with tempfile.TemporaryDirectory() as d:
            src, page = os.path.join(d, "q.json"), os.path.join(d, "p.md")
            with open(src, "w") as f:
                json.dump({k: v for k, v in DOC.items() if k != "recheck"}, f)
            with open(page, "w") as f:
                f.write(f"a\n{dc.BEGIN}\nold\n{dc.END}\nb\n")
            self.assertEqual(dc.main(["--from", src, "--page", page, "--write"]), 2)
            self.assertEqual(open(page).read(), f"a\n{dc.BEGIN}\nold\n{dc.END}\nb\n")


if __name__ == "__main__":
    unittest.main()
