#!/usr/bin/env bash
# Scene files go through the same validation as options: an unknown key, a bad value and a
# malformed file are refused with exit 2 naming the key, and so is a file of any kind (scene,
# materials, mask, sweep) that cannot be read. Usage: scene_file.sh SPRINGBLOCK PYTHON
set -u
sb=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail=0

check() {  # check FILE_CONTENT EXPECTED_FIELD PATTERN
  printf '%s' "$1" >"$dir/scene.json"
  local err rc
  err=$("$sb" run --scene "$dir/scene.json" --reps 1 2>&1 >/dev/null)
  rc=$?
  [ "$rc" -eq 2 ] || { echo "FAIL [$1]: exit $rc, expected 2: $err"; fail=1; return; }
  grep -qF -- "invalid $2" <<<"$err" || { echo "FAIL [$1]: message does not name '$2': $err"; fail=1; }
  grep -qF -- "$3" <<<"$err" || { echo "FAIL [$1]: message lacks '$3': $err"; fail=1; }
}

check '{"N": 50, "colour": "red"}' colour "unknown scene field"
check '{"N": 50, "velocity": "-3cm/s"}' velocity "outside the allowed range"
check '{"N": 50, "length": "4 parsecs"}' length "unknown unit"
check '{"N": 0}' N "outside [1, 1000000]"
check '{"N": 50, "pattern": "periodic:60,1"}' pattern "exceeds the number of blocks"
check '{"N": 50, "damping": [1, 2]}' damping "string, number or boolean"
check '{"N": 50, "mu_s": "1.0,0.1", "mu_d": "1.5,0.01"}' mu_d "[0, mu_s mean = 1]"
check '[1, 2, 3]' scene "one JSON object"
check '{"N": 50,' scene "not valid JSON"

# Files that cannot be read as text: exit 2 naming the field, for every file the user names.
unreadable() {  # unreadable FIELD WORDS...: the command words after springblock
  local field=$1 err rc
  shift
  err=$("$sb" "$@" 2>&1 >/dev/null)
  rc=$?
  [ "$rc" -eq 2 ] && grep -qF "invalid $field: cannot read" <<<"$err" ||
    { echo "FAIL [$*]: exit $rc, expected 2 naming $field: $err"; fail=1; }
}
mkdir "$dir/folder" "$dir/folder.toml"
unreadable scene run --scene "$dir/folder" --reps 1
unreadable scene run --scene "$dir/missing.json" --reps 1
unreadable materials run --N 20 --materials "$dir/folder" --reps 1
unreadable pattern run --N 20 --pattern "mask:@$dir/folder" --reps 1
unreadable sweep sweep "$dir/folder.toml"

# A good scene file runs.
printf '{"N": 20, "reps": 1, "duration": "3t0", "pattern": "periodic:2,1"}' >"$dir/ok.json"
"$sb" run --scene "$dir/ok.json" --json >/dev/null 2>&1 || { echo "FAIL a valid scene file was refused"; fail=1; }

[ $fail -eq 0 ] && echo "scene files validated"
exit $fail
