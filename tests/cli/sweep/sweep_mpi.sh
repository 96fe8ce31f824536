#!/usr/bin/env bash
# springblock sweep under mpirun: 1, 2 and 4 oversubscribed ranks give the numbers of one
# process, bit for bit, and so does springblock run --reps 8 on 2 ranks (its --series too); a
# worker rank killed halfway is reported with the unit it lost, and
# --resume (on another rank count) computes only the missing units, again with the same numbers;
# a worker stopped by SIGTERM gives its unit back and the others finish the sweep;
# a killed job leaves a valid partial results file (OUT.partial) and no OUT; units dealt in
# batches (--batch-ms, default 50) and one at a time (--batch-ms 0) give the same numbers, the
# batches in far fewer messages than units;
# a bad sweep file is refused once, with exit 2 and nothing written.
# Usage: sweep_mpi.sh SPRINGBLOCK PYTHON MPIEXEC
set -u
sb=$1 py=$2 mpirun=$3
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../.." && pwd)
example="$here/../../../examples/sweep.toml"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail=0
mpi() { "$mpirun" --oversubscribe --allow-run-as-root "$@"; }

"$sb" sweep "$example" --threads 2 --out "$dir/one.jsonl" >/dev/null 2>&1 || { echo "FAIL one process"; exit 1; }
for np in 1 2 4; do
  mpi -np $np "$sb" sweep "$example" --threads 1 --out "$dir/np$np.jsonl" >"$dir/np$np.txt" 2>&1 ||
    { echo "FAIL mpirun -np $np"; cat "$dir/np$np.txt"; fail=1; continue; }
  grep -q "on $np rank(s)" "$dir/np$np.txt" || { echo "FAIL -np $np did not run on $np ranks"; fail=1; }
  "$py" "$here/compare_results.py" "$dir/one.jsonl" "$dir/np$np.jsonl" || { echo "FAIL -np $np differs"; fail=1; }
done

# Batches on and off: 20,000 tiny units (well under a millisecond each) on 2 ranks.
printf '[base]\nN = 4\nduration = "1t0"\nreps = 20000\nseed = 1\n' >"$dir/tiny.toml"
for ms in 50 0; do
  mpi -np 2 "$sb" sweep "$dir/tiny.toml" --threads 1 --batch-ms $ms --out "$dir/b$ms.jsonl" >/dev/null 2>&1 ||
    { echo "FAIL --batch-ms $ms"; fail=1; }
done
"$py" "$here/compare_results.py" "$dir/b50.jsonl" "$dir/b0.jsonl" || { echo "FAIL batches on and off differ"; fail=1; }
"$py" - "$dir/b50.jsonl" "$dir/b0.jsonl" <<'PY' || fail=1
import json, sys
for path, batched in zip(sys.argv[1:], (True, False)):
    lines = open(path).read().splitlines()
    messages = json.loads(lines[0])["messages"]
    remote = sum(1 for l in lines[1:] for r in json.loads(l)["runs"] if r["rank"] != 0)
    print(f"{'batches' if batched else 'one unit a request'}: {remote} units run by rank 1 in {messages} messages")
    if batched and not messages * 10 < remote:
        sys.exit("FAIL batched dealing did not batch")
    if not batched and messages < remote:
        sys.exit("FAIL --batch-ms 0 sent fewer messages than units")
PY

# springblock run spreads its repetitions the same way: --reps 8 on 2 ranks = one process.
opts=(--N 40 --reps 8 --seed 11 --duration 3t0 --pattern periodic:3,1 --velocity 5cm/s --json)
"$sb" run "${opts[@]}" >"$dir/run1.json" 2>/dev/null || { echo "FAIL run in one process"; fail=1; }
mpi -np 2 "$sb" run "${opts[@]}" --threads 1 >"$dir/run2.json" 2>"$dir/run2.err" || { echo "FAIL run under mpirun"; cat "$dir/run2.err"; fail=1; }
[ "$(wc -l <"$dir/run2.json")" -eq 1 ] || { echo "FAIL run under mpirun printed more than rank 0's line"; fail=1; }
"$py" "$here/compare_results.py" "$dir/run1.json" "$dir/run2.json" || { echo "FAIL run: 2 ranks differ"; fail=1; }
# Repetition 0's mu(t) series comes back from whichever rank ran it, to the last digit.
"$sb" run "${opts[@]}" --series "$dir/s1.tsv" >/dev/null 2>&1 || { echo "FAIL run --series in one process"; fail=1; }
mpi -np 2 "$sb" run "${opts[@]}" --threads 1 --series "$dir/s2.tsv" >/dev/null 2>"$dir/s2.err" ||
  { echo "FAIL run --series under mpirun"; cat "$dir/s2.err"; fail=1; }
cmp -s <(grep -v '^#' "$dir/s1.tsv") <(grep -v '^#' "$dir/s2.tsv") || { echo "FAIL run --series: 2 ranks differ"; fail=1; }

# A worker rank killed early (3 ranks, one thread each; 24 units of 0.2 to 0.5 s).
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
units=24
"$sb" sweep "$dir/k.toml" --out "$dir/clean.jsonl" >/dev/null 2>&1 || { echo "FAIL clean sweep"; exit 1; }
finished() { if [ -e "$1" ]; then grep -c '"unit"' "$1"; else echo 0; fi; }
# The pid of rank 1 of the running sweep of k.toml (found by its environment), once the checkpoint
# shows it holding a unit.
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
mpi -np 3 "$sb" sweep "$dir/k.toml" --threads 1 --out "$dir/k.jsonl" >/dev/null 2>"$dir/err" &
job=$!
# Killed as soon as it holds a unit: mpirun takes a second or two to end the other ranks, which
# go on meanwhile, so the units must outlast that.
victim=$(rank1_when_busy)
[ -n "$victim" ] && kill -9 "$victim"
wait $job 2>/dev/null
[ $? -ne 0 ] || { echo "FAIL the job with a killed rank exited 0"; fail=1; }
[ ! -e "$dir/k.jsonl" ] || { echo "FAIL a killed job wrote results"; fail=1; }
PYTHONPATH="$root" PYTHONDONTWRITEBYTECODE=1 "$py" -m tools.sweep_results "$dir/k.jsonl" | grep -q "^partial: " ||
  { echo "FAIL the killed job left no valid partial results file"; fail=1; }
grep -q "in flight (lost, recomputed on resume): .*rank 1: [0-9]" "$dir/err" ||
  { echo "FAIL rank 0 did not report the units rank 1 lost"; cat "$dir/err"; fail=1; }
done_before=$(finished "$dir/k.jsonl.checkpoint")
mpi -np 2 "$sb" sweep "$dir/k.toml" --threads 1 --out "$dir/k.jsonl" --resume >/dev/null 2>"$dir/err2" ||
  { echo "FAIL resume under mpirun"; cat "$dir/err2"; exit 1; }
computed=$("$py" -c 'import json,sys; print(json.loads(open(sys.argv[1]).readline())["computed_units"])' "$dir/k.jsonl")
echo "killed rank 1 with $done_before of $units units done; the resume on 2 ranks computed $computed"
[ "$done_before" -lt $units ] || { echo "FAIL the kill came after the last unit"; fail=1; }
[ "$computed" -eq $((units - done_before)) ] || { echo "FAIL resume computed $computed, expected $((units - done_before))"; fail=1; }
grep -q "rank 1: " "$dir/err2" || { echo "FAIL the resume did not name the units rank 1 lost"; fail=1; }
"$py" "$here/compare_results.py" "$dir/clean.jsonl" "$dir/k.jsonl" || { echo "FAIL resumed results differ"; fail=1; }

# A worker rank told to stop (SIGTERM to it alone) gives its unit back; the others finish the
# sweep, which says so, with the same numbers.
rm -f "$dir/k.jsonl"*
mpi -np 3 "$sb" sweep "$dir/k.toml" --threads 1 --out "$dir/k.jsonl" >/dev/null 2>"$dir/err4" &
job=$!
victim=$(rank1_when_busy)
[ -n "$victim" ] && kill -TERM "$victim"
wait $job || { echo "FAIL the sweep did not finish without the stopped rank"; cat "$dir/err4"; fail=1; }
grep -q "rank 1 was interrupted and gave back unit" "$dir/err4" || { echo "FAIL the given-back unit was not reported"; fail=1; }
"$py" "$here/compare_results.py" "$dir/clean.jsonl" "$dir/k.jsonl" >/dev/null || { echo "FAIL results without rank 1 differ"; fail=1; }

# A bad field: exit 2 from mpirun, said once, nothing written.
printf '[base]\nN = 30\n[axes]\ncolour = ["red"]\n' >"$dir/bad.toml"
mpi -np 2 "$sb" sweep "$dir/bad.toml" --out "$dir/bad.jsonl" >/dev/null 2>"$dir/err3"
rc=$?
[ $rc -eq 2 ] || { echo "FAIL bad file under mpirun exited $rc"; fail=1; }
[ "$(grep -c 'invalid colour: unknown scene field (.*bad.toml line 4)' "$dir/err3")" -eq 1 ] ||
  { echo "FAIL the bad field was not named once with its line"; cat "$dir/err3"; fail=1; }
ls "$dir"/bad.jsonl* >/dev/null 2>&1 && { echo "FAIL a refused sweep left a file"; fail=1; }

[ $fail -eq 0 ] && echo "MPI sweeps identical to one process; a dead rank's units reported and resumed"
exit $fail
