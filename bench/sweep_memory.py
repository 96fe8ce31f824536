#!/usr/bin/python3
"""Peak memory of one `springblock sweep` process against the sweep's size (`make bench` runs it).

Tiny units (4-block chains, 1 t0: well under a millisecond each) so that the coordinator's
bookkeeping, not the simulation, is what grows: SCENES x 1000 repetitions for each size asked
(1e5 and 1e6 units by default). Each sweep runs in its own process, whose maximum resident set
comes from wait4(2); the table gives it with the wall time, and the growth per added unit
between consecutive sizes. Memory bounded by what is in flight means a growth of a few bytes a
unit (the unit's scene, its checkpoint offset, its place in the queue), not its ~0.5 KB record.

Usage: python3 -m bench.sweep_memory --springblock BIN [--units 100000 1000000] [--threads 2]
                                     [--dir DIR]   (DIR gets the files; default: a temporary one)
                                     [--out JSON]  (the rows and where they were measured, for
                                                    python3 -m tools.sweep_cost)
"""
import argparse
import json
import os
import tempfile
import time

from bench.child import run_child
from tools.generated_block import write_atomic
from tools.machine import load_average, machine

REPS = 1000


def sweep_file(path, units):
    scenes = max(1, units // REPS)
    with open(path, "w") as f:
        f.write(f'[base]\nN = 4\nduration = "1t0"\nreps = {min(units, REPS)}\n'
                f'[axes]\nseed = {{ from = 1, to = {scenes}, steps = {scenes} }}\n' if scenes > 1 else
                f'[base]\nN = 4\nduration = "1t0"\nreps = {units}\nseed = 1\n')


def peak(springblock, toml, out, threads):
    """(maximum RSS in MB, wall seconds) of one sweep."""
    t0 = time.monotonic()
    _, usage, code = run_child([springblock, "sweep", toml, "--out", out, "--threads", str(threads)])
    if code != 0:
        raise SystemExit(f"{springblock} sweep {toml} failed ({code})")
    return usage.ru_maxrss / 1024, time.monotonic() - t0


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--springblock", required=True)
    ap.add_argument("--units", type=int, nargs="+", default=[100000, 1000000])
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--dir")
    ap.add_argument("--out")
    a = ap.parse_args()
    doc = {"machine": machine(), "load_start": load_average(), "threads": a.threads, "rows": []}
    with tempfile.TemporaryDirectory() as tmp:
        d = a.dir or tmp
        print(f"{'units':>9}  {'peak RSS':>9}  {'wall':>8}  {'growth per added unit':>22}")
        first = last = None
        for n in a.units:
            toml, out = os.path.join(d, f"mem{n}.toml"), os.path.join(d, f"mem{n}.jsonl")
            sweep_file(toml, n)
            mb, wall = peak(a.springblock, toml, out, a.threads)
            growth = f"{(mb - last[1]) * 1048576 / (n - last[0]):.1f} B" if last else ""
            print(f"{n:>9}  {mb:>6.1f} MB  {wall:>6.1f} s  {growth:>22}", flush=True)
            doc["rows"].append({"units": n, "peak_rss_mb": mb, "wall_s": wall})
            last = (n, mb)
            first = first or last
            for f in (toml, out):
                os.remove(f)
        if len(a.units) > 1:
            print(f"growth from {first[0]} to {last[0]} units: {last[1] - first[1]:.1f} MB (goal: < 50 MB)")
    doc["load_end"] = load_average()
    if a.out:
        write_atomic(a.out, json.dumps(doc, indent=1) + "\n")


if __name__ == "__main__":
    main()
