#!/usr/bin/env python3
"""Compare two reproduction summaries (build/reproduce/summary.tsv) number by number.

For a change that is meant to alter results only within the statistics (a different but
equivalent floating-point route, a faster algorithm), this is the evidence: for every published
number, the shift of our ensemble mean in units of the two runs' combined standard error,
dz = (ours_B - ours_A) / sqrt(sem_A^2 + sem_B^2), and every verdict that changed.

Both runs use the same seeds, so their repetitions share micro coefficients and the shifts are
smaller than for independent runs: |dz| <= 3 for every number is the criterion stated before
looking (issue 19's "equal within 3 combined standard errors"); a larger one is a real change.

Usage: python3 -m tools.compare_summaries A/summary.tsv B/summary.tsv [--json OUT]
Exit status 1 if some |dz| > 3 or a row is missing from either side.
"""
import csv
import json
import math
import sys


def read(path):
    with open(path, newline="") as f:
        return {(r["row_id"], r["coef"]): r for r in csv.DictReader(f, delimiter="\t")}


def main():
    a, b = read(sys.argv[1]), read(sys.argv[2])
    missing = sorted(set(a) ^ set(b))
    rows = []
    for key in sorted(set(a) & set(b)):
        ra, rb = a[key], b[key]
        ya, yb = float(ra["ours"]), float(rb["ours"])
        se = math.hypot(float(ra["sem"]), float(rb["sem"]))
        dz = (yb - ya) / se if se > 0 else (0.0 if yb == ya else math.inf)
        rows.append({"row_id": key[0], "coef": key[1], "a": ya, "b": yb, "diff": yb - ya, "dz": dz,
                     "verdict_a": ra["verdict"], "verdict_b": rb["verdict"]})
    absz = [abs(r["dz"]) for r in rows]
    n = len(rows)
    report = {
        "numbers": n,
        "missing": [list(k) for k in missing],
        "within": {str(k): sum(z <= k for z in absz) / n for k in (1, 2, 3)} if n else {},
        "max_abs_dz": max(absz) if absz else None,
        "by_coef": {},
        "verdict_changes": [r for r in rows if r["verdict_a"] != r["verdict_b"]],
    }
    for coef in sorted({r["coef"] for r in rows}):
        sub = [r for r in rows if r["coef"] == coef]
        report["by_coef"][coef] = {
            "numbers": len(sub),
            "max_abs_dz": max(abs(r["dz"]) for r in sub),
            "max_abs_diff": max(abs(r["diff"]) for r in sub),
            "mean_dz": sum(r["dz"] for r in sub) / len(sub),
        }
    worst = sorted(rows, key=lambda r: -abs(r["dz"]))[:5]
    print(f"{n} numbers compared; |dz| within 1/2/3: "
          + "/".join(f"{report['within'][k]:.3f}" for k in ("1", "2", "3")) + f"; max |dz| {report['max_abs_dz']:.2f}")
    for coef, s in report["by_coef"].items():
        print(f"  {coef}: max |dz| {s['max_abs_dz']:.2f}, max |diff| {s['max_abs_diff']:.2e}, mean dz {s['mean_dz']:+.2f}")
    for r in worst:
        print(f"  largest: {r['row_id']} {r['coef']} {r['a']:.6f} -> {r['b']:.6f} (dz {r['dz']:+.2f})")
    for r in report["verdict_changes"]:
        print(f"  verdict: {r['row_id']} {r['coef']} {r['verdict_a']} -> {r['verdict_b']} (dz {r['dz']:+.2f})")
    if missing:
        print("  missing rows:", missing)
    if "--json" in sys.argv:
        with open(sys.argv[sys.argv.index("--json") + 1], "w") as f:
            json.dump({"summary": report, "rows": rows}, f, indent=1)
    return 1 if missing or (absz and max(absz) > 3) else 0


if __name__ == "__main__":
    sys.exit(main())
