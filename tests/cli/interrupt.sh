#!/usr/bin/env bash
# No partial results: SIGINT during a run exits with 130, leaves a pre-existing --out file
# untouched and no temporary files, and says how many repetitions had finished.
# Usage: interrupt.sh SPRINGBLOCK PYTHON
set -u
sb=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
echo "previous results" >"$dir/out.json"
cp "$dir/out.json" "$dir/before"
# ~0.5 s per repetition on one thread: 200 repetitions cannot finish within the 1 s we wait.
"$sb" run --reps 200 --threads 1 --out "$dir/out.json" 2>"$dir/err" >/dev/null &
pid=$!
sleep 1
kill -INT $pid
wait $pid
rc=$?
fail=0
[ "$rc" -eq 130 ] || { echo "FAIL exit $rc after SIGINT, expected 130"; fail=1; }
cmp -s "$dir/out.json" "$dir/before" || { echo "FAIL the existing --out file was modified"; fail=1; }
leftovers=$(find "$dir" -name '*.tmp.*' | wc -l)
[ "$leftovers" -eq 0 ] || { echo "FAIL $leftovers temporary file(s) left behind"; fail=1; }
grep -Eq '[0-9]+ of 200 repetitions had finished' "$dir/err" || {
  echo "FAIL the message does not say how many repetitions finished: $(cat "$dir/err")"; fail=1; }

# A quiet stretch of ~10^11 samples (sample_dt 1e-11 s): the observer takes it in pieces, so the
# progress line moves and an interrupt lands between them (one stretch used to run for hours).
"$sb" run --N 20 --reps 2 --threads 1 --sample-dt 1e-11s --progress --out "$dir/tiny.json" 2>"$dir/err2" >/dev/null &
pid=$!
sleep 3
kill -INT $pid
for _ in $(seq 100); do kill -0 $pid 2>/dev/null || break; sleep 0.1; done
if kill -0 $pid 2>/dev/null; then
  echo "FAIL a run with sample_dt 1e-11 s was still running 10 s after SIGINT"
  kill -KILL $pid
  fail=1
else
  wait $pid
  rc=$?
  [ "$rc" -eq 130 ] || { echo "FAIL exit $rc after SIGINT with sample_dt 1e-11 s, expected 130"; fail=1; }
fi
grep -q "ETA" "$dir/err2" || { echo "FAIL no progress line in 3 s: $(head -c 300 "$dir/err2")"; fail=1; }
[ ! -e "$dir/tiny.json" ] || { echo "FAIL an interrupted run wrote its --out file"; fail=1; }
[ $fail -eq 0 ] && echo "interrupt ok: $(grep -Eo '[0-9]+ of 200 repetitions had finished' "$dir/err")"
exit $fail
