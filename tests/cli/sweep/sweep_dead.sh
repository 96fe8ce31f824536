#!/usr/bin/env bash
# A worker rank killed in the middle of an MPI sweep, under an mpirun that keeps the job alive
# (Open MPI 4: --enable-recovery --mca orte_abort_on_non_zero_status 0): rank 0 notices the
# silence within --dead-after (2 s here) plus the polling delay, deals the dead rank's units to the
# others, and the sweep completes with the numbers of an undisturbed run, no unit counted twice.
# Ctrl-C leaves a checkpoint that --resume completes with the same numbers; SIGINT to rank 0 exits
# 130 as in one process (to mpirun: 1, Open MPI's own status, see below).
# Usage: sweep_dead.sh SPRINGBLOCK PYTHON MPIEXEC
set -u
sb=$1 py=$2 mpirun=$3
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../.." && pwd)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail=0
limit=2
recover=(--enable-recovery --mca orte_abort_on_non_zero_status 0)

# 24 units of 0.2 to 0.5 s on 3 ranks of one thread: the kill comes with most units still to run.
cat >"$dir/k.toml" <<'TOML'
[base]
N = 60
duration = "60t0"
velocity = "5cm/s"
reps = 8
seed = 3
[axes]
pattern = ["smooth", "periodic:3,1", "hierarchical:2,2"]
TOML
"$sb" sweep "$dir/k.toml" --threads 2 --out "$dir/clean.jsonl" >/dev/null 2>&1 || { echo "FAIL clean sweep"; exit 1; }

# The pid of rank 1 of the running sweep of k.toml (found by its environment), once the
# checkpoint shows it holding a unit.
rank1_when_busy() {
  local victim="" i=0 p
  while [ -z "$victim" ] && [ $i -lt 1000 ]; do
    for p in $(pgrep -f "sweep $dir/k.toml"); do
      tr '\0' '\n' <"/proc/$p/environ" 2>/dev/null | grep -qx 'OMPI_COMM_WORLD_RANK=1' && victim=$p
    done
    i=$((i + 1))
  done
  while ! grep -qs '"rank":1' "$dir/k.jsonl.checkpoint" && [ $i -lt 2000 ]; do sleep 0.01; i=$((i + 1)); done
  echo "$victim"
}

"$mpirun" --oversubscribe --allow-run-as-root "${recover[@]}" -np 3 "$sb" sweep "$dir/k.toml" --threads 1 \
  --dead-after $limit --out "$dir/k.jsonl" >"$dir/out" 2>"$dir/err" &
job=$!
victim=$(rank1_when_busy)
[ -n "$victim" ] || { echo "FAIL rank 1 not found"; kill -TERM $job; exit 1; }
kill -9 "$victim"
killed=$(date +%s.%N)
detected=""
for _ in $(seq 1 300); do
  grep -q "rank 1 stopped answering" "$dir/err" && { detected=$(date +%s.%N); break; }
  sleep 0.05
done
wait $job
if [ -z "$detected" ]; then
  echo "FAIL rank 0 did not report rank 1 dead"; cat "$dir/err"; fail=1
else
  "$py" - "$killed" "$detected" "$limit" <<'PY' || fail=1
import sys
killed, detected, limit = map(float, sys.argv[1:])
took = detected - killed
print(f"rank 1 SIGKILLed: rank 0 said so {took:.2f} s later (limit {limit:.0f} s of silence)")
# The silence began at its last message, before the kill; 1 s covers polling and a loaded machine.
if took > limit + 1:
    sys.exit("FAIL the dead rank was noticed too late")
PY
fi
grep -q "rank 1 stopped answering: silent [0-9.]* s (limit 2.0 s), taken for dead; its unit(s) [0-9]" "$dir/err" ||
  { echo "FAIL the units rank 1 held were not named"; cat "$dir/err"; fail=1; }
[ -e "$dir/k.jsonl" ] || { echo "FAIL the sweep did not complete without rank 1"; cat "$dir/err"; fail=1; }
if [ -e "$dir/k.jsonl" ]; then
  "$py" - "$dir/k.jsonl" <<'PY' || fail=1
import json, sys
lines = open(sys.argv[1]).read().splitlines()
header = json.loads(lines[0])
if header["lost_ranks"] != [1] or header["computed_units"] != 24:
    sys.exit(f"FAIL header: lost_ranks {header['lost_ranks']}, computed_units {header['computed_units']}")
units = [(r["scene"], r["rep"]) for l in lines[1:] for r in json.loads(l)["runs"]]
if sorted(units) != sorted(set(units)) or len(units) != 24:
    sys.exit(f"FAIL {len(units)} runs, {len(set(units))} distinct: a unit was lost or counted twice")
PY
  "$py" "$here/compare_results.py" "$dir/clean.jsonl" "$dir/k.jsonl" || { echo "FAIL results without rank 1 differ"; fail=1; }
fi

# A rank stalled past the limit (SIGSTOP; SIGCONT once rank 0 has said it is taken for dead, while
# rank 0 still deals: 72 units) is told to stop when it speaks again, and what it brings is
# dropped: every unit counts once. (One that wakes after rank 0 has finished dealing would find no
# one to answer it: the job would not end; see mpi_scheduler.hpp.)
sed 's/^reps = 8/reps = 24/' "$dir/k.toml" >"$dir/s.toml"
"$sb" sweep "$dir/s.toml" --threads 2 --out "$dir/s_clean.jsonl" >/dev/null 2>&1 || { echo "FAIL clean sweep"; exit 1; }
"$mpirun" --oversubscribe --allow-run-as-root "${recover[@]}" -np 3 "$sb" sweep "$dir/s.toml" --threads 1 \
  --dead-after $limit --out "$dir/s.jsonl" >/dev/null 2>"$dir/err5" &
job=$!
victim=""
for _ in $(seq 1 500); do
  for p in $(pgrep -f "sweep $dir/s.toml"); do
    tr '\0' '\n' <"/proc/$p/environ" 2>/dev/null | grep -qx 'OMPI_COMM_WORLD_RANK=1' && victim=$p
  done
  [ -n "$victim" ] && grep -qs '"rank":1' "$dir/s.jsonl.checkpoint" && break
  sleep 0.01
done
kill -STOP "$victim"
for _ in $(seq 1 300); do grep -q "rank 1 stopped answering" "$dir/err5" && break; sleep 0.02; done
kill -CONT "$victim"
wait $job
grep -q "rank 1 was silent too long and was taken for dead.*it stops" "$dir/err5" ||
  { echo "FAIL the stalled rank was not told to stop"; cat "$dir/err5"; fail=1; }
"$py" "$here/compare_results.py" "$dir/s_clean.jsonl" "$dir/s.jsonl" || { echo "FAIL results with a stalled rank differ"; fail=1; }

# Ctrl-C while units run. A terminal's Ctrl-C reaches mpirun alone (the ranks have process groups
# of their own), and Open MPI 4.1's mpirun then ends the job with exit status 1 whatever the ranks
# say (it cannot forward SIGINT: ess_base_forward_signals refuses it), and its SIGKILL may come
# before rank 0, stopped by its SIGTERM, has said how to resume; the checkpoint holds every unit
# finished. SIGINT to rank 0 itself exits 130 with that message, as in one process.
rank0() {
  local p
  for p in $(pgrep -f "sweep $dir/k.toml"); do
    tr '\0' '\n' <"/proc/$p/environ" 2>/dev/null | grep -qx 'OMPI_COMM_WORLD_RANK=0' && echo "$p"
  done
}
for target in mpirun rank0; do
  rm -f "$dir/k.jsonl"*
  "$mpirun" --oversubscribe --allow-run-as-root -np 3 "$sb" sweep "$dir/k.toml" --threads 1 --out "$dir/k.jsonl" \
    >/dev/null 2>"$dir/err2" &
  job=$!
  rank1_when_busy >/dev/null
  if [ $target = mpirun ]; then kill -INT $job; else kill -INT "$(rank0)"; fi
  wait $job
  rc=$?
  echo "SIGINT to $target: exit $rc"
  [ $target = mpirun ] && [ $rc -eq 0 ] && { echo "FAIL Ctrl-C to mpirun exited 0"; fail=1; }
  [ $target = rank0 ] && [ $rc -ne 130 ] && { echo "FAIL SIGINT to rank 0 exited $rc, not 130"; cat "$dir/err2"; fail=1; }
  # mpirun's SIGKILL may come before rank 0 has said it; the checkpoint is written as units finish.
  [ $target = rank0 ] && ! grep -q "interrupted; .* Run the same command with --resume" "$dir/err2" &&
    { echo "FAIL rank 0 did not say how to resume"; cat "$dir/err2"; fail=1; }
  "$mpirun" --oversubscribe --allow-run-as-root -np 2 "$sb" sweep "$dir/k.toml" --threads 1 --out "$dir/k.jsonl" \
    --resume >/dev/null 2>"$dir/err3" || { echo "FAIL resume after SIGINT to $target"; cat "$dir/err3"; fail=1; }
  "$py" "$here/compare_results.py" "$dir/clean.jsonl" "$dir/k.jsonl" >/dev/null || { echo "FAIL resumed results differ"; fail=1; }
done

[ $fail -eq 0 ] && echo "a killed worker rank's units were dealt again, same numbers; an interrupted MPI sweep resumes"
exit $fail
