#!/usr/bin/env python3
"""A table row read from another target's document (repro::table_scenes_reading: tab_pat0's and
tab_pat1's rows from the sensitivity study, which runs them with the rows' own seeds) must be the
very simulation the table would run itself: the same statistics and the same per-repetition
numbers, to the last bit. Runs tab_pat0 twice at the quick tier on one such row, once given the
study's document and once not, and compares. Made to fail by a study that runs its surfaces with
another seed than the rows' (the row is then not read from it, and this test says so), or by
reading a row off a shared trajectory that is not the row's own run.

usage: borrowed_rows_are_own_runs.py <dir of the target programs> <tables dir>"""
import json
import os
import subprocess
import sys
import tempfile

VOLATILE = {"cpu_s", "wall_s", "rhs_evals", "steps", "switches", "work"}


def run(bindir, target, out, *args):
    cmd = [os.path.join(bindir, target), "--tier", "quick", "--threads", "2", "--out", out, *args]
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"FAIL: {' '.join(cmd)} exited {p.returncode}:\n{p.stderr[-2000:]}")
    with open(os.path.join(out, f"{target}.json")) as f:
        return json.load(f)


def record(doc, scene_id):
    return next(s for s in doc["scenes"] if s["id"] == scene_id)


def comparable(rec):
    """The numbers of a record, without what measures the run rather than its result (a record
    read off a longer shared trajectory has no cost of its own)."""
    r = rec["result"]
    runs = [{k: v for k, v in x.items() if k not in VOLATILE} for x in r["runs"]]
    return {"mu_s": r["mu_s"], "mu_d": r["mu_d"], "runs": runs, "seed": r["scene"]["seed"]}


def main():
    bindir, tables = sys.argv[1], sys.argv[2]
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        d = lambda name: os.path.join(tmp, name)  # noqa: E731
        # The source: the smooth surface's baseline and the 6 t0 run it is read off.
        run(bindir, "sensitivity", d("sens"), "--only", "smooth__baseline,smooth__duration=6t0")
        src = os.path.join(d("sens"), "sensitivity.json")
        table = os.path.join(tables, "published_tab_pat0.tsv")
        read = run(bindir, "tab_pat0", d("read"), "--table", table, "--only", "pat0_r01", "--input", src)
        own = run(bindir, "tab_pat0", d("own"), "--table", table, "--only", "pat0_r01")
        a, b = record(read, "pat0_r01"), record(own, "pat0_r01")
        if a.get("borrowed_from") != "sensitivity/smooth__baseline":
            failures.append(f"tab_pat0/pat0_r01 not read from the sensitivity study: {a.get('borrowed_from')}")
        elif comparable(a) != comparable(b):
            failures.append("tab_pat0/pat0_r01 read from the sensitivity study differs from its own run")
    for f in failures:
        print("FAIL:", f)
    if not failures:
        print("tab_pat0/pat0_r01 read from the sensitivity study equals its own run")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
