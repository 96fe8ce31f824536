#!/usr/bin/env bash
# The same seed gives identical per-repetition results at 1 and 2 threads (repetition r always
# draws from rep_seed(seed, r)), for both integrators. A fast slider keeps the run short on a
# grooved surface, where the RK4 stepper cannot jump over the loading phase.
# Usage: threads_determinism.sh SPRINGBLOCK PYTHON
set -u
sb=$1
py=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
for m in rk4 event; do
  for t in 1 2; do
    "$sb" run --N 40 --reps 4 --seed 11 --duration 3t0 --pattern periodic:3,1 --velocity 5cm/s --threads $t \
      --method $m --json >"$dir/$m$t.json" 2>/dev/null || { echo "FAIL run with --method $m --threads $t"; exit 1; }
  done
  "$py" -c '
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
ra, rb = a["runs"], b["runs"]
bad = [i for i in range(len(ra)) if (ra[i]["mu_s"], ra[i]["mu_d"]) != (rb[i]["mu_s"], rb[i]["mu_d"])]
if len(ra) != 4 or len(rb) != 4 or bad or a["mu_s"] != b["mu_s"] or a["mu_d"] != b["mu_d"]:
    print("FAIL", sys.argv[3], "results differ between 1 and 2 threads at repetitions", bad); sys.exit(1)
print(sys.argv[3] + ": identical per-repetition mu_s, mu_d at 1 and 2 threads")
' "$dir/${m}1.json" "$dir/${m}2.json" "$m" || exit 1
done
