#!/usr/bin/python3
"""Optional study `layout` (issue: fidelity): where does the paper put its pawls?

The paper does not say where a level's alternation of pawls and grooves starts on the run it
divides (the chain at level 1, each pawl of the level above deeper down). This study runs every
candidate rule on all 71 appendix rows and all 35 claims at the paper's statistics, and chooses
ONE rule for every row and both pattern kinds by a criterion fixed before any variant was run
(CRITERION below, also in paper/choices.md, "Pattern layout"):

  1. admissible: reproduces every printed S/S_tot that is a count (tpat1's 15 rows);
  2. then: the most published numbers not in disagreement (|z| <= k);
  3. then: the smallest sum of z^2 over the 142 numbers.

For each variant the layout-dependent targets (the three tables and fig3, fig_p1, fig5) are run
again with `--layout VARIANT` into <build>/studies/layout/VARIANT/; the layout-free ones (smooth
chains: fig1, fig_s1, fig_s2, fig2) are the build's own. Every variant is judged by the checker
(tools/reproduction) with no known deviations, so every disagreement counts. The result goes to
<build>/reproduce/layout/layout.json; `make studies` copies it to paper/data/ (committed: the
report and figures/layout.py read it).

Usage: python3 -m tools.layout_study BUILD_DIR [--variants a+b,c,...] [--out FILE]
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from fractions import Fraction

from tools.build_cache import cache_value
from tools.reproduction import evaluate

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)

CRITERION = ("admissible if every printed S/S_tot that is a count (the 15 rows of tpat1) is reproduced; "
             "among those, the most published numbers with |z| <= k; then the smallest sum of z^2 over "
             "the 142 numbers. One rule for every row, periodic and hierarchical alike.")
VARIANTS = ["pawl_first", "symmetric", "symmetric,pawl_first", "one_based", "groove_first"]
TABLES = {"tab_pat0": "published_tab_pat0.tsv", "tab_pat1": "published_tab_pat1.tsv",
          "tab_pat2": "published_tab_pat2.tsv"}
# Targets whose scenes depend on the layout, in dependency order, with the targets they read.
DEPENDENT = [("tab_pat0", []), ("tab_pat1", []), ("tab_pat2", []), ("fig3", []),
             ("fig_p1", ["tab_pat0", "tab_pat2"]), ("fig5", ["tab_pat0", "tab_pat2"])]
FREE = ["fig1", "fig_s1", "fig_s2", "fig2"]
COUNTED = "tab_pat1"  # the table whose printed S/S_tot are counts (see CRITERION)


def run_variant(build, tier, variant, out_root):
    """Run the layout-dependent targets with this layout; link the layout-free ones."""
    vdir = os.path.join(out_root, variant.replace(",", "+"))
    os.makedirs(vdir, exist_ok=True)
    bindir = os.path.join(build, "reproduce", "bin")
    for target, inputs in DEPENDENT:
        doc = os.path.join(vdir, target, f"{target}.json")
        exe = os.path.join(bindir, target)
        if os.path.exists(doc) and os.path.getmtime(doc) > os.path.getmtime(exe):
            continue  # resumable: a target this variant finished with the current driver is kept
        cmd = [exe, "--tier", tier, "--layout", variant, "--out", os.path.join(vdir, target)]
        if target in TABLES:
            cmd += ["--table", os.path.join(REPO, "tables", TABLES[target])]
        for src in inputs:
            cmd += ["--input", os.path.join(vdir, src, f"{src}.json")]
        t = time.time()
        log = os.path.join(vdir, f"{target}.log")
        with open(log, "w") as f:
            rc = subprocess.call(cmd, stdout=f, stderr=subprocess.STDOUT)
        if rc:
            raise RuntimeError(f"{variant}/{target} failed (exit {rc}); see {log}")
        print(f"  {variant:<22}{target:<10}{time.time() - t:7.0f} s", flush=True)
    for target in FREE:
        src = os.path.join(build, "reproduce", target)
        dst = os.path.join(vdir, target)
        if not os.path.exists(os.path.join(src, f"{target}.json")):
            raise RuntimeError(f"{target} has not been reproduced in {build}: run make reproduce-all first")
        if not os.path.islink(dst):
            os.symlink(os.path.abspath(src), dst)
    return vdir


def printed_s(rows_pub, row_id):
    r = rows_pub[row_id]
    return Fraction(int(r["S_over_Stot_num"]), int(r["S_over_Stot_den"]))


def judge(vdir):
    """The checker's summary of one variant, with no known deviations (every disagreement counts),
    plus its S/S_tot against the printed ones."""
    with tempfile.NamedTemporaryFile("w", suffix=".tsv", delete=False) as f:
        f.write("row_id\tcoef\ttiers\treason\n")
        empty = f.name
    try:
        inp = evaluate.Inputs(vdir, os.path.join(REPO, "tables"), known_path=empty)
        s = evaluate.summarize(inp)
    finally:
        os.unlink(empty)
    s_rows = []
    for target in TABLES:
        doc = json.load(open(os.path.join(vdir, target, f"{target}.json")))
        for sc in doc["scenes"]:
            mask = sc["contact_mask"]
            ours = Fraction(mask.count("1"), len(mask))
            pub = printed_s(inp.pub, sc["id"])
            s_rows.append({"row_id": sc["id"], "target": target, "S": str(ours), "S_printed": str(pub),
                           "match": ours == pub, "mask": mask})
    return s, s_rows


def digest(variant, s, s_rows):
    judged = [r for r in s["rows"] if r["z"] is not None]
    counted = [r for r in s_rows if r["target"] == COUNTED]
    return {
        "variant": variant,
        "S_matches_counted": sum(r["match"] for r in counted),
        "S_counted_rows": len(counted),
        "S_matches_all": sum(r["match"] for r in s_rows),
        "S_rows": len(s_rows),
        "not_disagree": sum(r["verdict"] not in ("disagree_known", "disagree_new", "missing") for r in s["rows"]),
        "sum_z2": sum(r["z"] ** 2 for r in judged),
        "counts": s["counts"],
        "z_distribution": s["z_distribution"],
        "rows": [{k: r[k] for k in ("row_id", "coef", "published", "err", "ours", "sem", "z", "k", "verdict")}
                 for r in s["rows"]],
        "claims": {c["claim_id"]: {"verdict": c["verdict"], "lines": c["lines"]} for c in s["claims"]},
        "S": s_rows,
    }


def choose(digests):
    """The criterion, applied to every variant alike."""
    admissible = [d for d in digests if d["S_matches_counted"] == d["S_counted_rows"]]
    if not admissible:
        raise RuntimeError("no variant reproduces every counted S/S_tot: the criterion cannot choose")
    return min(admissible, key=lambda d: (-d["not_disagree"], d["sum_z2"]))["variant"]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("build")
    ap.add_argument("--variants", default=",".join(v.replace(",", "+") for v in VARIANTS),
                    help="comma-separated; '+' joins the per-level rules of one variant")
    ap.add_argument("--out", default=None, help="default: <build>/reproduce/layout/layout.json (make studies "
                    "copies it to paper/data/)")
    a = ap.parse_args()
    tier = cache_value(a.build, "SPRINGBLOCK_TIER")
    a.out = a.out or os.path.join(a.build, "reproduce", "layout", "layout.json")
    variants = [v.replace("+", ",") for v in a.variants.split(",")]
    root = os.path.join(a.build, "studies", "layout")
    t0 = time.time()
    print(f"layout study: {len(variants)} variants at tier '{tier}' into {root}/", flush=True)
    digests = []
    for v in variants:
        vdir = run_variant(a.build, tier, v, root)
        s, s_rows = judge(vdir)
        d = digest(v, s, s_rows)
        digests.append(d)
        print(f"  {v:<22} S/S_tot counted {d['S_matches_counted']}/{d['S_counted_rows']}, all "
              f"{d['S_matches_all']}/{d['S_rows']}; not in disagreement {d['not_disagree']}/142; "
              f"sum z^2 {d['sum_z2']:.1f}; claims {d['counts']['claims']}", flush=True)
    chosen = choose(digests)
    doc = {"study": "layout", "tier": tier, "criterion": CRITERION, "chosen": chosen, "variants": digests,
           "wall_seconds": time.time() - t0,
           "provenance": {"commit": subprocess.run(["git", "-C", REPO, "rev-parse", "--short=12", "HEAD"],
                                                   capture_output=True, text=True).stdout.strip(),
                          "utc": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())}}
    os.makedirs(os.path.dirname(a.out), exist_ok=True)
    tmp = a.out + ".tmp"
    with open(tmp, "w") as f:
        json.dump(doc, f, indent=1)
    os.replace(tmp, a.out)
    print(f"layout study: chosen '{chosen}' by the criterion; wrote {a.out}", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
