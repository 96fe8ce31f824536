#!/usr/bin/python3
"""Compare reproduced friction coefficients with the published ones, and judge the figure claims.

Published numbers (one rule for all 142, no per-row tuning). The paper's round-bracket error is
read as the standard error of about N_PUB = 20 repetitions. For published p +- e and our mean
m +- s (standard error of n repetitions): d = m - p, sigma = sqrt(e^2 + s^2), z = d / sigma,
Welch-Satterthwaite dof nu = sigma^4 / (e^4/(N_PUB-1) + s^4/(n-1)). Each number gets one verdict:
  disagree      |z| > k, k the two-sided Student-t quantile at a 1 % family-wise false-alarm rate
                over the 142 numbers (Sidak). A significant difference is a finding however small,
                so it is never called agreement. Split into disagree_known (listed for this tier
                in tables/known_deviations.tsv, with what was investigated) and disagree_new.
  agree         |d| + t_{nu,0.95} sigma <= Delta (Delta = 0.03 for mu_s, 0.01 for mu_d), and not
                disagree. This is Schuirmann's two one-sided tests at 5 % each: the data exclude a
                deviation of Delta either way. A small |z| alone is not agreement: with few
                repetitions it is only the absence of evidence, and such a check could not have
                seen the deviations that matter.
  not_resolved  neither: at this tier the data can neither show nor exclude a deviation of Delta.
  missing       no result.
The rule and Delta were fixed before looking at which numbers land where. A known deviation that
no longer disagrees is stale: the summary says so and its test fails, so the list cannot rot.

Claims (tables/figure_claims.tsv) compare our own numbers; every comparison line is ok, fail or
unresolved by the same logic (tools/reproduction/lines.py): fail on a significant contradiction
(one-sided normal quantile k_c at 1 % family-wise over the claim's comparisons), ok when a 95 %
confidence bound shows what the claim needs (orderings up to the margin Delta, bounds within their
stated limit), unresolved otherwise. A claim holds when every line is ok, fails (known / new) when a
line fails, and is not_resolved otherwise.

Modes and exit codes (CTest registers 77 as SKIP_RETURN_CODE):
  --row ID --coef mu_s|mu_d   0 agree or disagree_known; 1 disagree_new, missing or stale; 77 not_resolved
  --claim CXX                 0 holds or fails_known;    1 fails_new, missing or stale;    77 not_resolved
  --summary [--out DIR]       summary.json (tools/summary_schema.py) and summary.tsv; exit 0 once written
  --list-claims               every claim with the targets it needs (CMake registers the tests from it)
"""
import argparse
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from tools import summary_schema as schema  # noqa: E402
from tools.reproduction import evaluate  # noqa: E402
from tools.reproduction.exit_codes import claim_exit_code, row_exit_code  # noqa: E402
from tools.reproduction.rows import row_line  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))


def print_claim(rec, statement):
    print(f"{rec['claim_id']} ({rec['figure']}, tier {rec['tier']}): {statement}")
    for ln in rec["lines"]:
        print(f"  {ln['status']:10s} {ln['text']}")
    if rec["note"]:
        print(f"  {rec['note']}")
    print(f"-> {rec['verdict']}" + (f" (k_c = {rec['k_c']:.2f})" if rec["k_c"] is not None else ""))
    if rec["known_deviation"]:
        print(f"known deviation at this tier: {rec['known_deviation']}")
    if rec["stale"]:
        print("STALE: listed in tables/known_deviations.tsv but no longer fails: remove it")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--results", default=os.path.join(HERE, "..", "build", "reproduce"))
    ap.add_argument("--tables", default=os.path.join(HERE, "..", "tables"))
    ap.add_argument("--known-deviations", default=None, help="default: TABLES/known_deviations.tsv")
    ap.add_argument("--out", default=None, help="directory for summary.json/tsv (default: --results)")
    mode = ap.add_mutually_exclusive_group(required=True)
    mode.add_argument("--row")
    mode.add_argument("--claim")
    mode.add_argument("--summary", action="store_true")
    mode.add_argument("--list-claims", action="store_true")
    ap.add_argument("--coef", choices=["mu_s", "mu_d"])
    a = ap.parse_args()
    inp = evaluate.Inputs(a.results, a.tables, a.known_deviations)
    if a.list_claims:
        for cid in sorted(inp.claims):
            print(cid, *inp.claim_targets(cid))
        return 0
    if a.summary:
        s = evaluate.summarize(inp)
        out = a.out or a.results
        os.makedirs(out, exist_ok=True)
        schema.write(os.path.join(out, "summary.json"), s)
        schema.write_tsv(os.path.join(out, "summary.tsv"), s)
        print("\n".join(evaluate.report_lines(s)))
        return 0
    if a.row:
        if a.row not in inp.pub or not a.coef:
            ap.error("--row needs a published row_id and --coef")
        rec = inp.row(a.row, a.coef)
        print(row_line(rec))
        if rec["known_deviation"]:
            print(f"known deviation at tier {rec['tier']}: {rec['known_deviation']}")
        return row_exit_code(rec)
    if a.claim not in inp.claims:
        ap.error(f"unknown claim {a.claim}")
    rec = inp.claim(a.claim)
    print_claim(rec, inp.claims[a.claim]["statement"])
    return claim_exit_code(rec)


if __name__ == "__main__":
    sys.exit(main())
