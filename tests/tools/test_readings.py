#!/usr/bin/python3
"""tools/reproduction/readings.py on synthetic studies (no simulation): a reading closer to the
published values on every table is chosen in every fold and adopted; one that wins only on the
table it is chosen on is not; the baseline stays when the folds disagree; the spread labels a row
whose verdict changes with the reading; the sample spacing rule keeps the default only when every
row moves by less than a fifth of its combined error."""
import sys
import unittest

sys.dont_write_bytecode = True
from tools.reproduction import readings  # noqa: E402

TABLES = ("pat0", "pat1", "pat2")


def published(n_per_table=4):
    return {f"{t}_r{k:02d}": {"mu_s": "0.600", "mu_s_err": "0.005"} for t in TABLES for k in range(n_per_table)}


def study(pub, offsets, spacing="1e-2ms", admissible=None):
    """offsets: rule -> row_id -> ours minus published (sem 0.005, n 20)."""
    scenes = []
    for rule, by_row in offsets.items():
        for rid in pub:
            scenes.append({"x": {"rule": rule, "row_id": rid, "sample_dt": spacing,
                                 "admissible": True if admissible is None else rule in admissible},
                           "result": {"mu_s": {"mean": 0.6 + by_row(rid), "sem": 0.005, "n": 20}}})
    return {"scenes": scenes}


class Choice(unittest.TestCase):
    def judge(self, offsets, **kw):
        pub = published()
        return readings.Readings(study(pub, offsets, **kw), pub)

    def test_a_reading_better_everywhere_is_adopted(self):
        rd = self.judge({"all_slipped": lambda r: 0.02, "slid_or_drop_0.1": lambda r: 0.002})
        a = readings.adoption(readings.cross_validate(rd))
        self.assertEqual(a["adopted"], "slid_or_drop_0.1")
        self.assertEqual(a["votes"], 3)

    def test_a_reading_that_wins_only_where_it_is_chosen_is_not(self):
        # Better than the baseline on pat0 only, far worse on the others: folds trained with pat0
        # in them may choose it, but it loses on the held-out table.
        off = {"all_slipped": lambda r: 0.01,
               "slid_or_event_0.5": lambda r: 0.0 if r.startswith("pat0") else (0.05 if r.startswith("pat1") else 0.011)}
        rd = self.judge(off)
        a = readings.adoption(readings.cross_validate(rd))
        self.assertEqual(a["adopted"], "all_slipped")

    def test_an_inadmissible_reading_is_never_chosen(self):
        rd = self.judge({"all_slipped": lambda r: 0.02, "drop_0.02": lambda r: 0.0}, admissible={"all_slipped"})
        self.assertEqual(rd.admissible, ["all_slipped"])
        self.assertEqual(readings.adoption(readings.cross_validate(rd))["adopted"], "all_slipped")

    def test_spread_labels_a_row_whose_verdict_depends_on_the_reading(self):
        off = {"all_slipped": lambda r: 0.05 if r == "pat1_r00" else 0.0, "slid_or_drop_0.1": lambda r: 0.0}
        rd = self.judge(off)
        spread = {s["row_id"]: s for s in readings.row_spread(rd, "all_slipped")}
        self.assertFalse(spread["pat1_r00"]["robust"])
        self.assertAlmostEqual(spread["pat1_r00"]["high"] - spread["pat1_r00"]["low"], 0.05)
        self.assertTrue(spread["pat0_r00"]["robust"])


class Spacing(unittest.TestCase):
    def effect(self, shift):
        pub = published()
        doc = study(pub, {"all_slipped": lambda r: 0.0})
        doc["scenes"] += study(pub, {"all_slipped": lambda r: shift if r == "pat2_r03" else 0.0},
                               spacing="1e-3ms")["scenes"]
        return readings.spacing_effect(readings.Readings(doc, pub), "all_slipped")

    def test_small_shifts_keep_the_default(self):
        # combined error hypot(0.005, 0.005) = 0.00707; 0.2 of it is 0.00141
        self.assertTrue(self.effect(0.0013)["default_stays"])

    def test_one_row_moving_too_far_changes_it(self):
        e = self.effect(0.0015)
        self.assertFalse(e["default_stays"])
        self.assertEqual(e["worst"]["row_id"], "pat2_r03")
        self.assertEqual(e["default"], readings.FINE_SPACING)


if __name__ == "__main__":
    unittest.main()
