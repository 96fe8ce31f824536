#!/usr/bin/python3
"""summary.json is written and read in one place (tools/summary_schema.py): a summary built from a
synthetic results directory survives write and load; a missing key, a wrong vocabulary or a count
that does not match its records is refused with a message naming it; and the readers (report,
tables, README check) stop with that message instead of printing a placeholder."""
import copy
import json
import math
import os
import subprocess
import sys
import tempfile
import unittest

sys.dont_write_bytecode = True
from tools import summary_schema as schema  # noqa: E402
from tools.reproduction import evaluate  # noqa: E402
from tools.reproduction.inputs import read_tsv  # noqa: E402

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

TABLES = os.path.join(REPO, "tables")
PY = sys.executable
TIER_REPS = {"paper": 20, "quick": 6, "smoke": 2}


def synthetic_results(root):
    """tab_pat0 only, every row at its published value with a small standard error."""
    scenes = []
    for r in read_tsv(os.path.join(TABLES, "published_tab_pat0.tsv")):
        res = {c: {"mean": float(r[c]), "sem": 0.002, "std": 0.002 * math.sqrt(20), "n": 20} for c in ("mu_s", "mu_d")}
        res["contact_fraction"] = int(r["S_over_Stot_num"]) / int(r["S_over_Stot_den"])
        scenes.append({"id": r["row_id"], "result": res})
    os.makedirs(os.path.join(root, "tab_pat0"))
    with open(os.path.join(root, "tab_pat0", "tab_pat0.json"), "w") as f:
        json.dump({"tier": "paper", "tier_reps": TIER_REPS, "scenes": scenes}, f)


class Schema(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.data = os.path.join(cls.tmp.name, "data")
        synthetic_results(cls.data)
        # A known-deviations list of our own, so the stale detection is tested whatever the live
        # list says: two tab_pat0 rows and a claim they carry, all listed as deviating.
        known = os.path.join(cls.tmp.name, "known.tsv")
        with open(known, "w") as f:
            f.write("row_id\tcoef\ttiers\treason\npat0_r03\tmu_s\tpaper\tsynthetic\n"
                    "pat0_r16\tmu_s\tpaper\tsynthetic\nC14\tclaim\tpaper\tsynthetic\n")
        cls.summary = evaluate.summarize(evaluate.Inputs(cls.data, TABLES, known_path=known))
        schema.write(os.path.join(cls.data, "summary.json"), cls.summary)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def broken(self, change):
        s = copy.deepcopy(self.summary)
        change(s)
        path = os.path.join(self.tmp.name, "broken.json")
        with open(path, "w") as f:
            json.dump(s, f)
        return path

    def test_round_trip_and_counts(self):
        s = schema.load(os.path.join(self.data, "summary.json"))
        self.assertEqual(s, json.loads(json.dumps(self.summary)))
        self.assertEqual(s["tier"], "paper")
        rows = s["counts"]["rows"]
        # Every tab_pat0 number at its published value: it agrees unless the published error alone is
        # too wide to certify it; tab_pat1 and tab_pat2 were not produced.
        wide = sum(r["equivalence"] >= r["delta"] for r in s["rows"] if r["target"] == "tab_pat0")
        self.assertEqual((rows["agree"], rows["not_resolved"], rows["missing"]), (78 - wide, wide, 64))
        self.assertEqual(rows["disagree_known"] + rows["disagree_new"], 0)
        # The rows listed as known deviations at the paper tier agree here, and C14, which they
        # carry, holds: all stale, said loudly.
        self.assertEqual(s["stale"], ["pat0_r03 mu_s", "pat0_r16 mu_s", "C14 claim"])
        self.assertEqual(sum(s["counts"]["claims"].values()), 35)   # every claim, judged or missing
        self.assertEqual(schema.target_counts(s, "tab_pat0")["rows"]["agree"], 78 - wide)
        self.assertEqual(s["resolution"]["paper"]["reps"], 20)
        with self.assertRaises(schema.SummaryError):
            schema.target_counts(s, "fig9")

    def assert_refused(self, change, *words):
        with self.assertRaises(schema.SummaryError) as cm:
            schema.load(self.broken(change))
        for w in words:
            self.assertIn(w, str(cm.exception))

    def test_missing_keys_are_named(self):
        self.assert_refused(lambda s: s.pop("counts"), "'counts'")
        self.assert_refused(lambda s: s["rows"][5].pop("verdict"), "rows[5]", "'verdict'")
        self.assert_refused(lambda s: s["claims"][3].pop("lines"), "claims[3]", "'lines'")
        self.assert_refused(lambda s: s["thresholds"]["delta"].pop("mu_d"), "delta", "'mu_d'")
        self.assert_refused(lambda s: s["z_distribution"].pop("sd"), "z_distribution", "'sd'")

    def test_inconsistent_or_unknown_values_are_refused(self):
        self.assert_refused(lambda s: s["counts"]["rows"].update(agree=77), "counts")
        self.assert_refused(lambda s: s["rows"][0].update(verdict="disagree"), "verdict")
        self.assert_refused(lambda s: s["rows"][0].update(z=None), "rows[0]", ".z")
        self.assert_refused(lambda s: s.update(schema_version=1), "schema_version")
        self.assert_refused(lambda s: s.update(tier="fast"), "tier")

    def test_missing_file_is_a_clear_error(self):
        with self.assertRaises(schema.SummaryError) as cm:
            schema.load(os.path.join(self.tmp.name, "nowhere", "summary.json"))
        self.assertIn("check_reproduction.py --summary", str(cm.exception))

    def test_readers_stop_on_a_broken_summary(self):
        bad = os.path.join(self.tmp.name, "bad")
        os.makedirs(bad)
        with open(os.path.join(bad, "summary.json"), "w") as f:
            json.dump({k: v for k, v in self.summary.items() if k != "claims"}, f)
        out = os.path.join(self.tmp.name, "out")
        env = dict(os.environ, PYTHONDONTWRITEBYTECODE="1")
        for cmd in ([PY, "-m", "paper.build_report", "--data", bad, "--figures", out, "--out", out],
                    [PY, "-m", "tables.render_tables", "--data", bad, "--out", out],
                    [PY, "-m", "tools.readme_results", "--check",
                     "--summary", os.path.join(bad, "summary.json")]):
            p = subprocess.run(cmd, capture_output=True, text=True, env=env)
            self.assertNotEqual(p.returncode, 0, cmd)
            self.assertIn("'claims'", p.stdout + p.stderr, cmd)
            self.assertFalse(os.path.exists(os.path.join(out, "report.md")))

    def test_readme_check_skips_other_tiers(self):
        path = os.path.join(self.tmp.name, "quick.json")
        s = copy.deepcopy(self.summary)
        s["tier"] = "quick"
        schema.write(path, s)
        p = subprocess.run([PY, "-m", "tools.readme_results", "--check", "--summary", path],
                           capture_output=True, text=True, env=dict(os.environ, PYTHONDONTWRITEBYTECODE="1"))
        self.assertEqual(p.returncode, 77, p.stdout + p.stderr)


if __name__ == "__main__":
    unittest.main()
