#!/usr/bin/env bash
# `run --profile` prints the work table on stderr after the results (stdout unchanged), and the
# JSON's runs[].work carries the counts always and the times only when profiled.
# Usage: profile.sh SPRINGBLOCK PYTHON
set -u
sb=$1
py=$2
args=(run --N 30 --reps 2 --seed 5 --duration 3t0 --pattern periodic:3,3)
plain=$("$sb" "${args[@]}" 2>/dev/null) || { echo "FAIL plain run exited $?"; exit 1; }
err=$(mktemp)
trap 'rm -f "$err"' EXIT
prof=$("$sb" "${args[@]}" --profile 2>"$err") || { echo "FAIL --profile exited $?"; exit 1; }
# Only the wall-time line may differ on stdout.
[ "$(grep -v '^wall time' <<<"$plain")" = "$(grep -v '^wall time' <<<"$prof")" ] || { echo "FAIL stdout changed"; exit 1; }
for row in slip_starts stepping_s sampling_s other_s; do
  grep -q "^  $row " "$err" || { echo "FAIL no '$row' row in the table:"; cat "$err"; exit 1; }
done
for flag in "" --profile; do
  "$sb" "${args[@]}" $flag --json 2>/dev/null | "$py" -c '
import json, sys
timed = sys.argv[1] == "--profile"
for r in json.load(sys.stdin)["runs"]:
    w = r["work"]
    assert w["slip_starts"] > 0 and w["stepped_attempts"] > 0, w
    assert ("stepping_s" in w) == timed, (timed, w)
' "$flag" || { echo "FAIL json work ($flag)"; exit 1; }
done
echo "profile ok"
