#!/usr/bin/env bash
# The reproduction targets share the springblock program's shell: every bad option is refused
# with exit code 2 and a message naming the field and what is allowed, before anything is
# simulated, and no output file (nor directory) is left. An unknown --method is such an error,
# never a silent fall back to another integrator. Usage: bad_options.sh BIN_DIR
set -u
bin=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail=0

# expect_error TARGET "ARGS" FIELD RANGE_PATTERN
expect_error() {
  local target=$1 args=$2 field=$3 range=$4 err rc
  # shellcheck disable=SC2086  # ARGS is a list of words on purpose
  err=$(timeout 60 "$bin/$target" --tier smoke --out "$dir/out" $args 2>&1 >/dev/null)
  rc=$?
  if [ "$rc" -ne 2 ]; then
    echo "FAIL [$target $args]: exit $rc, expected 2 (stderr: $err)"; fail=1; return
  fi
  for pat in "$target: invalid $field: " "$range"; do
    grep -qF -- "$pat" <<<"$err" || { echo "FAIL [$target $args]: message lacks '$pat': $err"; fail=1; }
  done
  # The field is named once: "invalid method: 'x' ...", not "invalid method: method: 'x' ...".
  if grep -qF -- "invalid $field: $field:" <<<"$err"; then
    echo "FAIL [$target $args]: field named twice: $err"; fail=1
  fi
  grep -qF "scenes," <<<"$err" && { echo "FAIL [$target $args]: simulated before refusing"; fail=1; }
  [ -e "$dir/out" ] && { echo "FAIL [$target $args]: left $dir/out behind"; fail=1; rm -rf "$dir/out"; }
}

expect_error fig1 "--method euler" method "'euler' is not one of: rk4, event"
expect_error fig1 "--threads 5000" threads "[0, 1024]"
expect_error fig1 "--threads abc" threads "whole number"
expect_error fig1 "--seed -3" seed "[0, 18446744073709551615]"
expect_error fig1 "--only nope" only "no scene of fig1"
expect_error fig1 "--layout zigzag" layout "pawl_first, symmetric"
expect_error fig_p1 "" input "needs --input <tab_pat0.json>"

# A malformed command line (CLI11's own checks) is bad input too.
for args in "--tier huge" "--bogus"; do
  # shellcheck disable=SC2086
  "$bin/fig1" $args --out "$dir/out" >/dev/null 2>&1
  rc=$?
  [ "$rc" -eq 2 ] || { echo "FAIL [fig1 $args]: exit $rc, expected 2"; fail=1; }
done

# An output directory that cannot be made is refused before the run, not after it.
touch "$dir/file"
err=$(timeout 60 "$bin/fig1" --tier smoke --threads 1 --out "$dir/file/sub" 2>&1 >/dev/null)
rc=$?
[ "$rc" -eq 2 ] || { echo "FAIL unwritable --out: exit $rc, expected 2: $err"; fail=1; }
grep -qF "fig1: invalid out: " <<<"$err" || { echo "FAIL unwritable --out: message: $err"; fail=1; }
grep -qF "scenes," <<<"$err" && { echo "FAIL unwritable --out: simulated before refusing"; fail=1; }

[ $fail -eq 0 ] && echo "reproduction targets refuse bad options with exit 2 and a clear message"
exit $fail
