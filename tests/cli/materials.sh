#!/usr/bin/env bash
# Per-block materials from the command line, scene files and sweep files: a file of the scene's
# own values gives the uniform scene's mu_s and mu_d to the last bit under every method; bad files
# and segments exit 2 naming the path, line and column (or the segment) and write nothing.
# Usage: materials.sh SPRINGBLOCK PYTHON
set -u
sb=$1
py=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail=0

# A file of the defaults (mu_s 1.0,0.1, mu_d 0.5,0.01, scales 1) for N blocks, with a contact
# column (the mask `springblock pattern` prints) when one is given.
defaults() {  # defaults N FILE [CONTACT_MASK]
  "$py" - "$1" "$2" "${3:-}" <<'EOF'
import sys
n, path, mask = int(sys.argv[1]), sys.argv[2], sys.argv[3]
cols = (["contact"] if mask else []) + ["mu_s", "mu_s_sd", "mu_d", "mu_d_sd", "k_int_scale", "k_s_scale", "mass_scale"]
with open(path, "w") as f:
    f.write("# the scene's own values, block by block\n" + "\t".join(cols) + "\n")
    for i in range(n):
        f.write("\t".join(([mask[i]] if mask else []) + ["1.0", "0.1", "0.5", "0.01", "1", "1", "1"]) + "\n")
EOF
}

# mu_s and mu_d of `run --json` as exact hex doubles, and the materials record.
measured() {
  "$sb" run "$@" --json | "$py" -c '
import json, sys
j = json.load(sys.stdin)
print(float(j["mu_s"]["mean"]).hex(), float(j["mu_d"]["mean"]).hex())'
}

# Bit-identity, method by method: event, rk4, and the K_int = 0 solver.
defaults 40 "$dir/defaults.tsv"
for args in "--method event" "--method rk4" "--method event --k-int-scale 0" "--method rk4 --k-int-scale 0"; do
  # shellcheck disable=SC2086
  a=$(measured --N 40 --reps 3 --seed 11 --duration 3t0 $args)
  # shellcheck disable=SC2086
  b=$(measured --N 40 --reps 3 --seed 11 --duration 3t0 $args --materials "$dir/defaults.tsv")
  if [ -z "$a" ] || [ "$a" != "$b" ]; then echo "FAIL [$args]: uniform '$a', defaults file '$b'"; fail=1; fi
done
# With a contact column equal to the pattern's mask, on a patterned surface.
mask=$("$sb" pattern --pattern periodic:3,2 --N 40 | head -1)
defaults 40 "$dir/masked.tsv" "$mask"
a=$(measured --N 40 --reps 3 --seed 11 --duration 3t0 --pattern periodic:3,2)
b=$(measured --N 40 --reps 3 --seed 11 --duration 3t0 --pattern periodic:3,2 --materials "$dir/masked.tsv")
[ -n "$a" ] && [ "$a" == "$b" ] || { echo "FAIL contact column: '$a' vs '$b'"; fail=1; }

# The record: source and hash in the scene of every output.
"$sb" run --N 40 --reps 1 --duration 3t0 --method rk4 --materials "$dir/defaults.tsv" --json | "$py" -c '
import json, sys
m = json.load(sys.stdin)["scene"]["materials"]
assert m["source"].endswith("defaults.tsv") and len(m["hash"]) == 16, m
' || { echo "FAIL materials record"; fail=1; }

# expect_error FILE_CONTENT PATTERN [ARGS...]: exit 2, the message, no output file.
expect_error() {
  local content=$1 pattern=$2 err rc
  shift 2
  printf '%b' "$content" >"$dir/bad.tsv"
  rm -f "$dir/out.json"
  err=$("$sb" run --N 3 --reps 1 --materials "$dir/bad.tsv" --out "$dir/out.json" "$@" 2>&1 >/dev/null)
  rc=$?
  [ "$rc" -eq 2 ] || { echo "FAIL [$content]: exit $rc, expected 2: $err"; fail=1; return; }
  grep -qF -- "invalid materials" <<<"$err" || { echo "FAIL [$content]: does not name materials: $err"; fail=1; }
  grep -qF -- "$pattern" <<<"$err" || { echo "FAIL [$content]: message lacks '$pattern': $err"; fail=1; }
  [ ! -e "$dir/out.json" ] || { echo "FAIL [$content]: an output file was written"; fail=1; }
}

expect_error 'mu_s\tgrip\n1\t1\n1\t1\n1\t1\n' "unknown field 'grip'; the per-block fields are contact, mu_s"
expect_error 'mu_s\n1\n1\n' "has 2 rows; the scene has N = 3 blocks"
expect_error 'mu_s\tmu_s_sd\n1\t0.1\n1\t-0.1\n1\t0.1\n' "line 3 (row 2, block 1), column mu_s_sd: value -0.1 is outside the allowed range [0, 100]"
expect_error 'mu_s\n1\nx\n1\n' "line 3: column mu_s: 'x' is not a number"
expect_error 'mu_s\n1\ninf\n1\n' "column mu_s: value inf is outside"
expect_error 'k_s_scale\n1\n0\n1\n' "column k_s_scale: value 0 is outside the allowed range [1e-8, 1e8]" --method rk4
expect_error 'mass_scale\n1\n1e-300\n1\n' "column mass_scale: value 1e-300 is outside the allowed range [1e-8, 1e8]"
expect_error 'contact\n0\n0\n0\n' "no block in contact"
expect_error 'contact\n0\n0.5\n1\n' "column contact: value 0.5 is outside the allowed range 0 or 1"
expect_error 'mu_s\tmu_d\n1\t0.5\n0.4\t0.5\n1\t0.5\n' "mu_d mean 0.5 exceeds the mu_s mean 0.4"
rm -f "$dir/out.json"
err=$("$sb" run --N 3 --materials "$dir/missing.tsv" --out "$dir/out.json" 2>&1 >/dev/null)
rc=$?
{ [ "$rc" -eq 2 ] && grep -qF "cannot read materials file '$dir/missing.tsv'" <<<"$err" && [ ! -e "$dir/out.json" ]; } ||
  { echo "FAIL missing file: exit $rc: $err"; fail=1; }

# The closed forms take per-block fields block by block: a file of the scene's own values gives the
# uniform chain's (mu_d)_M; a random surface has no fixed contact blocks and is refused.
out=$("$sb" theory --N 40 --materials "$dir/defaults.tsv" --json)
rc=$?
{ [ "$rc" -eq 0 ] && "$py" -c 'import json,sys; j=json.loads(sys.argv[1]); c=j["chain"]
assert abs(c["mu_d_macro_gaussian"] - j["mu_d_macro_gaussian"]) <= 1e-12 * j["mu_d_macro_gaussian"], j
assert c["n_contact"] == 40 and c["quadratures"] == 1' "$out"; } ||
  { echo "FAIL theory with materials: exit $rc: $out"; fail=1; }
err=$("$sb" theory --N 40 --pattern random:0.5 --materials "$dir/defaults.tsv" 2>&1 >/dev/null)
rc=$?
{ [ "$rc" -eq 2 ] && grep -qF "a random surface draws a new mask each repetition" <<<"$err"; } ||
  { echo "FAIL theory with materials on a random surface: exit $rc: $err"; fail=1; }
# The surface search refuses what it would silently override.
err=$("$sb" design --N 40 --materials "$dir/masked.tsv" --target-mu-s 0.7 2>&1 >/dev/null)
rc=$?
{ [ "$rc" -eq 2 ] && grep -qF "a contact column or segment would override every candidate's pattern" <<<"$err"; } ||
  { echo "FAIL design with a contact column: exit $rc: $err"; fail=1; }

# Segments in a scene file: a bad one names the segment; a good one runs and is recorded.
printf '{"N": 30, "segments": [{"field": "mu_s", "from": 0, "to": 40, "value": 1.2}]}' >"$dir/seg.json"
err=$("$sb" run --scene "$dir/seg.json" --reps 1 2>&1 >/dev/null)
rc=$?
{ [ "$rc" -eq 2 ] && grep -qF "invalid segments: segments.0 (mu_s): blocks from = 0 to = 40" <<<"$err"; } ||
  { echo "FAIL bad segment: exit $rc: $err"; fail=1; }
printf '{"N": 30, "duration": "3t0", "segments": [{"field": "mu_s", "from": 0, "to": 14, "value": 1.2},
  {"field": "mu_s", "from": 15, "to": -1, "start": 0.9, "end": 1.1}]}' >"$dir/seg.json"
"$sb" run --scene "$dir/seg.json" --reps 2 --json | "$py" -c '
import json, sys
m = json.load(sys.stdin)["scene"]["materials"]
assert m["source"] == "segments" and m["fields"] == ["mu_s"] and len(m["segments"]) == 2, m
' || { echo "FAIL segments scene"; fail=1; }

# A sweep axis over a segment's value: three scenes, three hashes.
cat >"$dir/sweep.toml" <<'EOF'
[base]
N = 30
reps = 2
duration = "3t0"
segments = [{field = "mu_s", from = 0, to = 14, value = 1.0}]
[axes]
"segments.0.value" = [1.0, 1.2, 1.4]
EOF
if "$sb" sweep "$dir/sweep.toml" --out "$dir/sweep.jsonl" --threads 2 >/dev/null 2>&1; then
  "$py" -c '
import json, sys
lines = [json.loads(l) for l in open(sys.argv[1]) if l.strip()]
hashes = {l["scene_json"]["materials"]["hash"] for l in lines if "scene_json" in l}
assert len(hashes) == 3, hashes
' "$dir/sweep.jsonl" || { echo "FAIL sweep over segments.0.value"; fail=1; }
else
  echo "FAIL sweep over segments.0.value did not run: $("$sb" sweep "$dir/sweep.toml" --out "$dir/sweep2.jsonl" 2>&1 | tail -3)"; fail=1
fi

[ "$fail" -eq 0 ] && echo "materials ok"
exit "$fail"
