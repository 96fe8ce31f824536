#!/usr/bin/python3
"""The documentation's design query on the paper's chain, run and checked (`make bench`; the cost
page quotes it through python3 -m tools.design_cost).

It runs the query of docs/cost.md ("A design query on the paper's chain": the periodic surfaces
with n_p, n_g <= 60 of the paper's N = 360 chain, target mu_s = 0.65), keeps what it printed and
its JSON's timings (wall time, each stage's CPU time), then simulates the first answer again with
an independent seed and 20 repetitions, and looks the answer up in the paper's table of
single-level periodic surfaces. Everything goes into one JSON document with where and when.

Usage: python3 -m bench.design_query --springblock BIN --out JSON [--threads 2]
"""
import argparse
import csv
import json
import os
import sys
import tempfile

from bench.child import run_child
from tools.generated_block import write_atomic
from tools.machine import REPO, load_average, machine

QUERY = ["--N", "360", "--length", "7.2cm", "--family", "periodic", "--max-np", "60", "--max-ng", "60",
         "--target-mu-s", "0.65"]
RECHECK_REPS, RECHECK_SEED = 20, 2026
PUBLISHED = os.path.join(REPO, "tables", "published_tab_pat0.tsv")


def timed(cmd):
    """(stdout, CPU seconds of the child, exit code) of one command."""
    out, usage, code = run_child(cmd, capture=True)
    return out, usage.ru_utime + usage.ru_stime, code


def published(pattern):
    """The paper's mu_s and its uncertainty for a single-level periodic surface, or None."""
    with open(PUBLISHED) as f:
        rows = csv.DictReader((line for line in f if not line.startswith("#")), delimiter="\t")
        for row in rows:
            if row.get("pattern") == pattern:
                return {"row": row["row_id"], "mu_s": float(row["mu_s"]), "mu_s_err": float(row["mu_s_err"])}
    return None


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--springblock", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--threads", type=int, default=2)
    a = ap.parse_args(argv)
    doc = {"machine": machine(), "load_start": load_average(), "threads": a.threads}
    with tempfile.TemporaryDirectory() as d:
        design_out = os.path.join(d, "design.json")
        printed, cpu, code = timed([a.springblock, "design", *QUERY, "--threads", str(a.threads), "--out", design_out])
        if code != 0:
            sys.exit(f"design_query: the query failed ({code})")
        with open(design_out) as f:
            design = json.load(f)
    doc.update(command=["springblock", "design", *QUERY, "--threads", str(a.threads), "--out", "design.json"],
               printed=printed, cpu_s=cpu, wall_s=design["wall_seconds"],
               classes_cpu_s=(design["search"]["contact_classes"] or {}).get("cpu_s", 0.0),
               rungs=[{"candidates": r["candidates"], "cpu_s": r["cpu_s"]} for r in design["search"]["rungs"]],
               answers=[{"pattern": b["pattern"], "mu_s": b["mu_s"], "reps": b["reps"]} for b in design["best"]])
    first = design["best"][0]["pattern"]
    out, _, code = timed([a.springblock, "run", "--N", "360", "--length", "7.2cm", "--pattern", first, "--reps",
                          str(RECHECK_REPS), "--seed", str(RECHECK_SEED), "--threads", str(a.threads), "--json"])
    if code != 0:
        sys.exit(f"design_query: the re-simulation of {first} failed ({code})")
    mu_s = json.loads(out)["mu_s"]
    doc["recheck"] = {"pattern": first, "reps": RECHECK_REPS, "seed": RECHECK_SEED, "mu_s": mu_s["mean"],
                      "mu_s_sem": mu_s["sem"], "target": design["target"], "published": published(first)}
    doc["load_end"] = load_average()
    write_atomic(a.out, json.dumps(doc, indent=1) + "\n")
    print(f"design_query: wrote {a.out}", file=sys.stderr)


if __name__ == "__main__":
    main()
