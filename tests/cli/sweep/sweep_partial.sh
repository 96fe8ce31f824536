#!/usr/bin/env bash
# A sweep's results while it runs: OUT.partial (header "partial": true, a whole JSON line per
# complete scene) grows scene by scene, and a reader polling it never takes a line cut short; a
# sweep killed with SIGKILL halfway leaves a valid OUT.partial and no OUT; --resume (on another
# thread count) picks up from the checkpoint and the partial file and gives results equal, bit for
# bit, to an uninterrupted sweep's; the partial lines' statistics are the complete file's; --units
# streams every unit's record once (and may not name one of the sweep's own files); SIGINT exits
# 130 naming the partial file.
# Usage: sweep_partial.sh SPRINGBLOCK PYTHON
set -u
sb=$1 py=$2
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../.." && pwd)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail=0
tool() { PYTHONPATH="$root" PYTHONDONTWRITEBYTECODE=1 "$py" -m "tools.$1" "${@:2}"; }

cat >"$dir/p.toml" <<'TOML'
[base]
N = 60
duration = "20t0"
velocity = "5cm/s"
reps = 3
seed = 5
[axes]
pattern = ["smooth", "periodic:3,1", "hierarchical:2,2"]
pressure = [1e6, 2e6]
TOML
units=18 scenes=6
"$sb" sweep "$dir/p.toml" --threads 2 --out "$dir/clean.jsonl" >/dev/null 2>&1 || { echo "FAIL clean sweep"; exit 1; }
[ ! -e "$dir/clean.jsonl.partial" ] || { echo "FAIL a complete sweep left its partial file"; fail=1; }
tool sweep_results "$dir/clean.jsonl" | grep -qx "complete: $scenes of $scenes scenes" ||
  { echo "FAIL the complete file does not read as complete"; fail=1; }

lines() { if [ -e "$1" ]; then wc -l <"$1"; else echo 0; fi; }
# One thread, killed once the partial file holds 2 scenes; a reader polls the file meanwhile.
"$sb" sweep "$dir/p.toml" --threads 1 --out "$dir/r.jsonl" --units "$dir/u.jsonl" >/dev/null 2>&1 &
pid=$!
"$py" - "$dir/r.jsonl.partial" "$dir/reader.txt" <<'PY' &
import json, os, sys, time
path, report = sys.argv[1], sys.argv[2]
reads = cut = 0
t0 = time.time()
while time.time() - t0 < 30 and not os.path.exists(report + ".stop"):
    try:
        text = open(path).read()
    except FileNotFoundError:
        continue
    reads += 1
    if not text.endswith("\n"):
        cut += 1  # a line being written: not taken
    for line in text[:text.rfind("\n") + 1].splitlines():
        json.loads(line)  # every newline-ended line is whole JSON
open(report, "w").write(f"{reads} {cut}\n")
PY
reader=$!
i=0
while [ "$(lines "$dir/r.jsonl.partial")" -lt 3 ] && [ $i -lt 1000 ]; do sleep 0.01; i=$((i + 1)); done
kill -9 $pid
wait $pid 2>/dev/null
touch "$dir/reader.txt.stop"
wait $reader || { echo "FAIL a reader of the growing partial file found a malformed line"; fail=1; }
echo "reader: $(cat "$dir/reader.txt" 2>/dev/null) (reads, reads ending inside a line)"
[ ! -e "$dir/r.jsonl" ] || { echo "FAIL a killed sweep left a complete results file"; fail=1; }
state=$(tool sweep_results "$dir/r.jsonl") || { echo "FAIL the partial file is malformed"; fail=1; }
echo "killed: $state; $(lines "$dir/u.jsonl.partial") unit records streamed"
case "$state" in
  "partial: "[1-5]" of $scenes scenes") ;;
  *) echo "FAIL the killed sweep's partial file: '$state' (the kill came too late?)"; fail=1 ;;
esac
"$py" - "$dir/r.jsonl.partial" "$dir/clean.jsonl" <<'PY' || fail=1
import json, sys
partial = [json.loads(l) for l in open(sys.argv[1])]
clean = {l["scene"]: l for l in map(json.loads, list(open(sys.argv[2]))[1:])}
assert partial[0]["partial"] is True and partial[0]["units"] == 18, partial[0]
for line in partial[1:]:
    want = {k: v for k, v in clean[line["scene"]].items() if k not in ("runs", "wall_s")}
    got = {k: v for k, v in line.items() if k != "wall_s"}
    if got != want:
        sys.exit(f"FAIL partial scene {line['scene']} differs from the complete file's")
PY

"$sb" sweep "$dir/p.toml" --threads 2 --out "$dir/r.jsonl" --units "$dir/u.jsonl" --resume >/dev/null 2>"$dir/err" ||
  { echo "FAIL resume"; cat "$dir/err"; exit 1; }
"$py" "$here/compare_results.py" "$dir/clean.jsonl" "$dir/r.jsonl" || { echo "FAIL resumed results differ"; fail=1; }
for f in r.jsonl.partial r.jsonl.checkpoint u.jsonl.partial; do
  [ ! -e "$dir/$f" ] || { echo "FAIL $f outlived the complete sweep"; fail=1; }
done
"$py" - "$dir/u.jsonl" "$dir/clean.jsonl" <<'PY' || fail=1
import json, sys
got = sorted((json.loads(l) for l in open(sys.argv[1])), key=lambda r: r["unit"])
want = [r for l in list(open(sys.argv[2]))[1:] for r in json.loads(l)["runs"]]
drop = lambda r: {k: v for k, v in r.items() if k not in ("wall_s", "cpu_s", "rank")}
if [r["unit"] for r in got] != list(range(18)) or list(map(drop, got)) != list(map(drop, want)):
    sys.exit("FAIL --units does not hold every unit's record once, equal to the results' runs")
PY

# Ctrl-C: exit 130, the message names the partial file, which is valid.
rm -f "$dir"/r.jsonl*
"$sb" sweep "$dir/p.toml" --threads 1 --out "$dir/r.jsonl" >/dev/null 2>"$dir/err" &
pid=$!
i=0
while [ "$(lines "$dir/r.jsonl.partial")" -lt 2 ] && [ $i -lt 1000 ]; do sleep 0.01; i=$((i + 1)); done
kill -INT $pid
wait $pid
rc=$?
[ $rc -eq 130 ] || { echo "FAIL interrupted sweep exited $rc"; fail=1; }
grep -q "complete so far are in .*r.jsonl.partial (marked partial)" "$dir/err" ||
  { echo "FAIL the interrupt message does not name the partial file"; cat "$dir/err"; fail=1; }
tool sweep_results "$dir/r.jsonl" | grep -q "^partial: " || { echo "FAIL no valid partial file after SIGINT"; fail=1; }

# --units naming one of the sweep's own files: exit 2, nothing written.
"$sb" sweep "$dir/p.toml" --out "$dir/same.jsonl" --units "$dir/same.jsonl" >/dev/null 2>"$dir/err"
[ $? -eq 2 ] && grep -q "invalid units: .* is the sweep's own file" "$dir/err" ||
  { echo "FAIL --units equal to --out was not refused"; cat "$dir/err"; fail=1; }
ls "$dir"/same.jsonl* >/dev/null 2>&1 && { echo "FAIL a refused sweep left a file"; fail=1; }

[ $fail -eq 0 ] && echo "partial results valid while running and after a kill; resumed results identical"
exit $fail
