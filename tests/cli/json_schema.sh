#!/usr/bin/env bash
# `run --json` prints one JSON object with the documented keys and types.
# Usage: json_schema.sh SPRINGBLOCK PYTHON
set -u
sb=$1
py=$2
out=$("$sb" run --N 30 --reps 3 --seed 5 --duration 3t0 --json 2>/dev/null)
rc=$?
[ "$rc" -eq 0 ] || { echo "FAIL run exited $rc"; exit 1; }
"$py" -c '
import json, sys
j = json.loads(sys.stdin.read())
def num(x): return isinstance(x, (int, float)) and not isinstance(x, bool)
errors = []
for k in ("mu_s", "mu_d"):
    if not isinstance(j.get(k), dict): errors.append(k + " is not an object"); continue
    for s in ("mean", "std", "sem"):
        if not num(j[k].get(s)): errors.append("%s.%s missing or not a number" % (k, s))
for k, ok in (("reps", lambda x: x == 3), ("seed", lambda x: x == 5),
              ("contact_fraction", lambda x: num(x) and 0 < x <= 1),
              ("method", lambda x: x in ("rk4", "event")), ("dt", lambda x: num(x) and x > 0),
              ("duration", lambda x: num(x) and x > 0), ("wall_seconds", lambda x: num(x) and x >= 0)):
    if k not in j: errors.append("missing key " + k)
    elif not ok(j[k]): errors.append("bad value %s = %r" % (k, j[k]))
if errors:
    print("FAIL json schema:\n  " + "\n  ".join(errors)); sys.exit(1)
print("json schema ok")
' <<<"$out"
