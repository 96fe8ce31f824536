#!/usr/bin/env python3
"""Exit 0 when two documents of a reproduction target hold the same results, bit for bit.

Usage: same_documents.py A B
Compared as parsed JSON (Python reads each double from its shortest round-trip text, so == is
exact), without what says who ran it, where and how long: the provenance (host, time, rank
count), wall and CPU seconds, thread counts and the work times (present only when timed; the
work counters are compared). Everything else must be equal, in the same order. A's scenes must
have measured some mu_s, so that two documents of nothing cannot pass as identical.
"""
import json
import sys

RESOURCES = {"provenance", "wall_seconds", "wall_s", "cpu_s", "threads"}


def scrub(x, parent=""):
    if isinstance(x, dict):
        return {k: scrub(v, k) for k, v in x.items()
                if k not in RESOURCES and not (parent == "work" and k.endswith("_s"))}
    if isinstance(x, list):
        return [scrub(v) for v in x]
    return x


def first_difference(a, b, path="$"):
    """The path of the first place where a and b differ, or None."""
    if type(a) is not type(b):
        return path
    if isinstance(a, dict):
        if list(a) != list(b):
            return f"{path} (keys {sorted(set(a) ^ set(b)) or 'in another order'})"
        for k in a:
            d = first_difference(a[k], b[k], f"{path}.{k}")
            if d:
                return d
        return None
    if isinstance(a, list):
        if len(a) != len(b):
            return f"{path} (length {len(a)} against {len(b)})"
        for i, (x, y) in enumerate(zip(a, b)):
            d = first_difference(x, y, f"{path}[{i}]")
            if d:
                return d
        return None
    return None if a == b else f"{path} ({a!r} against {b!r})"


def main():
    a, b = (scrub(json.load(open(p))) for p in sys.argv[1:3])
    scenes = a.get("scenes") or []
    if not any(s["result"]["mu_s"]["mean"] is not None for s in scenes if "result" in s):
        sys.exit(f"{sys.argv[1]}: no scene measured mu_s; nothing to compare")
    where = first_difference(a, b)
    if where:
        sys.exit(f"{sys.argv[1]} and {sys.argv[2]} differ at {where}")
    print(f"{a['target']}: {len(scenes)} scenes identical")


main()
