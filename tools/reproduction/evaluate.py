"""Everything together: every published number and every claim judged, counted and summarised in
the shape tools/summary_schema.py defines (the only place that shape is written down)."""
import os

from tools import summary_schema as schema

from . import stats
from .claims import REGISTRY, View, parse_params, targets_of
from .inputs import TIERS, COEFS, KnownDeviations, Results, load_claims, published_rows, table_target
from .lines import Claim, claim_verdict
from .rows import check_row, row_line


class Inputs:
    """The published side and the results directory, read once."""

    def __init__(self, results, tables, known_path=None):
        self.res = Results(results)
        self.pub = published_rows(tables)
        self.claims = load_claims(tables)
        self.known = KnownDeviations(known_path or os.path.join(tables, "known_deviations.tsv"))
        unregistered = sorted(set(self.claims) - set(REGISTRY))
        orphaned = sorted(set(REGISTRY) - set(self.claims))
        if unregistered or orphaned:
            raise ValueError(f"figure_claims.tsv and the claim registry differ: no function for {unregistered}, "
                             f"no TSV line for {orphaned}")
        if 2 * len(self.pub) != stats.N_PUBLISHED_NUMBERS:
            raise ValueError(f"{2 * len(self.pub)} published numbers in the tables, the detection rule's "
                             f"family is {stats.N_PUBLISHED_NUMBERS}")

    def row(self, row_id, coef):
        return check_row(self.res, self.pub, self.known, row_id, coef)

    def rows(self):
        return [self.row(rid, coef) for rid in self.pub for coef in COEFS]

    def claim_targets(self, cid):
        return targets_of(cid, parse_params(self.claims[cid]["parameters"]))

    def claim(self, cid):
        row = self.claims[cid]
        params = parse_params(row["parameters"])
        targets = targets_of(cid, params)
        rec = {"claim_id": cid, "figure": row["figure"], "statement": row["statement"], "targets": list(targets),
               "tier": None, "k_c": None, "lines": [], "verdict": "missing", "known_deviation": None,
               "stale": False, "note": ""}
        absent = [t for t in targets if self.res.doc(t) is None]
        if absent:
            rec["note"] = "not produced: " + ", ".join(absent)
            return rec
        # The weakest statistics among its targets decide what the claim can resolve.
        rec["tier"] = min((self.res.tier(t) for t in targets), key=TIERS.index)
        rec["known_deviation"] = self.known.reason((cid, "claim"), rec["tier"])
        c = Claim()
        try:
            REGISTRY[cid][0](c, params, View(self.res, self.pub, cid, targets))
        except (LookupError, ValueError, ZeroDivisionError) as ex:
            rec["note"] = f"cannot evaluate: {type(ex).__name__}: {ex}"
            return rec
        rec["k_c"], rec["lines"] = c.finish()
        rec["verdict"], rec["stale"] = claim_verdict(rec["lines"], rec["known_deviation"])
        return rec

    def produced(self):
        """{target: tier} of every document under the results directory."""
        out = {}
        for name in sorted(os.listdir(self.res.root)):
            if os.path.isfile(os.path.join(self.res.root, name, f"{name}.json")):
                out[name] = self.res.tier(name)
        return out

    def tier_reps(self, produced):
        """Repetitions per tier, as every target's document states them (they must agree)."""
        seen = {}
        for t in produced:
            doc = self.res.doc(t)
            if "tier_reps" not in doc:
                raise ValueError(f"{t}.json has no 'tier_reps' (repetitions of each tier, reproduce/README.md)")
            seen[t] = doc["tier_reps"]
        values = {tuple(sorted(v.items())) for v in seen.values()}
        if len(values) != 1:
            raise ValueError(f"targets disagree on tier_reps: {seen}")
        return dict(values.pop())


def summarize(inp):
    """The summary document of everything under the results directory."""
    produced = inp.produced()
    if not produced:
        raise ValueError(f"no target documents under {inp.res.root}")
    tier_reps = inp.tier_reps(produced)
    rows = inp.rows()
    claims = [inp.claim(cid) for cid in sorted(inp.claims)]
    judged = [r for r in rows if r["verdict"] != "missing"]
    summary = {
        "schema_version": schema.SCHEMA_VERSION,
        "tier": min(produced.values(), key=TIERS.index),
        "target_tiers": produced,
        "tier_reps": tier_reps,
        "thresholds": {"alpha_familywise": stats.ALPHA, "n_published": stats.N_PUBLISHED_NUMBERS,
                       "n_pub_reps_assumed": stats.N_PUB, "alpha_equivalence": stats.ALPHA_EQUIVALENCE,
                       "z95": stats.z_upper(stats.ALPHA_EQUIVALENCE), "delta": dict(stats.DELTA)},
        "rows": rows,
        "claims": claims,
        "counts": schema.count(rows, claims),
        "counts_per_target": schema.counts_per_target(rows, claims, produced),
        "stale": [f"{r['row_id']} {r['coef']}" for r in rows if r["stale"]] +
                 [f"{c['claim_id']} claim" for c in claims if c["stale"]],
        "resolution": stats.tier_resolution(judged, tier_reps),
        "z_distribution": stats.z_distribution(judged),
    }
    return summary


def target_counts_now(inp, target):
    """Counts of one target while others may still be running: its published numbers, and the
    claims that need it and whose other targets are all produced (for a progress line)."""
    rows = [inp.row(rid, c) for rid in inp.pub for c in COEFS if table_target(rid) == target]
    ready = [cid for cid in sorted(inp.claims) if target in inp.claim_targets(cid)
             and all(inp.res.doc(t) is not None for t in inp.claim_targets(cid))]
    return schema.count(rows, [inp.claim(cid) for cid in ready])


def report_lines(s):
    """What the summary says, for the console (the full detail is in summary.json / the report)."""
    c, th = s["counts"], s["thresholds"]
    out = [f"Tier {s['tier']} ({s['tier_reps'][s['tier']]} repetitions).",
           f"Published numbers: {schema.format_counts({'rows': c['rows'], 'claims': {}})}.",
           f"  disagree: |z| > k (Sidak {th['alpha_familywise']:.0%} over {th['n_published']}); agree: TOST at "
           f"{th['alpha_equivalence']:.0%} within Delta = {th['delta']['mu_s']} (mu_s), {th['delta']['mu_d']} (mu_d)."]
    for r in s["rows"]:
        if r["verdict"] in ("disagree_new", "disagree_known", "missing"):
            out.append("  " + row_line(r))
    out.append(f"Claims: {schema.format_counts({'rows': {}, 'claims': c['claims']})}.")
    for cl in s["claims"]:
        if cl["verdict"] != "holds":
            out.append(f"  {cl['claim_id']}: {cl['verdict']}" + (f" ({cl['note']})" if cl["note"] else ""))
    out.append("What each tier can resolve (rows that could be certified equivalent / median detection "
               "threshold k sigma):")
    for tier, res in s["resolution"].items():
        out.append(f"  {tier:6s} ({res['reps']:2d} reps): " + "; ".join(
            f"{coef} {res[coef]['certifiable']}/{res[coef]['rows']}, {res[coef]['median_detection']:.4f}"
            for coef in COEFS if res[coef]["rows"]))
    z = s["z_distribution"]
    if z["n"]:
        out.append(f"z-scores: |z| <= 1, 2, 3: " + ", ".join(f"{z['within'][k]:.3f}" for k in ("1", "2", "3")) +
                   " (normal " + ", ".join(f"{z['normal'][k]:.3f}" for k in ("1", "2", "3")) +
                   f"); sd {z['sd']:.2f} over {z['n']} "
                   f"(mu_s {z['sd_by_coef']['mu_s']:.2f}, mu_d {z['sd_by_coef']['mu_d']:.2f})")
    for item in s["stale"]:
        out.append(f"STALE KNOWN DEVIATION: {item} is listed in tables/known_deviations.tsv for tier "
                   f"{s['tier']} but no longer deviates: remove it (its test fails)")
    return out
