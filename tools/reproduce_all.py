#!/usr/bin/python3
"""make reproduce-all: build the drivers, run every figure/table target, compare, draw, report.

What a user sees is one line per step: each target with its wall time and the verdicts of the
published numbers and claims it carries, then the figures and the report, and while a step runs,
one progress line with an ETA over the whole job. Everything the tools print goes to
<build>/logs/<step>.log; when a step fails its log's tail is shown.

The ETA weights the targets by their wall time in the previous run of the same tier
(<build>/reproduce/timings.json) and follows each target's own progress (its "NN.N%" lines).
With --mpirun "mpirun -np 4" each reproduction target is started by that launcher: its rank 0 deals
the target's repetitions to every rank and alone writes its document, which holds the numbers of a
run in one process (its provenance records the rank count).
Usage: python3 -m tools.reproduce_all BUILD_DIR [--jobs N] [--mpirun LAUNCHER] [--studies]
"""
import argparse
import json
import os
import re
import shlex
import shutil
import subprocess
import sys
import time

from tools import reproduction_counts  # verdict counts per target, from the checker
from tools.build_cache import cache_value

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)

PERCENT = re.compile(rb"(\d+(?:\.\d+)?)%")
START = re.compile(rb"Reproducing (\S+) \(tier")  # the COMMENT of each target's custom command


def fmt(s):
    return f"{s:.0f} s" if s < 120 else f"{s / 60:.1f} min" if s < 7200 else f"{s / 3600:.1f} h"


class Progress:
    """One status line: rewritten in place on a terminal, printed once per step otherwise."""

    def __init__(self, total_weight):
        self.total, self.done, self.t0 = total_weight, 0.0, time.time()
        self.tty = sys.stderr.isatty()
        self.shown = ""

    def eta(self, current):
        elapsed = time.time() - self.t0
        frac = (self.done + current) / self.total if self.total > 0 else 0
        return fmt(elapsed * (1 - frac) / frac) if frac > 0.02 and elapsed > 2 else "?"

    def show(self, label, current_weight=0.0, force=False):
        text = f"  ... {label}  (elapsed {fmt(time.time() - self.t0)}, ETA {self.eta(current_weight)})"
        if self.tty:
            sys.stderr.write("\r" + text.ljust(len(self.shown)) + "\r")
            sys.stderr.flush()
            self.shown = text
        elif force:
            print(text, file=sys.stderr, flush=True)

    def clear(self):
        if self.tty and self.shown:
            sys.stderr.write("\r" + " " * len(self.shown) + "\r")
            sys.stderr.flush()
            self.shown = ""


def run_logged(cmd, log_path, on_line=None, cwd=None):
    """Run cmd with stdout and stderr into log_path; on_line(bytes) sees each line as it comes
    (carriage returns, as in progress lines, end a line too)."""
    with open(log_path, "wb") as log:
        p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, cwd=cwd)
        pending = b""
        while True:
            chunk = p.stdout.read1(65536)
            if not chunk:
                break
            log.write(chunk)
            if on_line:
                pending += chunk.replace(b"\r", b"\n")
                *lines, pending = pending.split(b"\n")
                for ln in lines:
                    on_line(ln)
        if on_line and pending:
            on_line(pending)
        return p.wait()


def tail(path, lines=30):
    with open(path, "rb") as f:
        text = f.read().decode(errors="replace").replace("\r", "\n")
    return "\n".join([ln for ln in text.splitlines() if ln.strip()][-lines:])


def fail(step, log):
    print(f"reproduce-all: {step} failed; last lines of {log}:", file=sys.stderr)
    print(tail(log), file=sys.stderr)
    return 1


def read_names(rdir, listing):
    return [n.strip() for n in open(os.path.join(rdir, listing)) if n.strip()]


def up_to_date(cmd):
    """Whether a target's output exists and no input of its command (the driver program, the
    tables and documents it reads) is newer: make's rule for its custom command."""
    try:
        out = os.path.getmtime(cmd["output"])
    except OSError:
        return False
    # A missing input: out of date, and the target's own run says what it lacks.
    return all(os.path.exists(d) and os.path.getmtime(d) <= out for d in cmd["depends"])


def run_targets(build, tier, logs, listing, describe, launcher=()):
    """The targets of the listing, one after the other (each runs its repetitions on every core):
    a line per target as it finishes, one progress line meanwhile, each target's output in
    logs/<target>.log. The reproduction targets run their commands from
    <build>/reproduce/commands.json directly, each started by `launcher` (the words of an mpirun
    command) when one is given; the studies go through the build tool (one of them is a script
    target). Returns non-zero on the first failure."""
    rdir = os.path.join(build, "reproduce")
    names = read_names(rdir, listing)
    commands = json.load(open(os.path.join(rdir, "commands.json"))) if listing == "targets.txt" else None
    tpath = os.path.join(rdir, "timings.json")
    timings = json.load(open(tpath)) if os.path.exists(tpath) else {}
    past = timings.get(tier) or default_weights()
    weight = {n: past.get(n, max(past.values()) if past else 1.0) for n in names}
    progress = Progress(sum(weight.values()))
    cur = {"name": None, "t": 0.0, "log": None}
    seen = []

    def open_target(n, own_log):
        # own_log: the build tool's output is split into per-target logs here; a target run
        # directly writes its log through run_logged.
        seen.append(n)
        cur.update(name=n, t=time.time(), log=open(os.path.join(logs, f"{n}.log"), "wb") if own_log else None)
        progress.show(f"[{len(seen)}/{len(names)}] {n}", force=True)

    def close():
        n = cur["name"]
        if n is None:
            return
        if cur["log"]:
            cur["log"].close()
        wall = time.time() - cur["t"]
        past[n] = wall
        progress.done += weight.get(n, 0.0)
        progress.clear()
        print(f"  {n:<14}{fmt(wall):>8}   {describe(n)}", flush=True)
        cur["name"] = None

    def line(raw):
        m = START.search(raw) if commands is None else None
        if m and m.group(1).decode() in weight:
            close()
            open_target(m.group(1).decode(), True)
        if cur["name"]:
            if cur["log"]:
                cur["log"].write(raw + b"\n")
            # The target's own progress lines ("[fig2] 44 scenes, 51.4% ..."), not make's "[ 86%]".
            hits = PERCENT.findall(raw) if raw.lstrip().startswith(b"[" + cur["name"].encode() + b"]") else []
            if hits:
                frac = min(1.0, float(hits[-1]) / 100)
                progress.show(f"[{len(seen)}/{len(names)}] {cur['name']} {100 * frac:.0f}%",
                              weight[cur["name"]] * frac)

    if commands is None:
        log = os.path.join(logs, listing.replace(".txt", ".log"))
        rc = run_logged(["cmake", "--build", build, "--target"] + [f"reproduce_{n}" for n in names], log, line)
        failed = cur["name"]
        if rc:
            progress.clear()
            return fail(f"target {failed}" if failed else "the reproduction",
                        os.path.join(logs, f"{failed}.log") if failed else log)
    else:
        for n in names:
            cmd = commands[n]
            if up_to_date(cmd):
                continue
            open_target(n, False)
            log = os.path.join(logs, f"{n}.log")
            # In the directory its custom command runs in (CMake's default for it).
            rc = run_logged(list(launcher) + [cmd["program"]] + cmd["args"], log, line, cwd=rdir)
            if rc:
                progress.clear()
                return fail(f"target {n}", log)
            close()
    close()
    for n in names:
        if n not in seen:
            print(f"  {n:<14}{'up to date':>8}   {describe(n)}", flush=True)
    timings[tier] = past
    tmp = tpath + ".tmp"
    json.dump(timings, open(tmp, "w"), indent=1)
    os.replace(tmp, tpath)
    return 0


def write_run_record(rdir, tier, jobs, phases, total, compiled, fresh, mpirun):
    """<build>/reproduce/last_run.json: the wall time of each phase of this run and of each target
    (from timings.json), with the commit, the tier, the core count and the MPI launcher of the
    targets (null: one process each), so that the documentation's
    cost figures are read from a file (tools/readme_cost.py) rather than typed."""
    def git(*args):
        r = subprocess.run(["git", "-C", REPO] + list(args), capture_output=True, text=True)
        return r.stdout.strip() if r.returncode == 0 else "unknown"
    timings = json.load(open(os.path.join(rdir, "timings.json")))
    # This run's targets only: timings.json also keeps weights of names that are no target now.
    names = read_names(rdir, "targets.txt")
    record = {"tier": tier, "jobs": jobs, "cores": os.cpu_count(), "commit": git("rev-parse", "--short", "HEAD"),
              "dirty": bool(git("status", "--porcelain", "--untracked-files=no")),
              "date": time.strftime("%Y-%m-%d"), "total_s": total, "phases_s": phases,
              "compiled_units": compiled, "fresh_build": fresh, "mpirun": mpirun,
              "targets_s": {n: t for n, t in timings.get(tier, {}).items() if n in names}}
    path = os.path.join(rdir, "last_run.json")
    json.dump(record, open(path + ".tmp", "w"), indent=1)
    os.replace(path + ".tmp", path)


def default_weights():
    """Typical target costs on a 2-core machine, for the ETA of a first run (committed beside
    this script, copied from a run's timings.json)."""
    path = os.path.join(HERE, "reproduce_weights.json")
    return json.load(open(path)) if os.path.exists(path) else {}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("build")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    ap.add_argument("--started-at", type=float, default=None, metavar="EPOCH_S",
                    help="when `make reproduce-all` began (before its configure step), so that the "
                         "record's total is the whole command's")
    ap.add_argument("--fresh-build", action="store_true",
                    help="the build tree had no CMake cache before this run (set by the Makefile): the "
                         "run record's whole command is then a fresh clone's cost")
    ap.add_argument("--studies", action="store_true",
                    help="run the optional studies instead and copy their documents to paper/data/")
    ap.add_argument("--mpirun", default=None, metavar="LAUNCHER",
                    help="start every reproduction target with this MPI launcher, e.g. 'mpirun -np 4': its "
                         "repetitions are dealt to the ranks, with the numbers of one process")
    a = ap.parse_args()
    launcher = shlex.split(a.mpirun) if a.mpirun else []
    if a.mpirun is not None and not launcher:
        ap.error("--mpirun needs a launcher, e.g. --mpirun 'mpirun -np 4'")
    if launcher and a.studies:
        ap.error("--mpirun starts the reproduction targets; the studies run through the build tool, in one process each")
    build, jobs = a.build, ["-j", str(a.jobs)]
    logs = os.path.join(build, "logs")
    os.makedirs(logs, exist_ok=True)
    rdir = os.path.join(build, "reproduce")
    tier = cache_value(build, "SPRINGBLOCK_TIER")
    t_start = time.time()
    # The configure step (dependency check, cmake) ran before this script: counted from the
    # Makefile's clock, so that total_s is what `time make reproduce-all` shows.
    phases = {}
    if a.started_at is not None and 0 <= t_start - a.started_at < 3600:
        phases["configure"] = t_start - a.started_at
        t_start = a.started_at

    # Only what the reproduction runs: the simulator and the drivers (tests and benchmarks
    #    are built by `make test` / `make bench`).
    under = f", targets under '{a.mpirun}'" if launcher else ""
    print(f"reproduce-all: tier '{tier}'{under}, logs in {logs}/", flush=True)
    log = os.path.join(logs, "build.log")
    t = time.time()
    if run_logged(["cmake", "--build", build, "--target", "reproduce-programs", "springblock_pattern"] + jobs, log):
        return fail("build", log)
    phases["build"] = time.time() - t
    # How much the build compiled: a fresh clone's cost and an incremental run's differ tenfold.
    compiled = open(log, "rb").read().count(b"Building CXX object")
    for step in ("configure", "build"):
        if step in phases:
            print(f"  {step:<14}{fmt(phases[step]):>8}", flush=True)

    counter = reproduction_counts.Counter(rdir, os.path.join(REPO, "tables"))
    studies = a.studies
    t = time.time()
    rc = run_targets(build, tier, logs, "studies.txt" if studies else "targets.txt",
                     (lambda n: "") if studies else counter.line, launcher)
    if rc:
        return rc
    phases["targets"] = time.time() - t
    if studies:
        # Committed data: the report and figures read paper/data/<study>.json when the build
        # tree has no fresher copy.
        for n in read_names(rdir, "studies.txt"):
            dst = os.path.join(REPO, "paper", "data", f"{n}.json")
            os.makedirs(os.path.dirname(dst), exist_ok=True)
            shutil.copyfile(os.path.join(rdir, n, f"{n}.json"), dst + ".tmp")
            os.replace(dst + ".tmp", dst)
            print(f"  {n}: wrote {os.path.relpath(dst, REPO)} (commit it)", flush=True)
        print(f"reproduce-all: studies done in {fmt(time.time() - t_start)} (tier {tier})", flush=True)
        return 0

    # 3. Summary, figures, report (independent per figure: in parallel).
    progress = Progress(0)
    for step, target in (("summary", "reproduce-summary"), ("figures", "figures"), ("report", "report")):
        log = os.path.join(logs, f"{step}.log")
        t = time.time()
        progress.show(step, force=True)
        rc = run_logged(["cmake", "--build", build, "--target", target] + jobs, log)
        progress.clear()
        if rc:
            return fail(step, log)
        extra = ""
        if step == "summary":
            extra = counter.total_line()
        elif step == "report":
            extra = os.path.join(build, "paper", "report.html")
        phases[step] = time.time() - t
        print(f"  {step:<14}{fmt(phases[step]):>8}   {extra}", flush=True)
    write_run_record(rdir, tier, a.jobs, phases, time.time() - t_start, compiled, a.fresh_build, a.mpirun)
    print(f"reproduce-all: done in {fmt(time.time() - t_start)} (tier {tier}); "
          f"verdicts in {os.path.join(rdir, 'summary.tsv')}", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
