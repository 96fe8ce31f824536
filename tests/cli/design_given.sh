#!/usr/bin/env bash
# springblock design over surfaces of one's own (--family given --candidates ...): masks are
# honoured as candidates, a mask equal to a listed periodic surface is one surface, the answer
# records the mask's blocks; a fixed --pattern is refused (design chooses the surface) and bad
# candidates exit 2 naming `candidates`, writing nothing. Usage: design_given.sh SPRINGBLOCK PYTHON
set -u
sb=$1
py=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail=0
chain=(--top 3 --verify-reps 3 --seed 5)

"$sb" pattern --N 40 --pattern periodic:2,6 | head -1 >"$dir/sparse.mask"
"$sb" pattern --N 40 --pattern hierarchical:10/4,2/1 | head -1 >"$dir/pg.mask"
"$sb" design --N 40 "${chain[@]}" --family given --candidates "mask:@$dir/sparse.mask" "mask:@$dir/pg.mask" periodic:2,6 \
  periodic:3,1 --maximise mu_s --json >"$dir/found.json" || { echo "FAIL design over given surfaces"; fail=1; }
"$py" - "$dir" <<'PY' || fail=1
import json, sys
d = sys.argv[1]
j = json.load(open(f"{d}/found.json"))
bad = []
if j["search"]["family"] != "given" or len(j["search"]["given"]) != 4: bad.append(f"search {j['search']['family']} {j['search']['given']}")
pats = [b["pattern"] for b in j["best"]]
if sorted(pats) != sorted([f"mask:@{d}/sparse.mask", f"mask:@{d}/pg.mask", "periodic:3,1"]):
    bad.append(f"verified {pats}: periodic:2,6 is the sparse mask's surface, listed after it")
sparse = [b for b in j["best"] if b["pattern"].endswith("sparse.mask")]
if sparse and (sparse[0]["same_mask_specs"] != 1 or sparse[0]["pattern_mask"]["mask"] != open(f"{d}/sparse.mask").read().strip()):
    bad.append(f"sparse mask record {sparse[0]}")
if bad: print("FAIL design given:\n  " + "\n  ".join(bad)); sys.exit(1)
PY

# bad FIELD WORDS ARGS...: exit 2, the field and WORDS in the message, no --out file.
bad() {
  local field=$1 words=$2 err rc; shift 2
  [[ " $* " == *" --N "* ]] || set -- --N 40 "$@"
  err=$("$sb" design "${chain[@]}" --target-mu-s 0.6 --out "$dir/bad.json" "$@" 2>&1 >/dev/null); rc=$?
  [ "$rc" -eq 2 ] || { echo "FAIL [$*]: exit $rc, expected 2: $err"; fail=1; return; }
  grep -qF -- "invalid $field" <<<"$err" || { echo "FAIL [$*]: message does not name '$field': $err"; fail=1; }
  grep -qF -- "$words" <<<"$err" || { echo "FAIL [$*]: message lacks '$words': $err"; fail=1; }
  [ ! -e "$dir/bad.json" ] || { echo "FAIL [$*]: an output file was written"; fail=1; rm -f "$dir/bad.json"; }
}
bad pattern "design chooses the surface" --pattern "mask:@$dir/sparse.mask"
bad candidates "needs the surfaces to choose among" --family given
bad candidates "chosen among with --family given" --candidates periodic:3,1
bad candidates "has 40 blocks but the chain has N = 41" --N 41 --family given --candidates "mask:@$dir/sparse.mask"
bad candidates "cannot read mask file" --family given --candidates "mask:@$dir/missing.mask"
bad candidates "'mask:01x' is not a surface" --family given --candidates mask:01x

[ "$fail" -eq 0 ] && echo "design chooses among given masks; a fixed pattern and bad candidates are refused"
exit "$fail"
