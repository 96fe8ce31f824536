"""The readings of the first load peak (the `extraction` study) judged by the criterion fixed in
paper/choices.md ("Reading mu_s") before any of them was compared with a published number:
the score of a reading on a set of rows (sum of the checker's z^2 over their mu_s), the choice
by cross-validation over the three appendix tables, the adoption rule, each row's systematic
spread over the admissible readings, and what the sample spacing is worth.

Run as `python3 -m tools.reproduction.readings EXTRACTION_JSON [--out FILE]` to print (or write)
the whole judgement as JSON."""
import argparse
import json
import math
import os
import statistics
import sys
from pathlib import Path

from tools.reproduction import stats
from tools.reproduction.inputs import TABLE_TARGET, published_rows

DEFAULT_SPACING = "1e-2ms"
FINE_SPACING = "1e-3ms"
BASELINE = "all_slipped"
SPACING_SHARE = 0.2   # a spacing moves no z by more than this (choices.md)


def table_of(row_id):
    return row_id.split("_")[0]


class Readings:
    """Every row's mu_s statistics under every reading, from the study's document."""

    def __init__(self, doc, published):
        self.pub = published
        self.stat = {}          # (rule, spacing) -> row_id -> (mean, sem, n)
        self.admissible = []    # the admissible rules, in the study's order
        self.order = []         # every rule, in the study's order
        for s in doc["scenes"]:
            x = s["x"]
            rule, spacing = x["rule"], x.get("sample_dt", DEFAULT_SPACING)
            st = s["result"]["mu_s"]
            if rule not in self.order:
                self.order.append(rule)
                if x.get("admissible", rule == BASELINE):
                    self.admissible.append(rule)
            if st["mean"] is not None:
                self.stat.setdefault((rule, spacing), {})[x["row_id"]] = (st["mean"], st["sem"] or 0.0, st["n"])
        self.rows = [r for r in published if r in self.stat.get((BASELINE, DEFAULT_SPACING), {})]

    def compare(self, rule, row_id, spacing=DEFAULT_SPACING):
        mean, sem, n = self.stat[(rule, spacing)][row_id]
        p = self.pub[row_id]
        return stats.compare(float(p["mu_s"]), float(p["mu_s_err"]), mean, sem, n, "mu_s")

    def measured(self, rule, rows, spacing=DEFAULT_SPACING):
        have = self.stat.get((rule, spacing), {})
        return [r for r in rows if r in have]

    def score(self, rule, rows, spacing=DEFAULT_SPACING):
        """Sum of z^2 over the rows; a row the reading did not measure counts as infinite."""
        if len(self.measured(rule, rows, spacing)) < len(rows):
            return math.inf
        return sum(self.compare(rule, r, spacing)["z"] ** 2 for r in rows)

    def judge(self, rule, rows, spacing=DEFAULT_SPACING):
        """What a reading gives on a set of rows: S, the share of |z| <= 2, the sd of z, and how
        many are not in disagreement under the checker's detection rule."""
        zs, ok = [], 0
        for r in self.measured(rule, rows, spacing):
            c = self.compare(rule, r, spacing)
            zs.append(c["z"])
            ok += c["verdict"] != "disagree"
        n = len(zs)
        return {"rule": rule, "rows": n, "sum_z2": sum(z * z for z in zs),
                "within2": sum(abs(z) <= 2 for z in zs) / n if n else math.nan,
                "mean_z": statistics.fmean(zs) if n else math.nan,
                "sd_z": statistics.stdev(zs) if n > 1 else math.nan, "not_disagree": ok}

    def choose(self, rows):
        """The admissible reading with the smallest score on the rows (the study's order breaks ties)."""
        return min(self.admissible, key=lambda rule: (self.score(rule, rows), self.admissible.index(rule)))


def folds(rows):
    """Every direction of the cross-validation: leave one table out (train on two, judge on the
    third) and the other way round (train on one, judge on the other two)."""
    tables = sorted({table_of(r) for r in rows})
    out = []
    for held in tables:
        train = [r for r in rows if table_of(r) != held]
        test = [r for r in rows if table_of(r) == held]
        out.append({"kind": "leave_one_out", "train": [t for t in tables if t != held], "test": [held],
                    "train_rows": train, "test_rows": test})
    for one in tables:
        train = [r for r in rows if table_of(r) == one]
        test = [r for r in rows if table_of(r) != one]
        out.append({"kind": "train_on_one", "train": [one], "test": [t for t in tables if t != one],
                    "train_rows": train, "test_rows": test})
    return out


def cross_validate(rd):
    results = []
    for f in folds(rd.rows):
        chosen = rd.choose(f["train_rows"])
        results.append({"kind": f["kind"], "train": f["train"], "test": f["test"], "chosen": chosen,
                        "train_score": rd.score(chosen, f["train_rows"]),
                        "held_out": rd.judge(chosen, f["test_rows"]),
                        "baseline_held_out": rd.judge(BASELINE, f["test_rows"])})
    return results


def adoption(cv):
    """choices.md: R replaces all_slipped only if R is the choice of at least two of the three
    leave-one-table-out folds and, in each of those three folds, the choice beats all_slipped on
    the held-out table."""
    loo = [f for f in cv if f["kind"] == "leave_one_out"]
    counts = {}
    for f in loo:
        counts[f["chosen"]] = counts.get(f["chosen"], 0) + 1
    best, votes = max(counts.items(), key=lambda kv: kv[1])
    beats = [f["held_out"]["sum_z2"] < f["baseline_held_out"]["sum_z2"] for f in loo]
    adopted = best if best != BASELINE and votes >= 2 and all(beats) else BASELINE
    reason = (f"{best} is the choice of {votes} of {len(loo)} leave-one-table-out folds; the choice beats "
              f"{BASELINE} on the held-out table in {sum(beats)} of {len(loo)}")
    return {"adopted": adopted, "majority": best, "votes": votes, "beats_baseline": beats, "reason": reason}


def row_spread(rd, rule, spacing=DEFAULT_SPACING):
    """Per row: ours under the given reading and sample spacing, the range over the admissible
    readings at that spacing, and whether the verdict on the published number holds under every
    admissible reading."""
    out = []
    for r in rd.measured(rule, rd.rows, spacing):
        values, verdicts = {}, {}
        for a in rd.admissible:
            if r in rd.stat.get((a, spacing), {}):
                values[a] = rd.stat[(a, spacing)][r][0]
                verdicts[a] = rd.compare(a, r, spacing)["verdict"]
        c = rd.compare(rule, r, spacing)
        out.append({"row_id": r, "published": float(rd.pub[r]["mu_s"]), "err": float(rd.pub[r]["mu_s_err"]),
                    "ours": rd.stat[(rule, spacing)][r][0], "sem": rd.stat[(rule, spacing)][r][1],
                    "z": c["z"], "verdict": c["verdict"],
                    "low": min(values.values()), "high": max(values.values()),
                    "verdicts": sorted(set(verdicts.values())),
                    "robust": len(set(verdicts.values())) == 1})
    return out


def spacing_effect(rd, rule):
    """Per row, mu_s at 1e-3 ms minus at 1e-2 ms (same draws) over the row's combined standard
    error; the default spacing stays if every |shift| is below SPACING_SHARE."""
    rows = []
    for r in rd.measured(rule, rd.rows, FINE_SPACING):
        coarse, fine = rd.stat[(rule, DEFAULT_SPACING)][r], rd.stat[(rule, FINE_SPACING)][r]
        sigma = math.hypot(float(rd.pub[r]["mu_s_err"]), coarse[1])
        rows.append({"row_id": r, "shift": fine[0] - coarse[0], "shift_over_sigma": (fine[0] - coarse[0]) / sigma})
    worst = max(rows, key=lambda x: abs(x["shift_over_sigma"])) if rows else None
    keep = bool(rows) and all(abs(x["shift_over_sigma"]) < SPACING_SHARE for x in rows)
    return {"rule": rule, "rows": rows, "worst": worst, "default_stays": keep,
            "default": DEFAULT_SPACING if keep else FINE_SPACING}


def judgement(doc, tables):
    rd = Readings(doc, published_rows(tables))
    cv = cross_validate(rd)
    adopt = adoption(cv)
    spacing = {rule: spacing_effect(rd, rule) for rule in sorted({BASELINE, adopt["adopted"]})}
    return {
        "criterion": "paper/choices.md, 'Reading mu_s: the family, and how one is chosen'",
        "rows": len(rd.rows),
        "admissible": rd.admissible,
        "readings": [dict(rd.judge(rule, rd.rows), admissible=rule in rd.admissible) for rule in rd.order],
        "cross_validation": cv,
        "adoption": adopt,
        "spacing": spacing,
        # The systematic spread of the numbers in use: the adopted reading at the spacing the
        # spacing criterion set.
        "spread_spacing": spacing[adopt["adopted"]]["default"],
        "spread": row_spread(rd, adopt["adopted"], spacing[adopt["adopted"]]["default"]),
    }


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("extraction", help="the extraction study's JSON document")
    ap.add_argument("--tables", default=str(Path(__file__).resolve().parents[2] / "tables"))
    ap.add_argument("--out", help="write the judgement here (default: stdout)")
    a = ap.parse_args(argv)
    text = json.dumps(judgement(json.loads(Path(a.extraction).read_text()), a.tables), indent=1) + "\n"
    if a.out:
        tmp = a.out + ".tmp"
        Path(tmp).write_text(text)
        os.replace(tmp, a.out)
    else:
        sys.stdout.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
