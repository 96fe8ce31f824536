#!/usr/bin/python3
"""tools/first_slip_cost.py on synthetic first_slip_scaling documents (nothing is run): the growth
exponents and the least-squares slope must follow from the numbers given, each goal's verdict must
turn when its number crosses the threshold, a missing point must leave its goals 'not judged' with
the reason, --write must replace only the block, and a malformed file must exit 2 without touching
the page."""
import copy
import json
import math
import os
import sys
import tempfile
import unittest

sys.dont_write_bytecode = True
from tools import first_slip_cost as fc  # noqa: E402

MACHINE = {"cores": 2, "date": "2026-01-01 00:00 UTC", "commit": "abc1234", "dirty": False}
SIZES = [10000, 30000, 100000]


def read(path):
    with open(path) as f:
        return f.read()


def rows(surface, cpu_at_1e4=0.5, power=1.1, switch_power=1.05, mb_per_block=0.001, mb_quadratic=0.0):
    """A surface's rows with CPU time c (N/1e4)^power and memory 13 MB + a N + b N^2."""
    return [{"surface": surface, "N": n, "length_cm": n * 0.02, "cpu_s": cpu_at_1e4 * (n / 1e4) ** power,
             "wall_s": 1.0, "peak_rss_mb": 13.0 + mb_per_block * n + mb_quadratic * n * n,
             "switch_instants": round(1e5 * (n / 1e4) ** switch_power), "slip_starts": n, "samples": 100,
             "mu_s": 0.6, "t_peak_s": 0.3} for n in SIZES]


def document(*surface_rows):
    all_rows = [r for rs in surface_rows for r in rs]
    return {"machine": MACHINE, "load_start": [1.0, 1.0, 1.0], "load_end": [1.2, 1.0, 1.0],
            "command": ["springblock", "run", "--N", "{N}"], "block_cm": 0.02, "reps_per_point": 1,
            "build": {"version": "0.1.0", "commit": "abc123456789-dirty"},
            "surfaces": list(dict.fromkeys(r["surface"] for r in all_rows)), "sizes": SIZES, "rows": all_rows}


class Growth(unittest.TestCase):
    def test_exponents(self):
        rs = rows("smooth", power=1.3, switch_power=1.1)
        self.assertAlmostEqual(fc.exponent(rs[0], rs[-1], "cpu_s"), 1.3)
        k, se = fc.slope(rs, "cpu_s")
        self.assertAlmostEqual(k, 1.3)
        self.assertAlmostEqual(se, 0.0)
        self.assertAlmostEqual(fc.per_block(rs[0], rs[-1]), 0.001 * 1048576)

    def test_slope_and_its_error_by_hand(self):
        # ln N = 0, 1, 2 (N = 1, e, e^2) and ln y = 0, 2, 3: slope 1.5, residuals -1/6, 1/3, -1/6.
        rs = [{"N": math.exp(x), "cpu_s": math.exp(y)} for x, y in ((0, 0), (1, 2), (2, 3))]
        k, se = fc.slope(rs, "cpu_s")
        self.assertAlmostEqual(k, 1.5)
        self.assertAlmostEqual(se, math.sqrt((1 / 36 + 1 / 9 + 1 / 36) / 1 / 2))
        self.assertIsNone(fc.slope(rs[:2], "cpu_s")[1])  # two points: no residual, no error

    def test_events_and_their_price_add_up(self):
        text = fc.block(document(rows("smooth", power=1.3, switch_power=1.1)))
        self.assertIn("| smooth | 10,000 to 100,000 (3) | 1.300 | 1.300 ± 0.000 | 1.100 | +0.200 |", text)


class Verdicts(unittest.TestCase):
    def judged(self, **kw):
        return fc.verdicts(rows("s", **kw))

    def test_exponent_turns_at_its_goal(self):
        self.assertEqual(self.judged(power=1.149)["exponent"][0], "met")
        self.assertEqual(self.judged(power=1.151)["exponent"][0], "not met")

    def test_time_turns_at_its_goal(self):
        at_goal = 10.0 / 10 ** 1.1  # CPU at 1e5 is exactly 10 s (up to rounding)
        self.assertEqual(self.judged(cpu_at_1e4=at_goal * 0.999)["time"][0], "met")
        self.assertEqual(self.judged(cpu_at_1e4=at_goal * 1.001)["time"][0], "not met")

    def test_memory_turns_at_its_goal(self):
        # Increments per block: a + b (N1 + N2) over the first interval, a + b (N2 + N3) over the last.
        a = 0.001

        def ratio_for(b):
            return (a + b * 130000) / (a + b * 40000)
        b_at = a * 0.5 / (130000 - 1.5 * 40000)  # ratio exactly 1.5
        self.assertAlmostEqual(ratio_for(b_at), 1.5)
        self.assertEqual(self.judged(mb_quadratic=b_at * 0.99)["memory"][0], "met")
        self.assertEqual(self.judged(mb_quadratic=b_at * 1.01)["memory"][0], "not met")
        self.assertAlmostEqual(self.judged(mb_quadratic=b_at)["memory"][1], 1.5)
        self.assertEqual(self.judged()["memory"], ("met", 1.0))

    def test_block_counts_the_surfaces(self):
        text = fc.block(document(rows("fast"), rows("slow", power=1.2)))
        self.assertIn("| fast | **met** (1.100) |", text)
        self.assertIn("| slow | **not met** (1.200) |", text)
        self.assertIn("Of the 2 surfaces: the exponent met on 1, not met on 1;", text)


class Missing(unittest.TestCase):
    def test_missing_largest_n_is_not_judged(self):
        doc = document(rows("smooth"), rows("periodic:10,10"))
        doc["rows"] = [r for r in doc["rows"] if not (r["surface"] == "smooth" and r["N"] == 100000)]
        v = fc.verdicts(fc.by_surface(doc)["smooth"])
        self.assertEqual(v["exponent"], ("not judged: no run at N = 100,000", None))
        self.assertEqual(v["time"], ("not judged: no run at N = 100,000", None))
        self.assertTrue(v["memory"][0].startswith("not judged"))
        text = fc.block(doc)
        self.assertIn("No run for smooth at N = 100,000: the goals that need it are not judged.", text)
        self.assertIn("the exponent met on 1, not met on 0, not judged on 1", text)

    def test_two_sizes_judge_cost_not_memory(self):
        rs = [r for r in rows("s") if r["N"] != 30000]
        v = fc.verdicts(rs)
        self.assertEqual(v["exponent"][0], "met")
        self.assertEqual(v["memory"][0], "not judged: needs N = 10,000, 100,000 and a size between")

    def test_duplicate_or_no_rows_refused(self):
        doc = document(rows("s"))
        doc["rows"].append(dict(doc["rows"][0]))
        with self.assertRaisesRegex(ValueError, "two rows for one N"):
            fc.block(doc)
        with self.assertRaisesRegex(ValueError, "no rows"):
            fc.block(dict(doc, rows=[]))


class Page(unittest.TestCase):
    def files(self, d, doc):
        source, page = os.path.join(d, "fs.json"), os.path.join(d, "page.md")
        with open(source, "w") as f:
            f.write(doc if isinstance(doc, str) else json.dumps(doc))
        with open(page, "w") as f:
            f.write(f"before\n{fc.BEGIN}\nold\n{fc.END}\nafter\n")
        return ["--from", source, "--page", page], page

    def test_write_replaces_the_block_only(self):
        with tempfile.TemporaryDirectory() as d:
            args, page = self.files(d, document(rows("smooth")))
            self.assertEqual(fc.main(args + ["--write"]), 0)
            text = read(page)
            self.assertTrue(text.startswith("before\n") and text.endswith("\nafter\n"))
            self.assertNotIn("\nold\n", text)
            self.assertIn("built from commit abc123456789 with local changes", text)

    def test_bad_input_exits_2_and_leaves_the_page(self):
        with tempfile.TemporaryDirectory() as d:
            broken = copy.deepcopy(document(rows("smooth")))
            del broken["rows"][0]["cpu_s"]
            for doc in (broken, "{not json", dict(document(rows("smooth")), rows=[])):
                args, page = self.files(d, doc)
                before = read(page)
                self.assertEqual(fc.main(args + ["--write"]), 2)
                self.assertEqual(read(page), before)


if __name__ == "__main__":
    unittest.main()
