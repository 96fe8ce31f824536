#!/usr/bin/python3
"""Strong scaling of `springblock sweep` over MPI ranks and rank 0's cost per unit (`make bench`;
the documentation's cost page quotes it through python3 -m tools.sweep_cost).

Three measurements, written to one JSON document with where and when they were taken:
  * pairs: examples/sweep_scaling.toml on 1 rank and on 2 ranks, one thread each, run in
    interleaved pairs so that a change in the machine's other load hits both members of a pair;
  * units: each unit's wall time in the first one-rank run (how uneven the work is);
  * tiny: 20,000 units of well under a millisecond on 2 ranks, so that the coordinator, not the
    simulation, is busy; dealt in batches (--batch-ms 50, the default) and one unit per request
    (--batch-ms 0). Rank 0's time on messages and on the checkpoint comes from the results
    header; the bytes per record and per line of the results file from the file itself.

Usage: python3 -m bench.sweep_scaling --springblock BIN --out JSON [--pairs 3]
                                      [--mpirun "mpirun --oversubscribe"]
"""
import argparse
import json
import os
import shlex
import subprocess
import sys
import tempfile

from tools.generated_block import write_atomic
from tools.machine import REPO, load_average, machine

SCALING_SWEEP = os.path.join(REPO, "examples", "sweep_scaling.toml")
TINY_UNITS = 20000
BATCH_MS = (50, 0)
# Open MPI refuses to start as root unless told twice; CI containers run as root.
MPI_ENV = dict(os.environ, **({"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1"}
                              if os.geteuid() == 0 else {}))


def sweep(cmd, toml, out, *extra):
    """The results file's lines (header first) of one sweep run by cmd (a list)."""
    p = subprocess.run([*cmd, "sweep", toml, "--threads", "1", "--out", out, *extra], env=MPI_ENV,
                       stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if p.returncode != 0:
        sys.exit(f"sweep_scaling: {' '.join(cmd)} sweep {toml} failed ({p.returncode}): {p.stderr[-500:]}")
    with open(out) as f:
        return [json.loads(line) for line in f]


def tiny(mpi, springblock, d, batch_ms):
    toml, out = os.path.join(d, "tiny.toml"), os.path.join(d, "tiny.jsonl")
    with open(toml, "w") as f:
        f.write(f'[base]\nN = 4\nduration = "1t0"\nreps = {TINY_UNITS}\nseed = 1\n')
    lines = sweep(mpi + [springblock], toml, out, "--batch-ms", str(batch_ms))
    head, runs = lines[0], [r for scene in lines[1:] for r in scene["runs"]]
    record_bytes = sum(len(json.dumps(r, separators=(",", ":"))) + 1 for r in runs) / len(runs)
    row = {key: head[key] for key in ("units", "computed_units", "wall_s", "messages", "message_s", "checkpoint_s")}
    row.update(batch_ms=batch_ms, units_by_rank_1=sum(1 for r in runs if r["rank"] != 0),
               record_bytes=record_bytes, results_bytes_per_unit=os.path.getsize(out) / head["units"])
    os.remove(out)
    return row


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--springblock", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--pairs", type=int, default=3)
    ap.add_argument("--mpirun", default="mpirun --oversubscribe")
    a = ap.parse_args(argv)
    mpi = shlex.split(a.mpirun) + ["-np", "2"]
    doc = {"machine": machine(), "load_start": load_average(), "sweep": os.path.relpath(SCALING_SWEEP, REPO),
           "pairs": [], "tiny": []}
    with tempfile.TemporaryDirectory() as d:
        p1, p2 = os.path.join(d, "p1.jsonl"), os.path.join(d, "p2.jsonl")
        for i in range(a.pairs):
            one = sweep([a.springblock], SCALING_SWEEP, p1)
            two = sweep(mpi + [a.springblock], SCALING_SWEEP, p2)
            doc["pairs"].append({"one_rank_s": one[0]["wall_s"], "two_ranks_s": two[0]["wall_s"]})
            if i == 0:
                doc["unit_wall_s"] = sorted(r["wall_s"] for scene in one[1:] for r in scene["runs"])
            print(f"sweep_scaling: pair {i + 1}/{a.pairs}: {one[0]['wall_s']:.2f} s on 1 rank, "
                  f"{two[0]['wall_s']:.2f} s on 2", file=sys.stderr)
        for ms in BATCH_MS:
            doc["tiny"].append(tiny(mpi, a.springblock, d, ms))
    doc["load_end"] = load_average()
    write_atomic(a.out, json.dumps(doc, indent=1) + "\n")
    print(f"sweep_scaling: wrote {a.out}", file=sys.stderr)


if __name__ == "__main__":
    main()
