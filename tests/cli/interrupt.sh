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
[ $fail -eq 0 ] && echo "interrupt ok: $(grep -Eo '[0-9]+ of 200 repetitions had finished' "$dir/err")"
exit $fail
