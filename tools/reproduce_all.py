#!/usr/bin/python3
"""Build every reproduction target in order, with overall progress and ETA, then the summary.

Each target is a CMake custom target (reproduce_<name>), so an up-to-date JSON is not rebuilt.
The ETA weights targets by their wall time in the previous run of the same tier (stored in
<build>/reproduce/timings.json); on a first run every target counts the same.
Usage: reproduce_all.py BUILD_DIR [targets to build at the end if the build defines them,
       e.g. figures report]
"""
import json
import os
import subprocess
import sys
import time


def fmt(s):
    return f"{s:.0f}s" if s < 120 else f"{s / 60:.1f}min" if s < 7200 else f"{s / 3600:.1f}h"


def cache_value(build, key):
    with open(os.path.join(build, "CMakeCache.txt")) as f:
        for line in f:
            if line.startswith(key + ":"):
                return line.split("=", 1)[1].strip()
    return "?"


def main():
    build = sys.argv[1]
    extra = sys.argv[2:]
    rdir = os.path.join(build, "reproduce")
    names = [n.strip() for n in open(os.path.join(rdir, "targets.txt")) if n.strip()]
    tier = cache_value(build, "SPRINGBLOCK_TIER")
    tpath = os.path.join(rdir, "timings.json")
    timings = json.load(open(tpath)) if os.path.exists(tpath) else {}
    past = timings.get(tier, {})
    weight = {n: past.get(n, 1.0 if not past else max(past.values())) for n in names}
    total = sum(weight.values())
    t0 = time.time()
    done = 0.0
    print(f"reproduce-all: {len(names)} targets at tier '{tier}'", flush=True)
    for i, n in enumerate(names, 1):
        elapsed = time.time() - t0
        eta = elapsed * (total - done) / done if done > 0 and elapsed > 1 else None
        print(f"\n=== [{i}/{len(names)}] {n}  (elapsed {fmt(elapsed)}, ETA {fmt(eta) if eta else '?'})", flush=True)
        start = time.time()
        rc = subprocess.call(["cmake", "--build", build, "--target", f"reproduce_{n}"])
        if rc != 0:
            print(f"reproduce-all: target {n} failed (exit {rc})", file=sys.stderr)
            return rc
        wall = time.time() - start
        if wall > 2:  # an up-to-date target says nothing about its cost
            past[n] = wall
        done += weight[n]
    timings[tier] = past
    tmp = tpath + ".tmp"
    json.dump(timings, open(tmp, "w"), indent=1)
    os.replace(tmp, tpath)
    # The summary, figure scripts and report are independent per figure: run them in parallel.
    jobs = ["-j", str(os.cpu_count() or 2)]
    rc = subprocess.call(["cmake", "--build", build, "--target", "reproduce-summary"] + jobs)
    defined = subprocess.run(["cmake", "--build", build, "--target", "help"], capture_output=True,
                             text=True).stdout
    for t in extra:
        if f"... {t}\n" in defined or f" {t}:" in defined:
            rc = rc or subprocess.call(["cmake", "--build", build, "--target", t] + jobs)
    print(f"\nreproduce-all: finished in {fmt(time.time() - t0)} (tier {tier}); "
          f"summary in {os.path.join(rdir, 'summary.tsv')}")
    return rc


if __name__ == "__main__":
    sys.exit(main())
