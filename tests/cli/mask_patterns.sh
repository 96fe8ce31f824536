#!/usr/bin/env bash
# Surfaces given block by block: mask:0110..., mask:@FILE and hierarchical:P/G levels on the
# command line, in scene files and in sweeps. A mask equal to a periodic surface gives the same
# mu_s and mu_d to the last bit (same seed); bad masks are refused with exit 2, a message naming
# the field and what is wrong, nothing on stdout and no output file. Usage: mask_patterns.sh SPRINGBLOCK PYTHON
set -u
sb=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")  # absolute: the sweep runs in its own directory
py=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail=0
small="--N 60 --reps 3 --seed 7 --duration 3t0"

# `pattern` prints a mask as it was given (and S/S_tot), from the command line or a file.
periodic=$("$sb" pattern --N 60 --pattern periodic:3,2 | head -1)
got=$("$sb" pattern --N 60 --pattern "mask:$periodic")
[ "$got" = "$("$sb" pattern --N 60 --pattern periodic:3,2)" ] || { echo "FAIL pattern mask:: $got"; fail=1; }
{ echo "# periodic:3,2 on 60 blocks, the default layout"; echo "  ${periodic:0:30}"; echo
  echo "   # the second half"; echo "${periodic:30}"; } >"$dir/periodic.mask"
got=$("$sb" pattern --N 60 --pattern "mask:@$dir/periodic.mask") || { echo "FAIL pattern mask:@ exit $?"; fail=1; }
[ "$got" = "$("$sb" pattern --N 60 --pattern periodic:3,2)" ] || { echo "FAIL pattern mask:@: $got"; fail=1; }
got=$("$sb" pattern --N 12 --pattern hierarchical:4/2,2/1 | head -1)
[ "$got" = "110011010011" ] || { echo "FAIL pattern hierarchical:4/2,2/1 on 12 blocks: $got"; fail=1; }

# The same chain, so the same results, bit for bit; the scene records where the mask came from.
# shellcheck disable=SC2086  # $small is a list of words on purpose
"$sb" run $small --pattern periodic:3,2 --json >"$dir/periodic.json" || { echo "FAIL run periodic"; fail=1; }
# shellcheck disable=SC2086
"$sb" run $small --pattern "mask:$periodic" --json >"$dir/inline.json" || { echo "FAIL run inline mask"; fail=1; }
# shellcheck disable=SC2086
"$sb" run $small --pattern "mask:@$dir/periodic.mask" --json >"$dir/file.json" || { echo "FAIL run file mask"; fail=1; }
"$py" - "$dir" "$periodic" <<'PY' || fail=1
import json, sys
d, digits = sys.argv[1], sys.argv[2]
p, i, f = (json.load(open(f"{d}/{n}.json")) for n in ("periodic", "inline", "file"))
bad = [f"{n} {k}: {r[k]} != {p[k]}" for n, r in (("inline", i), ("file", f)) for k in ("mu_s", "mu_d", "contact_fraction")
       if r[k] != p[k]]
rec = f["scene"].get("pattern_mask", {})
if f["scene"]["pattern"] != f"mask:@{d}/periodic.mask": bad.append("file pattern " + f["scene"]["pattern"])
if rec.get("path") != f"{d}/periodic.mask" or rec.get("mask") != digits or rec.get("blocks") != 60:
    bad.append(f"file record {rec}")
if rec.get("contacts") != 36 or len(rec.get("fnv1a64", "")) != 16: bad.append(f"file record {rec}")
if i["scene"]["pattern"] != "mask:" + digits or i["scene"]["pattern_mask"]["fnv1a64"] != rec.get("fnv1a64"):
    bad.append(f"inline record {i['scene'].get('pattern_mask')}")
if "pattern_mask" in p["scene"]: bad.append("a periodic scene has a pattern_mask")
if bad: print("FAIL mask run:\n  " + "\n  ".join(bad)); sys.exit(1)
PY

# The equal-size form and its P/G spelling are one surface: the same numbers, the same pattern text.
# shellcheck disable=SC2086
"$sb" run $small --pattern hierarchical:12,4 --json >"$dir/equal.json" || { echo "FAIL run hierarchical:12,4"; fail=1; }
# shellcheck disable=SC2086
"$sb" run $small --pattern hierarchical:12/12,4/4 --json >"$dir/pg.json" || { echo "FAIL run P/G"; fail=1; }
"$py" - "$dir" <<'PY' || fail=1
import json, sys
a, b = (json.load(open(f"{sys.argv[1]}/{n}.json")) for n in ("equal", "pg"))
bad = [k for k in ("mu_s", "mu_d", "contact_fraction") if a[k] != b[k]]
per_run = lambda j: [(r["mu_s"], r["mu_d"]) for r in j["runs"]]  # not their timings
if per_run(a) != per_run(b): bad.append("runs")
if b["scene"]["pattern"] != "hierarchical:12,4": bad.append("pattern " + b["scene"]["pattern"])
if bad: print("FAIL hierarchical:12/12,4/4 differs from hierarchical:12,4 in " + ", ".join(bad)); sys.exit(1)
PY

# Scene files and sweeps take the same strings.
printf '{"N": 60, "reps": 3, "seed": 7, "duration": "3t0", "pattern": "mask:@%s"}' "$dir/periodic.mask" >"$dir/scene.json"
got=$("$sb" run --scene "$dir/scene.json" --json | "$py" -c 'import json,sys; print(json.load(sys.stdin)["mu_s"]["mean"])')
want=$("$py" -c 'import json,sys; print(json.load(open(sys.argv[1]))["mu_s"]["mean"])' "$dir/periodic.json")
[ "$got" = "$want" ] || { echo "FAIL scene file mask: mu_s $got, expected $want"; fail=1; }
printf '[base]\nN = 12\nreps = 1\nduration = "3t0"\n[axes]\npattern = ["mask:110011010011", "hierarchical:4/2,2/1", "mask:@%s"]\n' \
  "$dir/twelve.mask" >"$dir/sweep.toml"
echo "1100 1101 0011" >"$dir/twelve.mask"
(cd "$dir" && "$sb" sweep sweep.toml >/dev/null 2>&1) || { echo "FAIL sweep over masks"; fail=1; }
"$py" - "$dir/sweep.results.jsonl" <<'PY' || fail=1
import json, sys
rows = [json.loads(l) for l in open(sys.argv[1])][1:]
mu = {r["scene_json"]["pattern"].split("/")[-1]: r["mu_s"]["mean"] for r in rows}
if len(mu) != 3 or len(set(mu.values())) != 1: print(f"FAIL sweep: one surface, three results: {mu}"); sys.exit(1)
PY

# expect_refused "ARGS" WORDS...: exit 2, nothing on stdout, each of WORDS in the message, no --out file.
expect_refused() {
  local args=$1 out err rc; shift
  # shellcheck disable=SC2086  # ARGS is a list of words on purpose
  out=$("$sb" run $args --reps 1 --out "$dir/out.json" 2>"$dir/err"); rc=$?
  err=$(cat "$dir/err")
  [ "$rc" -eq 2 ] || { echo "FAIL [$args]: exit $rc, expected 2: $err"; fail=1; }
  [ -z "$out" ] || { echo "FAIL [$args]: printed '$out'"; fail=1; }
  [ ! -e "$dir/out.json" ] || { echo "FAIL [$args]: left out.json"; fail=1; rm -f "$dir/out.json"; }
  for w in "invalid pattern" "$@"; do
    grep -qF -- "$w" <<<"$err" || { echo "FAIL [$args]: message lacks '$w': $err"; fail=1; }
  done
  # The pattern program refuses it the same way (a mask's length is checked against its --N).
  # shellcheck disable=SC2086
  out=$("$sb" pattern $args 2>/dev/null); rc=$?
  if [ "$rc" -ne 2 ] || [ -n "$out" ]; then echo "FAIL pattern [$args]: exit $rc, printed '$out'"; fail=1; fi
}
printf '0110\n# fine\n01z0\n' >"$dir/bad.mask"
: >"$dir/empty.mask"
expect_refused "--N 4 --pattern mask:01x0" "character 3 of 4 is 'x'" "only 0 (groove) and 1 (pawl)"
expect_refused "--N 4 --pattern mask:" "empty mask"
expect_refused "--N 4 --pattern mask:0000" "no block in contact"
expect_refused "--N 5 --pattern mask:0110" "the mask has 4 blocks" "N = 5"
expect_refused "--pattern mask:0110" "the mask has 4 blocks" "N = 200"
expect_refused "--N 8 --pattern mask:@$dir/missing.mask" "cannot read mask file '$dir/missing.mask'"
expect_refused "--N 8 --pattern mask:@$dir/bad.mask" "'$dir/bad.mask' line 3, column 3" "'z' is not 0 or 1"
expect_refused "--N 8 --pattern mask:@$dir/empty.mask" "holds no 0 or 1"
expect_refused "--N 8 --pattern mask:@$dir" "it is a directory"
expect_refused "--N 12 --pattern hierarchical:0/2" "'0'" "positive"
expect_refused "--N 12 --pattern hierarchical:2/1000001" "too large (max 1000000)"
expect_refused "--N 12 --pattern hierarchical:2/1/1" "must be G (pawl = groove) or P/G"
expect_refused "--N 12 --pattern hierarchical:2/" "missing number"
expect_refused "--N 12 --pattern hierarchical:20/2" "size 20" "N=12"

[ "$fail" -eq 0 ] && echo "masks and P/G hierarchies: same results as the periodic surface, bad input refused"
exit "$fail"
