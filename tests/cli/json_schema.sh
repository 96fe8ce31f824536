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

# With --slip-events true: each repetition's events as columns of equal length, and their summary.
out=$("$sb" run --N 30 --reps 3 --seed 5 --duration 3t0 --slip-events true --json 2>/dev/null)
rc=$?
[ "$rc" -eq 0 ] || { echo "FAIL run --slip-events true exited $rc"; exit 1; }
"$py" -c '
import json, sys
j = json.loads(sys.stdin.read())
def num(x): return isinstance(x, (int, float)) and not isinstance(x, bool)
errors = []
s = j.get("slip_events")
if not isinstance(s, dict): errors.append("slip_events is not an object")
else:
    if not all(num(s.get("events_per_run", {}).get(k)) for k in ("mean", "std", "sem", "n")):
        errors.append("slip_events.events_per_run is not a statistic")
    c = s.get("counts_by_blocks", {})
    if not (isinstance(c.get("blocks"), list) and len(c["blocks"]) == len(c.get("events", [None]))):
        errors.append("slip_events.counts_by_blocks: blocks and events differ in length")
    if not isinstance(s.get("unfinished_runs"), int): errors.append("slip_events.unfinished_runs is not a count")
total = 0
for r in j.get("runs", []):
    e = r.get("slip_events")
    if not isinstance(e, dict): errors.append("runs[%d].slip_events missing" % r["rep"]); continue
    cols = ("t_start_s", "duration_s", "blocks", "episodes", "slip_m")
    lengths = {len(e.get(k, [])) for k in cols}
    if len(lengths) != 1 or not all(num(x) for k in cols for x in e.get(k, [])):
        errors.append("runs[%d].slip_events: columns of unequal length or not numbers" % r["rep"])
    if not isinstance(e.get("unfinished"), bool): errors.append("runs[%d].slip_events.unfinished" % r["rep"])
    if e.get("unfinished") != ("under_way" in e): errors.append("runs[%d]: under_way iff unfinished" % r["rep"])
    total += len(e.get("blocks", []))
if isinstance(s, dict) and sum(s.get("counts_by_blocks", {}).get("events", [])) != total:
    errors.append("counts_by_blocks does not add up to the events of the runs")
if total == 0: errors.append("no slip event recorded")
if errors:
    print("FAIL slip-event json:\n  " + "\n  ".join(errors)); sys.exit(1)
print("slip-event json ok")
' <<<"$out"
