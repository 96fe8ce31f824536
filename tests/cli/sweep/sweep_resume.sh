#!/usr/bin/env bash
# A sweep killed halfway (kill -9, as a dead job; and Ctrl-C, SIGINT) resumes with --resume and
# recomputes only the units its checkpoint lacks: the results header's computed_units must equal
# the units missing from the checkpoint at the kill, a truncated last checkpoint line (a kill
# mid-write) is tolerated, the unit in flight is reported lost, and the numbers equal an
# uninterrupted run's. Usage: sweep_resume.sh SPRINGBLOCK PYTHON
set -u
sb=$1 py=$2
here=$(cd "$(dirname "$0")" && pwd)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail=0

cat >"$dir/r.toml" <<'TOML'
[base]
N = 60
duration = "8t0"
velocity = "5cm/s"
reps = 4
seed = 3
[axes]
pattern = ["smooth", "periodic:3,1", "hierarchical:2,2"]
TOML
units=12
"$sb" sweep "$dir/r.toml" --threads 2 --out "$dir/clean.jsonl" >/dev/null 2>&1 || { echo "FAIL clean sweep"; exit 1; }

finished() { if [ -e "$1" ]; then grep -c '"unit"' "$1"; else echo 0; fi; }
# Starts the sweep on one thread, waits until WANT units are checkpointed, sends SIGNAL.
start_and_kill() {  # SIGNAL WANT
  "$sb" sweep "$dir/r.toml" --threads 1 --out "$dir/r.jsonl" >"$dir/out" 2>"$dir/err" &
  local pid=$! i=0
  while [ "$(finished "$dir/r.jsonl.checkpoint")" -lt "$2" ] && [ $i -lt 500 ]; do sleep 0.01; i=$((i + 1)); done
  kill -"$1" $pid
  wait $pid 2>/dev/null
}

# 1. kill -9 after 3 units: nothing but the checkpoint is left.
start_and_kill KILL 3
[ ! -e "$dir/r.jsonl" ] || { echo "FAIL a killed sweep left a results file"; fail=1; }
done_before=$(finished "$dir/r.jsonl.checkpoint")
lost=$("$py" - "$dir/r.jsonl.checkpoint" <<'PY'
import json, sys
done, handed = set(), set()
for line in open(sys.argv[1]):
    j = json.loads(line)
    if "assigned" in j: handed.add(j["assigned"])
    elif "unit" in j: done.add(j["unit"])
print(len(handed - done))
PY
)
printf '{"unit": 17, "scene": 2, "mu' >>"$dir/r.jsonl.checkpoint"  # cut short mid-write
"$sb" sweep "$dir/r.toml" --threads 2 --out "$dir/r.jsonl" --resume >"$dir/out" 2>"$dir/err" || { echo "FAIL resume"; cat "$dir/err"; exit 1; }
computed=$("$py" -c 'import json,sys; print(json.loads(open(sys.argv[1]).readline())["computed_units"])' "$dir/r.jsonl")
[ "$done_before" -ge 3 ] && [ "$done_before" -lt $units ] || { echo "FAIL the kill came too late ($done_before done)"; fail=1; }
[ "$computed" -eq $((units - done_before)) ] ||
  { echo "FAIL resume computed $computed units, expected $units - $done_before"; fail=1; }
if [ "$lost" -gt 0 ]; then
  grep -q "lost $lost unit(s) in flight (recomputed now): rank 0: " "$dir/err" || { echo "FAIL lost units not reported"; cat "$dir/err"; fail=1; }
fi
echo "killed with $done_before of $units units done, $lost in flight; the resume computed $computed"
"$py" "$here/compare_results.py" "$dir/clean.jsonl" "$dir/r.jsonl" || { echo "FAIL resumed results differ"; fail=1; }
[ ! -e "$dir/r.jsonl.checkpoint" ] || { echo "FAIL the checkpoint outlived the finished sweep"; fail=1; }

# 2. Ctrl-C (SIGINT) after 2 units: exit 130, says what to do, keeps the checkpoint; then resume.
rm -f "$dir/r.jsonl"
start_and_kill INT 2
rc=$?
[ $rc -eq 130 ] || { echo "FAIL interrupted sweep exited $rc, expected 130"; fail=1; }
grep -q -- "--resume" "$dir/err" || { echo "FAIL the interrupt message does not mention --resume"; cat "$dir/err"; fail=1; }
[ ! -e "$dir/r.jsonl" ] || { echo "FAIL an interrupted sweep wrote results"; fail=1; }
done_before=$(finished "$dir/r.jsonl.checkpoint")
"$sb" sweep "$dir/r.toml" --out "$dir/r.jsonl" --resume >/dev/null 2>&1 || { echo "FAIL resume after SIGINT"; exit 1; }
computed=$("$py" -c 'import json,sys; print(json.loads(open(sys.argv[1]).readline())["computed_units"])' "$dir/r.jsonl")
[ "$computed" -eq $((units - done_before)) ] || { echo "FAIL resume after SIGINT computed $computed"; fail=1; }
"$py" "$here/compare_results.py" "$dir/clean.jsonl" "$dir/r.jsonl" >/dev/null || { echo "FAIL results after SIGINT differ"; fail=1; }

# 3. A checkpoint of another sweep is refused.
"$sb" sweep "$dir/r.toml" --threads 1 --out "$dir/o.jsonl" >/dev/null 2>&1 &
pid=$!
while [ "$(finished "$dir/o.jsonl.checkpoint")" -lt 1 ]; do sleep 0.01; done
kill -9 $pid; wait $pid 2>/dev/null
sed 's/seed = 3/seed = 4/' "$dir/r.toml" >"$dir/r4.toml"
"$sb" sweep "$dir/r4.toml" --out "$dir/o.jsonl" --resume >/dev/null 2>"$dir/err"
[ $? -eq 2 ] && grep -q "another sweep" "$dir/err" || { echo "FAIL a foreign checkpoint was not refused"; fail=1; }

[ $fail -eq 0 ] && echo "killed and interrupted sweeps resumed: only missing units recomputed, same numbers"
exit $fail
