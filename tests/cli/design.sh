#!/usr/bin/env bash
# springblock design (issue 17) on a small chain (N = 60, the paper's block size), seconds each:
#  - a target set from a known surface's measured mu_s (mean +- 2 SEM) is found again: the answer
#    is that surface, or one whose fresh mu_s agrees with the known one within the combined
#    uncertainty;
#  - an infeasible target is reported as such (feasible false, nearest point, why), exit 0;
#  - bad bounds and targets exit 2 naming the field, and write nothing;
#  - the answer does not depend on the thread count, and the JSON has no NaN.
# Usage: design.sh SPRINGBLOCK PYTHON
set -u
sb=$1
py=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail=0
chain=(--N 60 --length 1.2cm)
space=(--family periodic --max-np 12 --max-ng 12 --top 3 --verify-reps 6 --verify-max-reps 24)

# 1. The known surface: periodic:3,8 measured with `run` at 12 repetitions of its own seed.
"$sb" run "${chain[@]}" --pattern periodic:3,8 --reps 12 --seed 41 --stop-after-mu-s true --json >"$dir/known.json" ||
  { echo "FAIL run of the known surface"; exit 1; }
# The target is the interval the measurement supports, mean +- 2 SEM. Taken as an exact point, a
# fresh estimate of the same surface would miss it (|fresh - known| > 2 fresh SEMs) by chance 10 %
# of the time at 6 fresh repetitions, 25 % at 24; against the interval, 0.5 %.
target=$("$py" -c "import json,sys; m = json.load(open(sys.argv[1]))['mu_s']
print('%.4f:%.4f' % (m['mean'] - 2 * m['sem'], m['mean'] + 2 * m['sem']))" "$dir/known.json")
"$sb" design "${chain[@]}" "${space[@]}" --target-mu-s "$target" --seed 5 --threads 2 --json >"$dir/found.json" ||
  { echo "FAIL design for the known target $target"; fail=1; }
"$py" - "$dir/known.json" "$dir/found.json" <<'PY' || fail=1
import json, math, sys
known = json.load(open(sys.argv[1]))["mu_s"]
found = json.load(open(sys.argv[2]))
best = found["best"][0]
assert found["feasible"] is True, "a target measured on a surface of the space was called infeasible"
assert best["meets_target"] is True
same = best["pattern"] == "periodic:3,8"
# Not that surface: its fresh mu_s must agree with the known surface's within 3 combined SEMs.
gap = abs(best["mu_s"]["mean"] - known["mean"])
tol = 3 * math.hypot(best["mu_s"]["sem"], known["sem"])
assert same or gap <= tol, f"found {best['pattern']} mu_s {best['mu_s']['mean']:.4f}, known {known['mean']:.4f} +- {known['sem']:.4f}"
for key in ("mu_s", "mu_d"):
    assert set(best[key]) >= {"mean", "sem", "n"} and best[key]["n"] == best["reps"] >= 6, best[key]
# The answers in the order of their printed scores; each one's repetitions doubled from 6 until its
# distance is resolved or the budget is spent, and the resolution it reached stated.
scores = [b["score"] for b in found["best"]]
assert scores == sorted(scores), f"answers out of the order of their scores: {scores}"
budget = found["search"]["verify_max_reps"]
for b in found["best"]:
    assert b["reps"] in (6, 12, 24, 48, budget), b["reps"]
    assert b["resolved"] or b["reps"] == budget, f"{b['pattern']}: unresolved at {b['reps']} of {budget} repetitions"
    assert b["half_width"] == max(2 * b["mu_s"]["sem"], 0), (b["half_width"], b["mu_s"]["sem"])
print("known surface found again:", best["pattern"], "(known periodic:3,8);",
      ", ".join(f"{b['pattern']} score {b['score']:.4f} reps {b['reps']} 2SEM {b['half_width']:.4f}" for b in found["best"]))
PY

# 2. An infeasible target: mu_s = 0.2 is far below anything a pattern reaches.
"$sb" design "${chain[@]}" "${space[@]}" --target-mu-s 0.2 --threads 2 --json >"$dir/infeasible.json" ||
  { echo "FAIL an infeasible target did not exit 0"; fail=1; }
"$py" - "$dir/infeasible.json" <<'PY' || fail=1
import json, sys
j = json.load(open(sys.argv[1]))
assert j["feasible"] is False, "mu_s = 0.2 was called feasible"
assert j["nearest"] is not None and j["nearest"]["mu_s"]["mean"] > 0.2
assert "below the smallest mu_s reached" in j["why"], j["why"]
assert not any(b["meets_target"] for b in j["best"])
print("infeasible target reported:", j["why"][:80], "...")
PY

# 3. Bad input: exit 2, the field named, no output file.
bad() {  # bad EXPECTED_FIELD ARGS...
  local field=$1 err rc
  shift
  err=$("$sb" design "${chain[@]}" --target-mu-s 0.6 --out "$dir/bad.json" "$@" 2>&1 >/dev/null)
  rc=$?
  [ "$rc" -eq 2 ] || { echo "FAIL [$*]: exit $rc, expected 2: $err"; fail=1; return; }
  grep -qF -- "invalid $field" <<<"$err" || { echo "FAIL [$*]: message does not name '$field': $err"; fail=1; }
  [ ! -e "$dir/bad.json" ] || { echo "FAIL [$*]: an output file was written"; fail=1; rm -f "$dir/bad.json"; }
}
bad max_np --max-np 0
bad max_np --max-np 61
bad max_ng --min-ng 9 --max-ng 3
bad min_contact --min-contact 1.5
bad max_contact --min-contact 0.6 --max-contact 0.5
bad min_feature --min-feature 0
bad family --family fractal
bad levels --family hierarchical --levels 0
bad target_mu_d --target-mu-d 0.7:0.5
bad target_ratio --target-ratio abc
bad verify_reps --verify-reps 1
# On a chain shorter than 60 blocks the size bounds left unset stop at N (not refused as 60 > N).
"$sb" design --N 20 --length 0.4cm --target-mu-s 0.7 --verify-reps 2 --verify-max-reps 2 --top 1 --json \
  >"$dir/short.json" 2>"$dir/short.err" || { echo "FAIL design on N = 20: $(cat "$dir/short.err")"; fail=1; }
"$py" -c "import json,sys; b = json.load(open(sys.argv[1]))['search']['bounds']; assert (b['max_np'], b['max_ng']) == (20, 20), b" \
  "$dir/short.json" || { echo "FAIL design's default bounds on N = 20"; fail=1; }
err=$("$sb" design --N 0 --target-mu-s 0.6 2>&1 >/dev/null)
[ $? -eq 2 ] && grep -qF "invalid N" <<<"$err" || { echo "FAIL --N 0 (a field shared with run): $err"; fail=1; }
err=$("$sb" design "${chain[@]}" 2>&1 >/dev/null)
[ $? -eq 2 ] && grep -qF "invalid target" <<<"$err" || { echo "FAIL no target: $err"; fail=1; }

# 4. The thread count does not change the answer; no NaN anywhere.
"$sb" design "${chain[@]}" "${space[@]}" --target-mu-s "$target" --seed 5 --threads 1 --json >"$dir/one.json" || fail=1
"$py" - "$dir/found.json" "$dir/one.json" <<'PY' || fail=1
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:])
strip = lambda j: json.dumps({k: j[k] for k in ("best", "evaluated", "feasible")}, sort_keys=True)
assert strip(a) == strip(b), "the answer changed with the thread count"
PY
"$py" - "$dir/found.json" "$dir/infeasible.json" <<'PY' || fail=1
import json, sys
def refuse(c):
    raise ValueError(f"{c} in the JSON")
for p in sys.argv[1:]:
    json.load(open(p), parse_constant=refuse)
PY

# 5. A mu_d interval prunes contact-fraction classes; the prune must not drop a surface that meets
# the target when nothing is pruned (the premise: mu_d is set by the contact fraction).
md=(--target-mu-s 0.6:0.75 --target-mu-d ">=0.56" --seed 3 --threads 2 --json)
"$sb" design "${chain[@]}" "${space[@]}" "${md[@]}" >"$dir/pruned.json" || { echo "FAIL mu_d query"; fail=1; }
"$sb" design "${chain[@]}" "${space[@]}" "${md[@]}" --no-class-prune >"$dir/unpruned.json" || fail=1
"$py" - "$dir/pruned.json" "$dir/unpruned.json" <<'PY' || fail=1
import json, sys
pruned, unpruned = (json.load(open(p)) for p in sys.argv[1:])
classes = pruned["search"]["contact_classes"]
assert classes is not None and unpruned["search"]["contact_classes"] is None
dropped = [(c["contact_lo"], c["contact_hi"]) for c in classes["classes"] if not c["kept"]]
assert dropped, "nothing pruned: the check below would be empty"
for b in unpruned["best"]:
    if b["meets_target"]:
        f = b["contact_fraction"]
        assert not any(lo <= f < hi for lo, hi in dropped), f"{b['pattern']} meets the target but its class was pruned"
print(f"class prune: {classes['candidates_pruned']} candidates in {len(dropped)} classes pruned; "
      f"feasible pruned {pruned['feasible']}, unpruned {unpruned['feasible']}")
PY

# 6. The other families: their answers are pattern strings that `run --pattern` accepts.
for fam in "--family hierarchical --max-ng 24 --levels 2" "--family random --min-fraction 0.2 --max-fraction 0.8 --fraction-step 0.1"; do
  # shellcheck disable=SC2086
  p=$("$sb" design "${chain[@]}" $fam --target-mu-s 0.7 --top 1 --verify-reps 2 --threads 2 --json |
    "$py" -c "import json,sys; print(json.load(sys.stdin)['best'][0]['pattern'])") || { echo "FAIL design $fam"; fail=1; continue; }
  "$sb" run "${chain[@]}" --pattern "$p" --reps 1 --stop-after-mu-s true >/dev/null 2>&1 ||
    { echo "FAIL design $fam answered '$p', which run --pattern refuses"; fail=1; }
done

[ $fail -eq 0 ] && echo "design: known target found, infeasible reported, bad bounds refused, thread-independent"
exit $fail
