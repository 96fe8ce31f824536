"""Comparison lines of a figure claim, each ok / fail / unresolved, and the claim's verdict.

Claims compare our own numbers with each other (or with theory), so the same discipline as for
the published numbers applies: a line fails only on a significant contradiction, and is ok only
when the data show what the claim needs with 95 % confidence; otherwise it is unresolved.
  fail        at k_c: the one-sided normal quantile at a 1 % family-wise rate (Sidak) over all
              one-sided comparisons of the claim
  ok          at z95 = 1.645, one-sided 5 %: a one-sided confidence bound on the right side
Kinds of line:
  ordered     "A > B" (means with standard errors): fail if (A - B)/sigma < -k_c; ok if A is
              shown non-inferior to B at margin Delta of the observable: (A - B) - z95 sigma >= -Delta
  at_most     estimate <= limit: ok if estimate + z95 se <= limit; fail if estimate - k_c se > limit
  at_least    the mirror image
  all_close   every listed pair within limit: ok if every pair passes its own 95 % bound (an
              intersection-union test needs no multiplicity correction); fail if one pair exceeds
              the limit by k_c standard errors
  any_beyond  some listed difference exceeds limit: ok if one does by a Sidak-corrected 95 % bound
              (picking the best of several needs the correction); fail if all are within at k_c
  exact       a deterministic comparison (one repetition, a formula): ok or fail
Only the counts of comparisons are needed before k_c is known, so lines are collected first and
judged at the end (Claim.finish)."""
import math

from . import stats

Z95 = stats.z_upper(stats.ALPHA_EQUIVALENCE)


def _z(d, sigma):
    return d / sigma if sigma > 0 else (0.0 if d == 0 else math.copysign(math.inf, d))


class Claim:
    """Collects the lines of one claim; finish() turns them into statuses."""

    def __init__(self):
        self.pending = []       # (number of one-sided comparisons, judge(k_c) -> (status, text))

    def _add(self, comparisons, judge):
        self.pending.append((comparisons, judge))

    def ordered(self, hi, lo, label, coef):
        """hi = (mean, se) expected above lo = (mean, se); margin Delta of coefficient coef."""
        delta = stats.DELTA[coef]
        d, sigma = hi[0] - lo[0], math.hypot(hi[1], lo[1])

        def judge(k_c):
            z, low = _z(d, sigma), d - Z95 * sigma
            status = "fail" if z < -k_c else "ok" if low >= -delta else "unresolved"
            return status, (f"{label}: {hi[0]:.4f} vs {lo[0]:.4f}, diff {d:+.4f} +- {sigma:.4f} (z = {z:+.2f}); "
                            f"lower 95% bound {low:+.4f} vs margin -{delta:.2f}, fail below z = -{k_c:.2f}")
        self._add(1, judge)

    def at_most(self, label, est, se, limit, sides=1):
        """est <= limit. sides=2 when est is a modulus |x| (either sign of x may exceed)."""
        def judge(k_c):
            up, down = est + Z95 * se, est - k_c * se
            status = "ok" if up <= limit else "fail" if down > limit else "unresolved"
            return status, (f"{label}: {est:.4f} +- {se:.4f}, upper 95% bound {up:.4f} vs limit {limit:.4f}, "
                            f"fail if {est:.4f} - {k_c:.2f} se = {down:.4f} > limit")
        self._add(sides, judge)

    def at_least(self, label, est, se, limit):
        def judge(k_c):
            down, up = est - Z95 * se, est + k_c * se
            status = "ok" if down >= limit else "fail" if up < limit else "unresolved"
            return status, (f"{label}: {est:.4f} +- {se:.4f}, lower 95% bound {down:.4f} vs limit {limit:.4f}, "
                            f"fail if {est:.4f} + {k_c:.2f} se = {up:.4f} < limit")
        self._add(1, judge)

    def all_close(self, label, pairs, limit, scale=1.0):
        """Every |a - b| / scale <= limit, pairs = [(name_a, (mean, se), name_b, (mean, se))]."""
        diffs = [(na, nb, abs(a[0] - b[0]), math.hypot(a[1], b[1])) for na, a, nb, b in pairs]
        if not diffs:
            raise LookupError(f"{label}: fewer than two values to compare")

        def judge(k_c):
            widest = max(diffs, key=lambda q: q[2])
            up = max(d + Z95 * s for _, _, d, s in diffs) / scale
            down = max(d - k_c * s for _, _, d, s in diffs) / scale
            status = "ok" if up <= limit else "fail" if down > limit else "unresolved"
            return status, (f"{label}: widest {widest[0]} vs {widest[1]}, |diff|/ref = {widest[2] / scale:.4f}; "
                            f"largest upper 95% bound {up:.4f} vs limit {limit:.3f}, "
                            f"largest lower bound at k_c = {k_c:.2f}: {down:.4f}")
        self._add(2 * len(diffs), judge)

    def spread(self, label, named_values, limit):
        """(max - min)/mean <= limit over named (mean, se) values: all pairs close."""
        vals = list(named_values)
        mean = sum(v[0] for _, v in vals) / len(vals)
        pairs = [(na, a, nb, b) for i, (na, a) in enumerate(vals) for nb, b in vals[i + 1:]]
        self.all_close(label + f" (spread/mean over {len(vals)} values)", pairs, limit, mean)

    def any_beyond(self, label, items, limit):
        """Some |diff| > limit, items = [(name, |diff|, se)]."""
        if not items:
            raise LookupError(f"{label}: no value to compare")
        z_ok = stats.z_upper(stats.sidak(stats.ALPHA_EQUIVALENCE, len(items)))

        def judge(k_c):
            best = max(items, key=lambda q: q[1] - z_ok * q[2])
            low = best[1] - z_ok * best[2]
            worst_up = max(d + k_c * s for _, d, s in items)
            status = "ok" if low > limit else "fail" if worst_up <= limit else "unresolved"
            return status, (f"{label}: largest |diff| {max(d for _, d, _ in items):.4f}; best lower bound "
                            f"({best[0]}, Sidak 95% over {len(items)}) {low:.4f} vs limit {limit:.4f}; "
                            f"all within at k_c = {k_c:.2f} would need {worst_up:.4f} <= limit")
        self._add(2 * len(items), judge)

    def exact(self, label, good):
        self._add(0, lambda k_c: ("ok" if good else "fail", label))

    def finish(self):
        """(k_c, [{"status", "text"}])."""
        m = sum(c for c, _ in self.pending)
        k_c = stats.z_upper(stats.sidak(stats.ALPHA, m)) if m else math.inf
        lines = []
        for _, judge in self.pending:
            status, text = judge(k_c)
            lines.append({"status": status, "text": text})
        return (k_c if m else None), lines


def claim_verdict(lines, known_reason):
    """holds (every line ok), fails_known / fails_new (a line fails), not_resolved (otherwise);
    stale when listed as a known deviation at this tier but not failing."""
    statuses = {ln["status"] for ln in lines}
    if not lines:
        raise ValueError("a claim without comparison lines")
    if "fail" in statuses:
        return ("fails_known" if known_reason else "fails_new"), False
    verdict = "holds" if statuses == {"ok"} else "not_resolved"
    return verdict, bool(known_reason)
