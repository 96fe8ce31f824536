#!/usr/bin/env bash
# springblock sweep in one process: the same numbers on 1 and 2 threads (and a changed seed
# changes them, so the comparison can fail); a sweep file with a bad field is refused with exit 2,
# the field and its line, before anything runs or any file is written.
# Usage: sweep.sh SPRINGBLOCK PYTHON
set -u
sb=$1 py=$2
here=$(cd "$(dirname "$0")" && pwd)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail=0

cat >"$dir/s.toml" <<'TOML'
[base]
N = 30
duration = "3t0"
velocity = "5cm/s"
reps = 3
seed = 5
[axes]
pattern = ["smooth", "periodic:3,1"]
N = { from = 20, to = 30, steps = 2 }
TOML
"$sb" sweep "$dir/s.toml" --threads 1 --out "$dir/t1.jsonl" >"$dir/t1.txt" 2>&1 || { echo "FAIL sweep --threads 1"; cat "$dir/t1.txt"; exit 1; }
"$sb" sweep "$dir/s.toml" --threads 2 --out "$dir/t2.jsonl" >/dev/null 2>&1 || { echo "FAIL sweep --threads 2"; exit 1; }
"$py" "$here/compare_results.py" "$dir/t1.jsonl" "$dir/t2.jsonl" || { echo "FAIL 1 and 2 threads differ"; fail=1; }
[ "$(grep -c '"scene":' "$dir/t1.jsonl")" -eq 4 ] || { echo "FAIL expected 4 scene lines"; fail=1; }
grep -q "periodic:3,1" "$dir/t1.txt" || { echo "FAIL the table lacks the varied pattern"; fail=1; }
[ ! -e "$dir/t1.jsonl.checkpoint" ] || { echo "FAIL the checkpoint of a finished sweep was left"; fail=1; }
sed 's/seed = 5/seed = 6/' "$dir/s.toml" >"$dir/s6.toml"
"$sb" sweep "$dir/s6.toml" --threads 2 --out "$dir/s6.jsonl" >/dev/null 2>&1
"$py" "$here/compare_results.py" "$dir/t1.jsonl" "$dir/s6.jsonl" >/dev/null 2>&1 && { echo "FAIL another seed compared equal"; fail=1; }

# The JSON form of the same sweep gives the same numbers.
cat >"$dir/s.json" <<'JSON'
{"base": {"N": 30, "duration": "3t0", "velocity": "5cm/s", "reps": 3, "seed": 5},
 "axes": {"pattern": ["smooth", "periodic:3,1"], "N": {"from": 20, "to": 30, "steps": 2}}}
JSON
"$sb" sweep "$dir/s.json" --threads 2 --out "$dir/j.jsonl" >/dev/null 2>&1 || { echo "FAIL JSON sweep"; fail=1; }
"$py" "$here/compare_results.py" "$dir/t1.jsonl" "$dir/j.jsonl" || { echo "FAIL JSON and TOML differ"; fail=1; }

bad() {  # bad EXT CONTENT FIELD LINE_TEXT
  printf '%s\n' "$2" >"$dir/bad.$1"
  rm -f "$dir/bad.out"*
  local err rc
  err=$("$sb" sweep "$dir/bad.$1" --out "$dir/bad.out" 2>&1 >/dev/null)
  rc=$?
  [ $rc -eq 2 ] || { echo "FAIL [$2]: exit $rc, expected 2: $err"; fail=1; return; }
  grep -qF -- "invalid $3" <<<"$err" || { echo "FAIL [$2]: does not name '$3': $err"; fail=1; }
  grep -qF -- "$4" <<<"$err" || { echo "FAIL [$2]: does not say '$4': $err"; fail=1; }
  ls "$dir"/bad.out* >/dev/null 2>&1 && { echo "FAIL [$2]: left a file"; fail=1; }
}
bad toml $'[base]\nN = 30\ncolour = "red"' colour "line 3"
bad toml $'[base]\nN = 30\n[axes]\nvelocity = ["5cm/s", "-1cm/s"]' velocity "line 4"
bad toml $'[base]\nreps = 2\n[axes]\nN = { from = 0, to = 10, steps = 2 }' N "line 4"
bad toml $'[base]\nN = 30\n[axes]\nN = []' N "at least one value"
bad toml $'[base]\nN = 30\n[axis]\nN = [1]' axis "line 3"
bad toml $'[base]\nN = = 3' sweep "line 2"
bad json $'{"base": {"N": 30,\n  "mu_d": "2.0,0.1"}}' mu_d "line 2"
bad json $'{"base": {"N": 30},\n "axes": {"pattern": ["smooth",\n   "sinusoidal"]}}' pattern "line 2"
bad toml '' sweep "holds no base, scenes or axes"
bad json '{}' sweep "holds no base, scenes or axes"

# An existing checkpoint is not overwritten without --resume.
printf '{}\n' >"$dir/t3.jsonl.checkpoint"
"$sb" sweep "$dir/s.toml" --out "$dir/t3.jsonl" >/dev/null 2>"$dir/err"
[ $? -eq 2 ] && grep -q -- "--resume" "$dir/err" || { echo "FAIL an existing checkpoint was not refused"; fail=1; }

[ $fail -eq 0 ] && echo "sweeps identical across threads; bad sweep files refused"
exit $fail
