#!/usr/bin/env python3
"""Structural limits of the library, checked by CTest (label fast).

The architecture issue asked for an integrator a newcomer can change: no file under
src/springblock/integrate/ over 300 lines, no function in the library or the shells over 80
lines, and no include cycle among the project's headers. These are checked here rather than by
review so that they stay true. Function extents come from Universal Ctags (its `end` field);
when ctags is missing the function check says so and is skipped (exit 77, CTest's skip code)
instead of passing silently.

Usage: python3 -m tools.check_structure SOURCE_DIR [--report]   (--report prints the longest functions)
"""
import json
import pathlib
import re
import shutil
import subprocess
import sys

MAX_INTEGRATE_FILE_LINES = 300
MAX_FUNCTION_LINES = 80
# Where the function limit applies: the library and the two command-line shells.
FUNCTION_ROOTS = ["src", "reproduce"]
INCLUDE_RE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def cxx_files(root: pathlib.Path, sub: str):
    return sorted(p for p in (root / sub).rglob("*") if p.suffix in (".cpp", ".hpp"))


def long_files(root):
    bad = []
    for p in cxx_files(root, "src/springblock/integrate"):
        n = len(p.read_text().splitlines())
        if n > MAX_INTEGRATE_FILE_LINES:
            bad.append(f"{p.relative_to(root)}: {n} lines (limit {MAX_INTEGRATE_FILE_LINES})")
    return bad


def function_lengths(root):
    ctags = shutil.which("ctags-universal") or shutil.which("ctags")
    if ctags is None:
        return None
    files = [str(p) for sub in FUNCTION_ROOTS for p in cxx_files(root, sub)]
    out = subprocess.run([ctags, "--c++-kinds=f", "--fields=+ne", "--output-format=json", "-f", "-", *files],
                         capture_output=True, text=True, check=True).stdout
    rows = []
    for line in out.splitlines():
        tag = json.loads(line)
        if "end" in tag:
            rows.append((tag["end"] - tag["line"] + 1, str(pathlib.Path(tag["path"]).relative_to(root)),
                         tag["name"], tag["line"]))
    return sorted(rows, reverse=True)


def include_cycles(root):
    """Cycles in the graph header -> project header it includes (src/ only)."""
    src = root / "src"
    graph = {}
    for p in cxx_files(root, "src"):
        rel = str(p.relative_to(src))
        graph[rel] = [inc for inc in INCLUDE_RE.findall(p.read_text()) if (src / inc).exists()]
    cycles, state = [], {}

    def visit(node, path):
        state[node] = 1
        for nxt in graph.get(node, []):
            if state.get(nxt) == 1:
                cycles.append(" -> ".join(path[path.index(nxt):] + [nxt]))
            elif nxt not in state:
                visit(nxt, path + [nxt])
        state[node] = 2

    for node in graph:
        if node not in state:
            visit(node, [node])
    return cycles


def main():
    root = pathlib.Path(sys.argv[1]).resolve()
    failures = long_files(root)
    failures += [f"include cycle: {c}" for c in include_cycles(root)]
    rows = function_lengths(root)
    if rows is not None:
        failures += [f"{path}:{line} {name}: {n} lines (limit {MAX_FUNCTION_LINES})"
                     for n, path, name, line in rows if n > MAX_FUNCTION_LINES]
        if "--report" in sys.argv:
            for n, path, name, line in rows[:15]:
                print(f"{n:4d}  {path}:{line} {name}")
    for f in failures:
        print("structure:", f)
    if failures:
        return 1
    if rows is None:
        print("structure: ctags not found, function lengths not checked (install universal-ctags)")
        return 77
    print("structure: integrate/ files <= %d lines, functions <= %d lines, no include cycle"
          % (MAX_INTEGRATE_FILE_LINES, MAX_FUNCTION_LINES))
    return 0


if __name__ == "__main__":
    sys.exit(main())
