#!/usr/bin/python3
"""The checker's verdict logic on synthetic numbers (no simulation, a second or two).

Boundaries are approached from both sides by a relative 1e-9, with the expected quantiles and
degrees of freedom recomputed here from their definitions, so a changed rule (a normal instead of
a Student-t quantile, no Sidak correction, a two-sided equivalence quantile, agreement allowed to
override a significant difference, a wrong exit code) fails a test rather than moving a number."""
import json
import math
import os
import sys
import tempfile
import unittest

sys.dont_write_bytecode = True
from scipy.stats import norm, t as student_t  # noqa: E402

from tools.reproduction import evaluate, exit_codes, stats  # noqa: E402
from tools.reproduction.inputs import KnownDeviations, Results, published_rows  # noqa: E402
from tools.reproduction.lines import Claim, claim_verdict  # noqa: E402
from tools.reproduction.rows import check_row  # noqa: E402

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

EPS = 1e-9
TABLES = os.path.join(REPO, "tables")


def welch(err, sem, n, n_pub=20):
    return (err ** 2 + sem ** 2) ** 2 / (err ** 4 / (n_pub - 1) + sem ** 4 / (n - 1))


def k_expected(nu):
    per_test = 1 - 0.99 ** (1 / 142)
    return student_t.isf(per_test / 2, nu)


class DetectionRule(unittest.TestCase):
    err, sem, n = 0.004, 0.006, 6       # few repetitions: Student t far from the normal

    def setUp(self):
        self.sigma = math.hypot(self.err, self.sem)
        self.nu = welch(self.err, self.sem, self.n)
        self.k = k_expected(self.nu)

    def verdict(self, d):
        return stats.compare(0.6, self.err, 0.6 + d, self.sem, self.n, "mu_s")

    def test_threshold_and_dof_from_their_definitions(self):
        r = self.verdict(0.0)
        self.assertAlmostEqual(r["dof"], self.nu, places=9)
        self.assertAlmostEqual(r["k"], self.k, places=9)
        self.assertAlmostEqual(r["detection"], self.k * self.sigma, places=12)
        self.assertGreater(self.k, norm.isf((1 - 0.99 ** (1 / 142)) / 2) + 0.3)  # t, not normal, at this dof

    def test_just_beyond_k_disagrees_either_sign(self):
        for sign in (1, -1):
            self.assertEqual(self.verdict(sign * self.k * self.sigma * (1 + EPS))["verdict"], "disagree")
            self.assertNotEqual(self.verdict(sign * self.k * self.sigma * (1 - EPS))["verdict"], "disagree")

    def test_significant_but_small_difference_is_a_disagreement(self):
        # |d| = 0.005 is well inside Delta = 0.03, but with tiny errors it is 10 sigma: a finding.
        r = stats.compare(0.6, 0.0003, 0.605, 0.0003, 20, "mu_s")
        self.assertLess(abs(r["d"]) + r["equivalence"], stats.DELTA["mu_s"])
        self.assertEqual(r["verdict"], "disagree")


class EquivalenceRule(unittest.TestCase):
    def check_boundary(self, coef, err, sem, n):
        sigma, nu = math.hypot(err, sem), welch(err, sem, n)
        t95 = student_t.ppf(0.95, nu)
        edge = stats.DELTA[coef] - t95 * sigma
        self.assertGreater(edge, 0)
        for sign in (1, -1):
            inside = stats.compare(0.5, err, 0.5 + sign * edge * (1 - EPS), sem, n, coef)
            outside = stats.compare(0.5, err, 0.5 + sign * edge * (1 + EPS), sem, n, coef)
            self.assertAlmostEqual(inside["equivalence"], t95 * sigma, places=12)
            self.assertEqual(inside["verdict"], "agree", (coef, err, sem, n, sign))
            self.assertEqual(outside["verdict"], "not_resolved", (coef, err, sem, n, sign))

    def test_tost_boundary_mu_s_few_repetitions(self):
        self.check_boundary("mu_s", 0.003, 0.004, 4)   # small dof: t95 well above 1.645

    def test_tost_boundary_mu_d(self):
        self.check_boundary("mu_d", 0.002, 0.0005, 20)

    def test_too_wide_to_certify_even_at_zero_difference(self):
        r = stats.compare(0.5, 0.02, 0.5, 0.02, 20, "mu_s")
        self.assertEqual(r["verdict"], "not_resolved")

    def test_tier_resolution_counts_rows_that_could_be_certified(self):
        rows = [{"coef": "mu_s", "err": 0.004, "sd": 0.02}, {"coef": "mu_s", "err": 0.004, "sd": 0.2},
                {"coef": "mu_d", "err": 0.009, "sd": 0.001}]
        res = stats.tier_resolution(rows, {"paper": 20, "smoke": 2})
        self.assertEqual(res["paper"]["mu_s"]["certifiable"], 1)   # sd 0.2 / sqrt(20) is too wide
        self.assertEqual(res["smoke"]["mu_s"]["certifiable"], 0)
        self.assertEqual(res["paper"]["mu_d"]["certifiable"], 0)   # the published error alone: 1.73 * 0.009 > 0.01
        self.assertEqual(list(res), ["paper", "smoke"])


def scene(row_id, mu_s, sem_s, n, mu_d=0.53, sem_d=0.0003):
    sd = lambda sem: sem * math.sqrt(n) if sem is not None else None  # noqa: E731
    return {"id": row_id, "result": {"mu_s": {"mean": mu_s, "sem": sem_s, "std": sd(sem_s), "n": n},
                                     "mu_d": {"mean": mu_d, "sem": sem_d, "std": sd(sem_d), "n": n},
                                     "contact_fraction": 1.0}}


class RowsAndKnownDeviations(unittest.TestCase):
    """check_row on a synthetic tab_pat0 document and a synthetic list of known deviations."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        root = self.tmp.name
        self.pub = published_rows(TABLES)
        p = {r: float(self.pub[r]["mu_s"]) for r in ("pat0_r01", "pat0_r02", "pat0_r03", "pat0_r04", "pat0_r05")}
        scenes = [scene("pat0_r01", p["pat0_r01"] + 0.2, 0.005, 20),     # far off, known at paper
                  scene("pat0_r02", p["pat0_r02"], 0.001, 20),           # agrees, known: stale
                  scene("pat0_r03", p["pat0_r03"] + 0.2, 0.005, 20),     # far off, known only at quick
                  scene("pat0_r04", p["pat0_r04"], 0.03, 20),            # too noisy: not resolved
                  scene("pat0_r05", None, None, 0)]                      # no slip: missing
        os.makedirs(os.path.join(root, "res", "tab_pat0"))
        with open(os.path.join(root, "res", "tab_pat0", "tab_pat0.json"), "w") as f:
            json.dump({"tier": "paper", "scenes": scenes}, f)
        kd = os.path.join(root, "known.tsv")
        with open(kd, "w") as f:
            f.write("row_id\tcoef\ttiers\treason\n"
                    "pat0_r01\tmu_s\tpaper\tsynthetic\npat0_r02\tmu_s\tall\tsynthetic\n"
                    "pat0_r03\tmu_s\tquick,smoke\tsynthetic\nC07\tclaim\tpaper\tsynthetic\n")
        self.known = KnownDeviations(kd)
        self.res = Results(os.path.join(root, "res"))

    def tearDown(self):
        self.tmp.cleanup()

    def row(self, rid):
        return check_row(self.res, self.pub, self.known, rid, "mu_s")

    def test_verdicts_and_exit_codes(self):
        cases = {"pat0_r01": ("disagree_known", False, 0), "pat0_r02": ("agree", True, 1),
                 "pat0_r03": ("disagree_new", False, 1), "pat0_r04": ("not_resolved", False, 77),
                 "pat0_r05": ("missing", False, 1)}
        for rid, (verdict, stale, code) in cases.items():
            r = self.row(rid)
            self.assertEqual((r["verdict"], r["stale"], exit_codes.row_exit_code(r)), (verdict, stale, code), rid)

    def test_stale_not_resolved_known_deviation_fails(self):
        r = self.row("pat0_r02")
        r.update(verdict="not_resolved")
        self.assertEqual(exit_codes.row_exit_code(r), 1)

    def test_unknown_tier_in_known_deviations_is_an_error(self):
        bad = os.path.join(self.tmp.name, "bad.tsv")
        with open(bad, "w") as f:
            f.write("row_id\tcoef\ttiers\treason\npat0_r01\tmu_s\tpaperr\tx\n")
        with self.assertRaises(ValueError):
            KnownDeviations(bad)


class ClaimLines(unittest.TestCase):
    def judge(self, fill):
        c = Claim()
        fill(c)
        return c.finish()

    def test_k_c_is_sidak_over_all_one_sided_comparisons(self):
        k_c, _ = self.judge(lambda c: (c.ordered((1, 0.1), (0, 0.1), "a", "mu_s"),
                                       c.at_most("b", 0, 0.1, 1, sides=2),
                                       c.exact("c", True)))
        self.assertAlmostEqual(k_c, norm.isf(1 - 0.99 ** (1 / 3)), places=12)
        # A spread over 3 values is 3 pairs, each of either sign: 6 one-sided comparisons.
        k_c, _ = self.judge(lambda c: c.spread("s", [("a", (1, 0.1)), ("b", (1, 0.1)), ("c", (1, 0.1))], 0.1))
        self.assertAlmostEqual(k_c, norm.isf(1 - 0.99 ** (1 / 6)), places=12)

    def test_ordering_fail_ok_unresolved(self):
        z95, sigma = norm.isf(0.05), math.hypot(0.006, 0.008)
        k_c = norm.isf(0.01)  # one comparison
        cases = [(-k_c * sigma * (1 + EPS), "fail"), (-k_c * sigma * (1 - EPS), "unresolved"),
                 (-0.03 + z95 * sigma * (1 + EPS), "ok"), (-0.03 + z95 * sigma * (1 - EPS), "unresolved"),
                 (0.0, "ok")]
        for d, want in cases:
            _, lines = self.judge(lambda c: c.ordered((0.5 + d, 0.006), (0.5, 0.008), "A > B", "mu_s"))
            self.assertEqual(lines[0]["status"], want, d)

    def test_ordering_uses_the_margin_of_its_coefficient(self):
        # d = -0.012 at sigma = 0.006: z = -2.0, not significant; lower bound -0.0219 lies within
        # the mu_s margin (0.03) but not within the mu_d margin (0.01).
        se = 0.006 / math.sqrt(2)
        for coef, want in (("mu_s", "ok"), ("mu_d", "unresolved")):
            _, lines = self.judge(lambda c: c.ordered((0.488, se), (0.5, se), "A > B", coef))
            self.assertEqual(lines[0]["status"], want, coef)

    def test_bound_fail_ok_unresolved(self):
        z95, k_c = norm.isf(0.05), norm.isf(0.01)
        for est, want in [(0.1 - z95 * 0.01 * (1 + EPS), "ok"), (0.1 - z95 * 0.01 * (1 - EPS), "unresolved"),
                          (0.1 + k_c * 0.01 * (1 - EPS), "unresolved"), (0.1 + k_c * 0.01 * (1 + EPS), "fail")]:
            _, lines = self.judge(lambda c: c.at_most("x", est, 0.01, 0.1))
            self.assertEqual(lines[0]["status"], want, est)

    def test_all_close_is_an_intersection_of_pairwise_bounds(self):
        z95 = norm.isf(0.05)
        # Two values 0.02 apart, sem 0.001 each: |d| + z95 * 0.00141 = 0.0223 against limit 0.025 * 1.0.
        _, lines = self.judge(lambda c: c.spread("s", [("a", (1.01, 0.001)), ("b", (0.99, 0.001))], 0.025))
        self.assertEqual(lines[0]["status"], "ok")
        limit = (0.02 + z95 * math.hypot(0.001, 0.001)) * (1 - EPS)
        _, lines = self.judge(lambda c: c.spread("s", [("a", (1.01, 0.001)), ("b", (0.99, 0.001))], limit))
        self.assertEqual(lines[0]["status"], "unresolved")
        _, lines = self.judge(lambda c: c.spread("s", [("a", (1.01, 0.001)), ("b", (0.99, 0.001))], 0.01))
        self.assertEqual(lines[0]["status"], "fail")

    def test_any_beyond(self):
        _, lines = self.judge(lambda c: c.any_beyond("dep", [("r1", 0.05, 0.001), ("r2", 0.0, 0.001)], 0.01))
        self.assertEqual(lines[0]["status"], "ok")
        _, lines = self.judge(lambda c: c.any_beyond("dep", [("r1", 0.001, 0.001), ("r2", 0.0, 0.001)], 0.01))
        self.assertEqual(lines[0]["status"], "fail")
        _, lines = self.judge(lambda c: c.any_beyond("dep", [("r1", 0.01, 0.001)], 0.01))
        self.assertEqual(lines[0]["status"], "unresolved")

    def test_claim_verdicts_and_exit_codes(self):
        ok, fail, unres = {"status": "ok"}, {"status": "fail"}, {"status": "unresolved"}
        cases = [([ok, ok], None, "holds", False, 0), ([ok, fail, unres], None, "fails_new", False, 1),
                 ([ok, fail], "why", "fails_known", False, 0), ([ok, unres], None, "not_resolved", False, 77),
                 ([ok, ok], "why", "holds", True, 1), ([ok, unres], "why", "not_resolved", True, 1)]
        for lines, known, verdict, stale, code in cases:
            v, s = claim_verdict(lines, known)
            self.assertEqual((v, s), (verdict, stale), (lines, known))
            self.assertEqual(exit_codes.claim_exit_code({"verdict": v, "stale": s}), code)
        self.assertEqual(exit_codes.claim_exit_code({"verdict": "missing", "stale": False}), 1)


class Registry(unittest.TestCase):
    def test_every_claim_of_the_table_has_a_function_and_targets(self):
        with tempfile.TemporaryDirectory() as empty:
            inp = evaluate.Inputs(empty, TABLES)
            self.assertEqual(len(inp.claims), 35)
            for cid in inp.claims:
                self.assertTrue(inp.claim_targets(cid), cid)
                rec = inp.claim(cid)   # nothing produced: every claim is missing, none is dropped
                self.assertEqual(rec["verdict"], "missing", cid)
                self.assertEqual(exit_codes.claim_exit_code(rec), 1)


if __name__ == "__main__":
    unittest.main()
