#!/usr/bin/env bash
# `run` defaults to the event method (RK4 by name), --threads 0 means all cores, and --help says
# both and the exit codes. Usage: defaults.sh SPRINGBLOCK PYTHON
set -u
sb=$1
py=$2
fail=0
small="--N 40 --length 0.8cm --reps 2 --seed 3"

# field_is OPTIONS KEY PYTHON_CONDITION_ON_x
field_is() {
  local out
  # shellcheck disable=SC2086  # OPTIONS is a list of words on purpose
  out=$("$sb" run $small $1 --json 2>/dev/null) || { echo "FAIL [$1]: exit $?"; fail=1; return; }
  "$py" -c 'import json, sys; x = json.loads(sys.stdin.read())[sys.argv[1]]; sys.exit(0 if eval(sys.argv[2]) else 1)' \
    "$2" "$3" <<<"$out" || { echo "FAIL [$1]: $2 does not satisfy $3"; fail=1; }
}
field_is "" method 'x == "event"'
field_is "--method rk4" method 'x == "rk4"'
field_is "--method event" method 'x == "event"'
field_is "--threads 0" threads 'x >= 1'
field_is "--threads 1" threads 'x == 1'

help=$("$sb" run --help)
for pat in "event (default" "0 = all cores" "Exit codes" "3 nothing measured" "(default 1e-4ms; s, ms, us)"; do
  grep -qF -- "$pat" <<<"$help" || { echo "FAIL run --help lacks '$pat'"; fail=1; }
done
if grep -qiE "rk4 \(default|default[^)]*rk4" <<<"$help"; then echo "FAIL run --help still calls rk4 the default"; fail=1; fi

[ $fail -eq 0 ] && echo "defaults: event method, --threads 0 = all cores, help says so"
exit $fail
