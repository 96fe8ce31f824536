#!/usr/bin/env bash
# Never a NaN, never an empty average: a run that measured nothing (no repetition slipped before
# the end, or no sample in the mu_d window; known only after the run) exits 3 naming the option
# to change and writes nothing; a quantity not measured on purpose (--stop-after-mu-s) is said so
# in the text and is null with its reason in the JSON. Usage: nothing_measured.sh SPRINGBLOCK PYTHON
set -u
sb=$1
py=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail=0
small="--N 40 --length 0.8cm --reps 2 --seed 3"  # t0 = 0.4 s; first slips near 0.3-0.4 s

no_nan() {  # no_nan LABEL TEXT: no NaN or inf as a word (so "provenance" is fine)
  if grep -Eiwq 'nan|-?inf' <<<"$2"; then echo "FAIL [$1]: output holds a NaN/inf: $2"; fail=1; fi
}

# expect_nothing_measured "OPTIONS" OPTION_NAMED
expect_nothing_measured() {
  local opts=$1 named=$2 out err rc
  # shellcheck disable=SC2086  # OPTIONS is a list of words on purpose
  out=$("$sb" run $small $opts --out "$dir/out.json" --series "$dir/mu.tsv" 2>"$dir/err")
  rc=$?
  err=$(cat "$dir/err")
  [ "$rc" -eq 3 ] || { echo "FAIL [$opts]: exit $rc, expected 3 (stdout: $out stderr: $err)"; fail=1; }
  grep -qF -- "nothing measured" <<<"$err" || { echo "FAIL [$opts]: no 'nothing measured' message: $err"; fail=1; }
  grep -qF -- "$named" <<<"$err" || { echo "FAIL [$opts]: message does not name $named: $err"; fail=1; }
  [ -z "$out" ] || { echo "FAIL [$opts]: printed results: $out"; fail=1; }
  no_nan "$opts" "$out$err"
  local left
  left=$(find "$dir" -mindepth 1 ! -name err | tr '\n' ' ')
  [ -z "$left" ] || { echo "FAIL [$opts]: left behind: $left"; fail=1; rm -f "$dir"/out.json "$dir"/mu.tsv "$dir"/*.tmp.*; }
}

# The run ends before any repetition's loading phase does (--duration shorter than the first slip).
expect_nothing_measured "--duration 0.05t0 --mu-d-skip 0" "--duration"
expect_nothing_measured "--duration 0.05t0 --stop-after-mu-s true" "--duration"
expect_nothing_measured "--duration 0.05t0 --mu-d-skip 0 --method rk4" "--duration"
expect_nothing_measured "--duration 0.05t0 --mu-d-skip 0 --json" "--duration"
expect_nothing_measured "--peak-rule drop --peak-drop 1" "--peak-drop"   # mu(t) never drops by 1
# Every repetition slips, but its mu_d window opens after the end of the run.
expect_nothing_measured "--mu-d-skip 3.99" "--mu-d-skip"

# --stop-after-mu-s measures no mu_d: the text says so, the JSON has null with the reason.
out=$("$sb" run $small --stop-after-mu-s true 2>&1)
rc=$?
[ "$rc" -eq 0 ] || { echo "FAIL --stop-after-mu-s: exit $rc: $out"; fail=1; }
grep -qF "mu_d: not measured (stop_after_mu_s)" <<<"$out" || { echo "FAIL --stop-after-mu-s text: $out"; fail=1; }
grep -Eq "^mu_s = [0-9.]+ \+- [0-9.]+ \(sd [0-9.]+, n=2\)$" <<<"$out" || { echo "FAIL --stop-after-mu-s mu_s line: $out"; fail=1; }
no_nan "--stop-after-mu-s text" "$out"
"$sb" run $small --stop-after-mu-s true --json --out "$dir/out.json" >"$dir/stdout.json" 2>/dev/null ||
  { echo "FAIL --stop-after-mu-s --json exited non-zero"; fail=1; }
for f in "$dir/stdout.json" "$dir/out.json"; do
  "$py" -c '
import json, math, sys
j = json.load(open(sys.argv[1]))
def bad(x):  # any non-finite number (Python reads NaN/Infinity tokens as floats)
    if isinstance(x, float): return not math.isfinite(x)
    if isinstance(x, dict): return any(bad(v) for v in x.values())
    if isinstance(x, list): return any(bad(v) for v in x)
    return False
errors = []
for k in ("mu_d", "mu_d_signed"):
    s = j[k]
    if (s["mean"], s["std"], s["sem"], s["n"]) != (None, None, None, 0): errors.append("%s not null: %r" % (k, s))
    if s.get("not_measured") != "stop_after_mu_s": errors.append("%s lacks its reason: %r" % (k, s))
if not isinstance(j["mu_s"]["mean"], float) or "not_measured" in j["mu_s"]: errors.append("mu_s: %r" % j["mu_s"])
if bad(j): errors.append("a NaN or infinity in the JSON")
if errors: print("FAIL", sys.argv[1], "; ".join(errors)); sys.exit(1)
' "$f" || fail=1
done
rm -f "$dir/stdout.json" "$dir/out.json"

# An ordinary run prints numbers, and no NaN.
out=$("$sb" run $small 2>&1)
[ $? -eq 0 ] || { echo "FAIL ordinary run: $out"; fail=1; }
grep -Eq "^mu_d = [0-9.]+ \+- [0-9.]+ \(sd [0-9.]+, n=2\)$" <<<"$out" || { echo "FAIL ordinary mu_d line: $out"; fail=1; }
no_nan "ordinary run" "$out"

[ $fail -eq 0 ] && echo "nothing measured exits 3 and writes nothing; not-measured quantities are said so, never NaN"
exit $fail
