"""One verdict per published number: agree, disagree_known, disagree_new, not_resolved or missing.

The statistics are in stats.compare; here the result is looked up, the known deviations are
applied and the record of the summary (tools/summary_schema.py, ROW_KEYS) is filled in."""
from . import stats
from .inputs import statistic, table_target


def check_row(res, pub, known, row_id, coef):
    target = table_target(row_id)
    tier = res.tier(target)
    p, e = float(pub[row_id][coef]), float(pub[row_id][coef + "_err"])
    rec = {"row_id": row_id, "coef": coef, "target": target, "tier": tier, "published": p, "err": e,
           "ours": None, "sem": None, "sd": None, "n": None, "d": None, "sigma": None, "z": None, "k": None,
           "dof": None, "detection": None, "equivalence": None, "delta": stats.DELTA[coef],
           "verdict": "missing", "known_deviation": known.reason((row_id, coef), tier), "stale": False,
           "note": ""}
    try:
        m, s, sd, n = statistic(res.scene(target, row_id), coef)
    except LookupError as ex:
        rec["note"] = str(ex)
        return rec
    rec.update(ours=m, sem=s, sd=sd, n=n, **stats.compare(p, e, m, s, n, coef))
    if rec["verdict"] == "disagree":
        rec["verdict"] = "disagree_known" if rec["known_deviation"] else "disagree_new"
    elif rec["known_deviation"]:
        # Listed as deviating at this tier, but the data no longer show it: the list is out of date.
        rec["stale"] = True
    return rec


def row_line(rec):
    """One line for people: what was compared and why the verdict."""
    head = f"{rec['row_id']} {rec['coef']}"
    if rec["verdict"] == "missing":
        return f"{head}: missing ({rec['note']})"
    line = (f"{head}: ours {rec['ours']:.4f} +- {rec['sem']:.4f} (n={rec['n']}), paper {rec['published']:.3f} "
            f"+- {rec['err']:.3f}: d = {rec['d']:+.4f}, z = {rec['z']:+.2f}, detect |z| > {rec['k']:.2f} "
            f"(|d| > {rec['detection']:.4f}), agree if |d| + {rec['equivalence']:.4f} <= {rec['delta']:.2f} "
            f"-> {rec['verdict']}")
    if rec["known_deviation"]:
        line += " [known deviation]"
    if rec["stale"]:
        line += " STALE: listed in known_deviations.tsv but no longer disagrees"
    return line
