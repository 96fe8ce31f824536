"""Statistics of the checker: library quantiles (SciPy), the two rules applied to every published
number, and what a tier of repetitions can resolve.

Rules (the reasons are in tools/check_reproduction.py's docstring):
  detection    |z| > k, z = d / sigma, k the two-sided Student-t quantile at the Sidak share of a
               1 % family-wise rate over the 142 published numbers, Welch-Satterthwaite dof
  equivalence  |d| + t_{nu,0.95} sigma <= Delta (Schuirmann's two one-sided tests at 5 % each)
with d = ours - published and sigma = sqrt(err^2 + sem^2).
"""
import math
import statistics

import numpy as np
# scipy.special holds the functions scipy.stats's norm and t evaluate (ndtr, ndtri, stdtrit), so
# these are the same doubles without importing scipy.stats, which took 0.46 s of a check's 0.50 s:
# each of the ~180 per-number CTest checks is a process of its own.
from scipy.special import ndtr, ndtri, stdtrit

ALPHA = 0.01                 # family-wise false-alarm rate of the detection rule
ALPHA_EQUIVALENCE = 0.05     # each of the two one-sided tests of the equivalence rule
N_PUBLISHED_NUMBERS = 142    # 71 table rows x (mu_s, mu_d): the family of the detection rule
N_PUB = 20                   # repetitions behind each published bracket (our reading of the paper)
# The smallest deviation that matters, per coefficient: what "agree" must exclude. Taken from
# issue 13 (a check that cannot see 0.03 in mu_s or 0.01 in mu_d must not say "agree") and
# fixed before looking at which rows land where.
DELTA = {"mu_s": 0.03, "mu_d": 0.01}


def sidak(alpha, m):
    """Per-comparison rate that keeps the family-wise rate at alpha over m independent tests."""
    return 1.0 - (1.0 - alpha) ** (1.0 / max(m, 1))


def t_upper(p, nu):
    """t with P(T > t) = p for nu degrees of freedom (the normal quantile when nu is infinite)."""
    return z_upper(p) if math.isinf(nu) else float(-stdtrit(nu, p))


def z_upper(p):
    """Normal quantile with upper tail p."""
    return float(-ndtri(p))


def normal_within(x):
    """P(|Z| <= x) for a standard normal Z."""
    return 2.0 * normal_cdf(x) - 1.0


def normal_cdf(x):
    """P(Z <= x) for a standard normal Z."""
    return float(ndtr(x))


def normal_pdf(x):
    """The standard normal density as scipy.stats.norm.pdf computes it: on an array (numpy's
    array exp and its scalar exp can differ in the last bit)."""
    return float(np.exp(-np.asarray(x, dtype=float)**2 / 2.0) / np.sqrt(2 * np.pi))


def welch_dof(err, sem, n):
    """Welch-Satterthwaite degrees of freedom of err^2 + sem^2, err from N_PUB repetitions and
    sem from n (n >= 2). Infinite when both are zero (nothing random left)."""
    var = err ** 2 + sem ** 2
    den = err ** 4 / (N_PUB - 1) + sem ** 4 / (n - 1)
    return var ** 2 / den if den > 0 else math.inf


def detection_k(nu):
    """k of the detection rule for one published number."""
    return t_upper(sidak(ALPHA, N_PUBLISHED_NUMBERS) / 2.0, nu)


def equivalence_t(nu):
    """t_{nu,0.95}: the one-sided quantile of each of the two tests of TOST."""
    return t_upper(ALPHA_EQUIVALENCE, nu)


def compare(published, err, ours, sem, n, coef):
    """Every number behind the verdict of one published value, and the verdict itself
    (agree / disagree / not_resolved; known deviations are sorted out by the caller)."""
    d = ours - published
    sigma = math.hypot(err, sem)
    nu = welch_dof(err, sem, n)
    k, t95, delta = detection_k(nu), equivalence_t(nu), DELTA[coef]
    z = d / sigma if sigma > 0 else (0.0 if d == 0 else math.copysign(math.inf, d))
    if abs(z) > k:
        verdict = "disagree"          # a significant difference is a finding, however small
    elif abs(d) + t95 * sigma <= delta:
        verdict = "agree"             # both one-sided tests exclude a deviation of delta
    else:
        verdict = "not_resolved"      # the data can neither show nor exclude a deviation of delta
    return {"d": d, "sigma": sigma, "z": z, "k": k, "dof": nu, "detection": k * sigma,
            "equivalence": t95 * sigma, "delta": delta, "verdict": verdict}


def tier_resolution(rows, tier_reps):
    """What each tier could resolve, from the per-repetition sd of the data at hand.

    rows: dicts with coef, err and sd (per-repetition standard deviation of our values).
    For each tier and coefficient: how many rows could at best be certified equivalent (even
    with d = 0: t95 sigma < Delta) and the median detection threshold k sigma, with
    sem = sd / sqrt(repetitions of the tier)."""
    out = {}
    for tier, reps in sorted(tier_reps.items(), key=lambda kv: -kv[1]):
        out[tier] = {"reps": reps}
        for coef in ("mu_s", "mu_d"):
            mine = [r for r in rows if r["coef"] == coef]
            certifiable, detection, equivalence = 0, [], []
            for r in mine:
                sem = r["sd"] / math.sqrt(reps)
                sigma = math.hypot(r["err"], sem)
                nu = welch_dof(r["err"], sem, reps)
                half = equivalence_t(nu) * sigma
                certifiable += half < DELTA[coef]
                detection.append(detection_k(nu) * sigma)
                equivalence.append(half)
            out[tier][coef] = {
                "rows": len(mine), "certifiable": certifiable,
                "median_detection": statistics.median(detection) if detection else None,
                "median_equivalence": statistics.median(equivalence) if equivalence else None}
    return out


def _sd(xs):
    return statistics.stdev(xs) if len(xs) > 1 else None


def z_distribution(rows):
    """How the z-scores of the judged published numbers spread, against a standard normal
    (and the sd per coefficient: their published errors need not mean the same thing)."""
    zs = [r["z"] for r in rows]
    cuts = (1, 2, 3)
    return {"n": len(zs),
            "within": {str(c): (sum(abs(z) <= c for z in zs) / len(zs) if zs else None) for c in cuts},
            "normal": {str(c): normal_within(c) for c in cuts},
            "mean": statistics.fmean(zs) if zs else None,
            "sd": _sd(zs),
            "sd_by_coef": {c: _sd([r["z"] for r in rows if r["coef"] == c]) for c in ("mu_s", "mu_d")}}
