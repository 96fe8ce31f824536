#!/usr/bin/python3
"""Cost of long chains run to their first slip, against the number of blocks (`make bench`; the
documentation's cost page quotes it through python3 -m tools.first_slip_cost).

Each surface (smooth, periodic:10,10, hierarchical:8,2 and hierarchical:30,10 by default) and
each N (10,000, 30,000 and 100,000 by default) is one repetition in its own process:

  springblock run --N N --length L_x [--pattern P] --stop-after-mu-s true --reps 1 --seed 1
                  --threads 1 --json

at the paper's block size l_x = 0.02 cm, so the chain grows with N: L_x = N x 0.02 cm. Per point
the row keeps the child's user + system CPU time and its maximum resident set (wait4(2)), the
wall time, and from the JSON mu_s, t_peak and the work counts of the repetition (switch
instants, mu(t) samples, block-slip episodes). With --reps-per-point K every point is run K
times, in K rounds that each visit every point once (a change in the machine's other load hits
all points alike); the row gives the median CPU time and the largest peak memory. The build
measured is the JSON's provenance (version and commit, `-dirty` for local changes).

Usage: python3 -m bench.first_slip_scaling --springblock BIN [--surfaces smooth periodic:10,10 ...]
           [--sizes 10000 30000 100000] [--reps-per-point 1]
           [--out JSON]   (the rows and where they were measured, for python3 -m tools.first_slip_cost)
"""
import argparse
import json
import os
import statistics
import sys
import time

from bench.child import run_child
from tools.generated_block import write_atomic
from tools.machine import load_average, machine

SURFACES = ["smooth", "periodic:10,10", "hierarchical:8,2", "hierarchical:30,10"]
SIZES = [10000, 30000, 100000]
BLOCK_CM = 0.02  # the paper's l_x: a longer chain is a longer sample, not finer blocks
TEMPLATE = ["springblock", "run", "--N", "{N}", "--length", "{N*0.02}cm", "[--pattern {surface}]",
            "--stop-after-mu-s", "true", "--reps", "1", "--seed", "1", "--threads", "1", "--json"]
# Counts of runs[0].work kept per row: how many events the first slip took.
WORK = ("switch_instants", "samples", "slip_starts")


def command(springblock, surface, n):
    cmd = [springblock, "run", "--N", str(n), "--length", f"{n * BLOCK_CM:g}cm"]
    if surface != "smooth":
        cmd += ["--pattern", surface]
    return cmd + ["--stop-after-mu-s", "true", "--reps", "1", "--seed", "1", "--threads", "1", "--json"]


def measure(springblock, surface, n):
    """One repetition to the first slip in its own process: its costs and what it reported."""
    t0 = time.monotonic()
    try:
        out, usage, code = run_child(command(springblock, surface, n), capture=True)
    except OSError as e:  # e.g. the binary being relinked under the benchmark
        sys.exit(f"first_slip_scaling: cannot run {springblock}: {e}")
    wall = time.monotonic() - t0
    if code != 0:
        # springblock's exit 2 is bad input refused before running: here, a surface it does not know.
        why = f"refused the scene (is {surface} a surface?)" if code == 2 else f"failed (exit {code})"
        print(f"first_slip_scaling: {' '.join(command(springblock, surface, n))}: {why}", file=sys.stderr)
        sys.exit(2 if code == 2 else 1)
    doc = json.loads(out)
    run = doc["runs"][0]
    return {"cpu_s": usage.ru_utime + usage.ru_stime, "wall_s": wall, "peak_rss_mb": usage.ru_maxrss / 1024,
            "run_cpu_s": run["cpu_s"], "mu_s": run["mu_s"], "t_peak_s": run["t_peak_s"],
            **{k: run["work"][k] for k in WORK}}, doc["provenance"]


def row(surface, n, runs):
    """The point's row from its K runs: median CPU (and the wall time of that run), largest peak."""
    mid = sorted(runs, key=lambda r: r["cpu_s"])[(len(runs) - 1) // 2]
    if any(r[k] != runs[0][k] for r in runs for k in WORK):
        print(f"first_slip_scaling: {surface} N={n}: repetitions of one seed did different work", file=sys.stderr)
    return {"surface": surface, "N": n, "length_cm": n * BLOCK_CM, "cpu_s": statistics.median(r["cpu_s"] for r in runs),
            "cpu_s_runs": [r["cpu_s"] for r in runs], "wall_s": mid["wall_s"],
            "peak_rss_mb": max(r["peak_rss_mb"] for r in runs), "run_cpu_s": mid["run_cpu_s"],
            **{k: runs[0][k] for k in ("mu_s", "t_peak_s", *WORK)}}


def arguments(argv):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--springblock", required=True)
    ap.add_argument("--surfaces", nargs="+", default=SURFACES)
    ap.add_argument("--sizes", type=int, nargs="+", default=SIZES)
    ap.add_argument("--reps-per-point", type=int, default=1)
    ap.add_argument("--out")
    a = ap.parse_args(argv)
    if not (os.path.isfile(a.springblock) and os.access(a.springblock, os.X_OK)):
        ap.error(f"--springblock {a.springblock}: not an executable file")
    if min(a.sizes) < 2 or len(set(a.sizes)) != len(a.sizes):
        ap.error(f"--sizes {' '.join(map(str, a.sizes))}: distinct numbers of blocks, each at least 2")
    if a.reps_per_point < 1:
        ap.error(f"--reps-per-point {a.reps_per_point}: at least 1")
    if len(set(a.surfaces)) != len(a.surfaces) or any(not s or " " in s for s in a.surfaces):
        ap.error(f"--surfaces {' '.join(a.surfaces)}: distinct surfaces, each one word (smooth, periodic:NP,NG, ...)")
    return a


def main(argv=None):
    a = arguments(argv)
    sizes = sorted(a.sizes)
    doc = {"machine": machine(), "load_start": load_average(), "command": TEMPLATE, "block_cm": BLOCK_CM,
           "springblock": os.path.abspath(a.springblock), "reps_per_point": a.reps_per_point,
           "surfaces": a.surfaces, "sizes": sizes}
    runs = {(s, n): [] for s in a.surfaces for n in sizes}
    print(f"{'round':>5}  {'surface':<20} {'N':>7}  {'CPU':>8}  {'wall':>8}  {'peak RSS':>9}  "
          f"{'switch instants':>15}  {'mu_s':>6}", flush=True)
    for k in range(a.reps_per_point):
        for n in sizes:  # smallest first: a surface springblock refuses fails in a second
            for s in a.surfaces:
                r, provenance = measure(a.springblock, s, n)
                runs[(s, n)].append(r)
                doc.setdefault("build", {key: provenance.get(key) for key in ("version", "commit")})
                print(f"{k + 1:>5}  {s:<20} {n:>7}  {r['cpu_s']:>6.2f} s  {r['wall_s']:>6.2f} s  "
                      f"{r['peak_rss_mb']:>6.1f} MB  {r['switch_instants']:>15}  {r['mu_s']:>6.4f}", flush=True)
    doc["rows"] = [row(s, n, runs[(s, n)]) for s in a.surfaces for n in sizes]
    doc["load_end"] = load_average()
    if a.out:
        write_atomic(a.out, json.dumps(doc, indent=1) + "\n")
        print(f"first_slip_scaling: wrote {a.out}", file=sys.stderr)


if __name__ == "__main__":
    main()
