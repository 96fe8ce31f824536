#!/usr/bin/env bash
# --out and --series into a missing or unwritable place are refused with exit 2, naming the
# option and the path, before anything is simulated, and leave no file (partial, temporary or
# the other output) behind. Usage: output_paths.sh SPRINGBLOCK PYTHON
set -u
sb=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail=0
echo "not a directory" >"$dir/file"
echo "previous results" >"$dir/keep.json"
# A scene of several minutes: a refusal that comes after simulating runs into the timeout.
slow="--N 360 --length 7.2cm --pattern hierarchical:60,6,1 --reps 1000 --threads 1"

# expect_refused "OPTIONS" FIELD PATH
expect_refused() {
  local opts=$1 field=$2 path=$3 err rc
  # shellcheck disable=SC2086  # OPTIONS is a list of words on purpose
  err=$(timeout 20 "$sb" run $slow $opts 2>&1 >/dev/null)
  rc=$?
  [ "$rc" -eq 2 ] || { echo "FAIL [$opts]: exit $rc, expected 2 before simulating (stderr: ${err:0:300})"; fail=1; }
  grep -qF -- "invalid $field" <<<"$err" || { echo "FAIL [$opts]: message does not name '$field': $err"; fail=1; }
  grep -qF -- "$path" <<<"$err" || { echo "FAIL [$opts]: message does not name '$path': $err"; fail=1; }
  local left
  left=$(cd "$dir" && find . -mindepth 1 ! -name file ! -name keep.json | sort | tr '\n' ' ')
  [ -z "$left" ] || { echo "FAIL [$opts]: left behind: $left"; fail=1; rm -rf "$dir"/out* "$dir"/*.tmp.*; }
  cmp -s "$dir/keep.json" <(echo "previous results") || {
    echo "FAIL [$opts]: an existing file was modified"; fail=1; echo "previous results" >"$dir/keep.json"; }
}

expect_refused "--out $dir/missing/out.json" out "$dir/missing/out.json"
expect_refused "--out $dir/file/out.json" out "$dir/file/out.json"   # parent is not a directory
expect_refused "--out $dir" out "$dir"                               # a directory, not a file
expect_refused "--series $dir/missing/mu.tsv" series "$dir/missing/mu.tsv"
# One good path and one bad: the good one must not be written either.
expect_refused "--out $dir/out.json --series $dir/missing/mu.tsv" series "$dir/missing/mu.tsv"
expect_refused "--series $dir/out.tsv --out $dir/missing/out.json" out "$dir/missing/out.json"
expect_refused "--out $dir/keep.json --series $dir/missing/mu.tsv" series "$dir/missing/mu.tsv"
expect_refused "--out $dir/out.json --series $dir/out.json" series "$dir/out.json"
# Permissions do not stop root, so this case runs only for other users.
if [ "$(id -u)" -ne 0 ]; then
  mkdir "$dir/ro" && chmod 555 "$dir/ro"
  expect_refused "--out $dir/ro/out.json" out "$dir/ro/out.json"
  rmdir "$dir/ro"
fi

# Good paths are written, and nothing else is left beside them.
"$sb" run --N 20 --length 0.4cm --reps 1 --out "$dir/out.json" --series "$dir/out.tsv" >/dev/null 2>&1 ||
  { echo "FAIL a run with writable --out and --series failed"; fail=1; }
[ -s "$dir/out.json" ] && [ -s "$dir/out.tsv" ] || { echo "FAIL --out/--series not written"; fail=1; }
[ "$(find "$dir" -name '*.tmp.*' | wc -l)" -eq 0 ] || { echo "FAIL temporary files left behind"; fail=1; }

[ $fail -eq 0 ] && echo "bad output paths refused with exit 2 before simulating, nothing left behind"
exit $fail
