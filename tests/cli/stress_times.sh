#!/usr/bin/env bash
# --stress-times: repetition 0's per-block snapshots are in the results JSON (stdout and --out
# alike), one per time in time order whatever order they were given in, each taken at the first
# sample at or after its time, with one entry per block; the scene records the times.
# Usage: stress_times.sh SPRINGBLOCK PYTHON
set -u
sb=$1
py=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail=0
"$sb" run --N 20 --reps 2 --stress-times 0.2s,0.1s --json --out "$dir/out.json" >"$dir/stdout.json" ||
  { echo "FAIL the run with --stress-times"; exit 1; }
"$py" - "$dir/stdout.json" "$dir/out.json" <<'PY' || fail=1
import json, sys
for path in sys.argv[1:]:
    j = json.load(open(path))
    scene = j["scene"]
    assert scene["stress_times_s"] == [0.1, 0.2], scene.get("stress_times_s")
    dt, N = scene["sample_dt_s"], scene["geometry"]["N"]
    shots = j["stress"]
    assert len(shots) == 2, shots
    for want, s in zip((0.1, 0.2), shots):
        assert want <= s["t_s"] < want + dt + 1e-12, (want, s["t_s"])
        assert len(s["f_over_Fn"]) == N and len(s["sigma_over_P"]) == N, s
        assert all(isinstance(x, float) for x in s["f_over_Fn"] + s["sigma_over_P"]), s
    # Loading: the springs pull every block the same way, so every friction force is positive.
    assert all(x > 0 for x in shots[0]["f_over_Fn"]), shots[0]["f_over_Fn"]
print("stress snapshots:", ", ".join(f"{s['t_s']:.6f} s" for s in shots), "in both outputs")
PY
# Without --stress-times there are none, and the scene says nothing of them.
"$sb" run --N 20 --reps 1 --json >"$dir/none.json" || fail=1
"$py" -c "import json,sys; j = json.load(open(sys.argv[1])); assert 'stress' not in j and 'stress_times_s' not in j['scene']" \
  "$dir/none.json" || { echo "FAIL stress entries without --stress-times"; fail=1; }
exit $fail
