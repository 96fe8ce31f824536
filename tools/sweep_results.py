#!/usr/bin/python3
"""Read the results of `springblock sweep`, complete or still running.

While a sweep runs, OUT.partial holds its header, with "partial": true, and one line per scene
completed so far, in the order scenes completed: the scene's statistics as in the complete file,
without its "runs" (the unit records are in OUT.checkpoint, and in UNITS.partial with --units).
Lines are appended whole, one write each; a reader that reads while one is being written can find
its beginning without its newline, so a line counts only once its newline is there. When the sweep
completes, OUT appears (written whole, then renamed) with a header without "partial" and every
scene in scene order with its runs, and OUT.partial is removed. An interrupted or killed sweep
leaves OUT.partial and OUT.checkpoint; `--resume` rebuilds OUT.partial from the checkpoint and
goes on appending to it.

read(path) takes OUT or OUT.partial (given OUT while only OUT.partial exists, it reads that) and
returns (header, scene lines sorted by scene index).

Usage: python3 -m tools.sweep_results FILE   (prints what FILE holds; exit 1 when malformed)
"""
import json
import os
import sys


def read(path):
    if not os.path.exists(path) and os.path.exists(path + ".partial"):
        path += ".partial"
    with open(path) as f:
        text = f.read()
    whole = text[:text.rfind("\n") + 1]  # a last line without its newline is still being written
    lines = [json.loads(line) for line in whole.splitlines()]
    if not lines or lines[0].get("kind") != "sweep":
        raise ValueError(f"{path}: not a sweep results file")
    return lines[0], sorted(lines[1:], key=lambda line: line["scene"])


def main():
    header, scenes = read(sys.argv[1])
    state = "partial" if header.get("partial") else "complete"
    print(f"{state}: {len(scenes)} of {header['scenes']} scenes")
    if state == "complete" and len(scenes) != header["scenes"]:
        sys.exit(f"{sys.argv[1]}: a complete file with {len(scenes)} of {header['scenes']} scenes")


if __name__ == "__main__":
    main()
