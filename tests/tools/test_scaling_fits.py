#!/usr/bin/python3
"""paper/scaling_fits.py on synthetic size-scaling documents (no simulation, a second): a power law
made exactly must come back with its parameters and be adequate, noise of the stated size must
pass the chi^2 rule and a trend the fit cannot follow must fail it; a curve in Lambda shared by
both families must collapse on Lambda and not on N, and points without a standard error are left
out."""
import math
import sys
import unittest

import numpy as np

sys.dont_write_bytecode = True
from paper import scaling_fits as sf  # noqa: E402

ELL = 0.1 * math.sqrt(3.0)  # the paper's elastic length at large N: l_z sqrt(E/G)
NS = [36, 108, 360, 1080, 3600, 10800, 36000, 108000]


def x_of(family, N):
    L = 7.2 if family == "fixed_length" else 0.02 * N
    return {"family": family, "surface": "smooth", "N": N, "L_x_cm": L, "l_x_cm": L / N,
            "elastic_length_cm": ELL * math.sqrt((N - 1) / N)}


def doc_of(mu_of, sem=1e-3, noise=None, families=sf.FAMILIES):
    """A document whose mu_s at each scene is mu_of(x), plus noise[k] standard errors if given."""
    scenes, k = [], 0
    for family in families:
        for N in NS:
            x = x_of(family, N)
            mu = mu_of(x) + (noise[k] * sem if noise is not None else 0.0)
            k += 1
            scenes.append({"x": x, "result": {"mu_s": {"mean": mu, "sem": sem, "n": 20}, "mu_d": None}})
    return {"scenes": scenes}


class Trends(unittest.TestCase):
    def test_exact_power_law_comes_back(self):
        doc = doc_of(lambda x: 0.6 + 0.8 * x["N"] ** -0.4)
        t = [r for r in sf.trends(doc) if r["family"] == "fixed_block"][0]
        pl = t["power_law"]
        self.assertTrue(pl["converged"])
        np.testing.assert_allclose(pl["params"], [0.6, 0.8, 0.4], rtol=1e-5)
        self.assertLess(pl["chi2"], 1e-6)
        self.assertTrue(pl["adequate"])
        self.assertEqual((t["N_min"], t["N_max"], t["points"]), (36, 108000, 8))

    def test_log_linear_slope_and_its_error(self):
        doc = doc_of(lambda x: 0.7 - 0.02 * math.log10(x["N"]), sem=2e-3)
        ll = [r for r in sf.trends(doc) if r["family"] == "fixed_length"][0]["log_linear"]
        self.assertAlmostEqual(ll["params"][1], -0.02, places=9)
        # The slope's error is the weighted least squares one: sem / sqrt(sum (u - mean u)^2).
        u = np.log10(NS)
        self.assertAlmostEqual(ll["errors"][1], 2e-3 / math.sqrt(np.sum((u - u.mean()) ** 2)), places=9)

    def test_noise_of_the_stated_size_passes_and_a_kink_fails(self):
        rng = np.random.default_rng(3)
        noisy = doc_of(lambda x: 0.7 - 0.02 * math.log10(x["N"]), noise=rng.standard_normal(16))
        for t in sf.trends(noisy):
            self.assertTrue(t["log_linear"]["adequate"], t)
        # A step of 10 standard errors between N = 360 and 1080 is no straight line in log N.
        kinked = doc_of(lambda x: 0.7 - (0.01 if x["N"] > 360 else 0.0))
        self.assertFalse([r for r in sf.trends(kinked)][0]["log_linear"]["adequate"])

    def test_points_without_a_standard_error_are_left_out(self):
        doc = doc_of(lambda x: 0.7)
        doc["scenes"][0]["result"]["mu_s"]["n"] = 1
        self.assertEqual(len(sf.points(doc, "smooth", "fixed_length", "mu_s")), 7)
        self.assertEqual(sf.points(doc, "smooth", "fixed_length", "mu_d"), [])


class Collapse(unittest.TestCase):
    def verdicts(self, doc):
        return {c["candidate"]: c["collapses"] for c in sf.collapses(doc) if c["quantity"] == "mu_s"}

    def test_a_curve_in_lambda_collapses_on_lambda_only(self):
        # mu depends on L_x / ell alone: flat at fixed L_x, falling at fixed l_x.
        v = self.verdicts(doc_of(lambda x: 0.6 + 0.5 * (x["L_x_cm"] / ELL) ** -0.5))
        self.assertEqual(v, {"N": False, "Lambda": True, "n_e": False})

    def test_a_curve_in_n_collapses_on_n_only(self):
        v = self.verdicts(doc_of(lambda x: 0.6 + 0.5 * x["N"] ** -0.3))
        self.assertEqual(v, {"N": True, "Lambda": False, "n_e": False})

    def test_candidates_are_exactly_constant_where_they_should_be(self):
        lam = {sf.candidate(x_of("fixed_length", N), "Lambda") for N in NS}
        ne = {sf.candidate(x_of("fixed_block", N), "n_e") for N in NS}
        self.assertEqual(len({round(v, 12) for v in lam}), 1)
        self.assertEqual(len({round(v, 12) for v in ne}), 1)
        self.assertAlmostEqual(next(iter(lam)), 7.2 / ELL, places=9)


if __name__ == "__main__":
    unittest.main()
