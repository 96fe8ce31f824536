#!/usr/bin/python3
"""reproduce_all.py runs the targets from <build>/reproduce/commands.json and decides by itself
whether each is up to date; the build tool must agree, or `make test` would run a target again
that reproduce-all left alone (or trust one it should rerun). For every target: the manifest's
verdict (tools/reproduce_all.py up_to_date) against a dry run of its custom target, which prints
the "Reproducing <name>" comment only if make would run it. Exit 77 (skip) for a generator other
than Makefiles, which has no dry run here. Usage: PYTHONPATH=<repository root> commands_agree_with_make.py BUILD_DIR"""
import json
import os
import subprocess
import sys

sys.dont_write_bytecode = True
from tools import reproduce_all as ra  # noqa: E402
from tools.build_cache import cache_value  # noqa: E402


def main():
    build = sys.argv[1]
    if "Makefiles" not in (cache_value(build, "CMAKE_GENERATOR") or ""):
        print("skip: the dry run needs a Makefile generator")
        return 77
    with open(os.path.join(build, "reproduce", "commands.json")) as f:
        commands = json.load(f)
    with open(os.path.join(build, "reproduce", "targets.txt")) as f:
        names = [n.strip() for n in f if n.strip()]
    problems = []
    if sorted(names) != sorted(commands):
        problems.append(f"targets.txt {sorted(names)} but commands.json {sorted(commands)}")
    for n in names:
        cmd = commands.get(n)
        if cmd is None:
            continue
        dry = subprocess.run(["cmake", "--build", build, "--target", f"reproduce_{n}", "--", "-n"],
                             capture_output=True, text=True)
        make_runs = f"Reproducing {n} (tier" in dry.stdout
        if dry.returncode != 0 or make_runs == ra.up_to_date(cmd):
            problems.append(f"{n}: make would {'run' if make_runs else 'not run'} it, the manifest says "
                            f"{'up to date' if ra.up_to_date(cmd) else 'stale'} (exit {dry.returncode})")
        if cmd["output"] != os.path.join(build, "reproduce", n, f"{n}.json"):
            problems.append(f"{n}: output {cmd['output']}")
    for p in problems:
        print("MISMATCH", p)
    print(f"{len(names)} targets, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
