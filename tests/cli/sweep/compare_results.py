#!/usr/bin/env python3
"""Exit 0 when two sweep results files (or two `springblock run --json` outputs) hold the same
numbers, bit for bit.

Usage: compare_results.py A B
Everything but what depends on who ran a unit and when (wall and CPU seconds, the rank, timed
work) must be equal: Python reads each double from its shortest round-trip text, so == on the
parsed values is an exact comparison. The files must hold at least one measured mu_s, so that a
sweep that measured nothing cannot pass as "identical".
"""
import json
import sys

VOLATILE = {"wall_s", "cpu_s", "rank", "wall_seconds", "threads", "provenance"}


def scrub(x, parent=""):
    if isinstance(x, dict):
        # Work counters are compared; the work times (present only when timed) are not.
        return {k: scrub(v, k) for k, v in x.items()
                if k not in VOLATILE and not (parent == "work" and k.endswith("_s"))}
    if isinstance(x, list):
        return [scrub(v) for v in x]
    return x


def scenes(path):
    with open(path) as f:
        lines = [json.loads(line) for line in f if line.strip()]
    if len(lines) == 1 and "runs" in lines[0]:  # one ensemble (springblock run --json)
        return [scrub(lines[0])]
    if not lines or lines[0].get("kind") != "sweep":
        sys.exit(f"{path}: not a sweep results file")
    return [scrub(line) for line in lines[1:]]


def main():
    a, b = scenes(sys.argv[1]), scenes(sys.argv[2])
    if not any(s["mu_s"]["mean"] is not None for s in a):
        sys.exit(f"{sys.argv[1]}: no scene measured mu_s; nothing to compare")
    if len(a) != len(b):
        sys.exit(f"{len(a)} scenes against {len(b)}")
    for i, (sa, sb) in enumerate(zip(a, b)):
        if sa != sb:
            keys = sorted(k for k in sa if sa.get(k) != sb.get(k))
            sys.exit(f"scene {i} differs in {keys}")
    print(f"{len(a)} scenes identical")


main()
