#!/usr/bin/env bash
# The numbers of the documentation's cost page (docs/cost.md, "Sweeps: memory and strong
# scaling"): strong scaling of examples/sweep_scaling.toml on 1 and 2 ranks (one thread each),
# measured in interleaved pairs so that a change in the machine's other load hits both; the
# per-unit run-time distribution; and rank 0's cost per unit (MPI message, checkpoint append +
# fsync) and output bytes per unit from a sweep of 20,000 tiny units on 2
# ranks, dealt in batches and one at a time.
# Usage: tools/sweep_scaling.sh BUILD_DIR [PAIRS]   (needs mpirun; root needs OMPI_ALLOW_RUN_AS_ROOT*)
set -euo pipefail
sb=$1/src/springblock
pairs=${2:-3}
root=$(cd "$(dirname "$0")/.." && pwd)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
mpi() { mpirun --oversubscribe "$@"; }
py=/usr/bin/python3

echo "machine: $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg) at start"
for i in $(seq "$pairs"); do
  "$sb" sweep "$root/examples/sweep_scaling.toml" --threads 1 --out "$dir/p1.$i.jsonl" >/dev/null
  mpi -np 2 "$sb" sweep "$root/examples/sweep_scaling.toml" --threads 1 --out "$dir/p2.$i.jsonl" >/dev/null
done
"$py" - "$dir" "$pairs" <<'PY'
import json, statistics, sys
d, pairs = sys.argv[1], int(sys.argv[2])
head = lambda p: json.loads(open(p).readline())
for i in range(1, pairs + 1):
    a, b = head(f"{d}/p1.{i}.jsonl")["wall_s"], head(f"{d}/p2.{i}.jsonl")["wall_s"]
    print(f"pair {i}: 1 rank {a:.2f} s, 2 ranks {b:.2f} s, speed-up {a / b:.2f}")
lines = [json.loads(l) for l in open(f"{d}/p1.1.jsonl")][1:]
w = sorted(r["wall_s"] for s in lines for r in s["runs"])
q = lambda f: w[min(len(w) - 1, int(f * len(w)))]
print(f"unit wall times ({len(w)} units, 1 rank): min {w[0]*1e3:.2f} ms, median {q(0.5)*1e3:.1f} ms, "
      f"90% {q(0.9)*1e3:.0f} ms, max {w[-1]*1e3:.0f} ms (max/median {w[-1]/q(0.5):.0f}), sum {sum(w):.2f} s")
PY

# Rank 0's cost per unit: 20,000 units of well under a millisecond, so the coordinator is busy;
# dealt in batches (--batch-ms 50, the default) and one unit per request (--batch-ms 0).
printf '[base]\nN = 4\nduration = "1t0"\nreps = 20000\nseed = 1\n' >"$dir/tiny.toml"
for ms in 50 0; do
mpi -np 2 "$sb" sweep "$dir/tiny.toml" --threads 1 --batch-ms $ms --out "$dir/tiny.jsonl" >/dev/null
"$py" - "$dir/tiny.jsonl" $ms <<'PY'
import json, os, sys
lines = open(sys.argv[1]).read().splitlines()
h = json.loads(lines[0])
runs = [r for l in lines[1:] for r in json.loads(l)["runs"]]
remote = sum(1 for r in runs if r["rank"] != 0)
bytes_unit = sum(len(json.dumps(r, separators=(",", ":"))) + 1 for r in runs) / len(runs)
print(f"tiny units on 2 ranks, --batch-ms {sys.argv[2]}: {h['units']} units in {h['wall_s']:.2f} s = "
      f"{h['units'] / h['wall_s']:.0f} units/s ({remote} by rank 1 in {h['messages']} messages); rank 0 "
      f"{1e6 * h['message_s'] / h['messages']:.1f} us per message, {1e6 * h['message_s'] / max(1, remote):.1f} us "
      f"per unit of rank 1 (receive + decode + answer); checkpoint (assignments, records, grouped fsync) "
      f"{1e6 * h['checkpoint_s'] / h['computed_units']:.1f} us per unit; rank 0 in all "
      f"{1e6 * (h['message_s'] + h['checkpoint_s']) / h['computed_units']:.1f} us per unit; record "
      f"{bytes_unit:.0f} bytes per unit, results file {os.path.getsize(sys.argv[1]) / h['units']:.0f} bytes per unit")
PY
rm -f "$dir/tiny.jsonl"
done
echo "load average $(cut -d' ' -f1-3 /proc/loadavg) at the end"
