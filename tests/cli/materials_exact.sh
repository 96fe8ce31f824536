#!/usr/bin/env bash
# The event method on chains whose blocks differ in slider spring, mass or internal springs, run by
# the general modes (one shape per run, K Q = W Q diag(lambda)):
#   1. every block's springs and mass doubled by a materials file gives, repetition by repetition,
#      the mu_s of the uniform chain whose K_s, K_int and m are doubled by its parameters (the
#      closed-form modes): to 1e-9 relative, coupled and at K_int = 0 (the per-block solver);
#   2. on a composite chain (hard and soft segments of five blocks, contrasts 10 in K_int, 3 in
#      mass, 2 in K_s, on a patterned surface) the exact stepper and Dormand-Prince steps at
#      tol 1e-12 give each repetition's mu_s to 1e-4 relative: the modes against direct forces.
#      The tolerance is Dormand-Prince's own: at tol 1e-11 it is 2e-4 from the exact value on one
#      repetition (a peak inside a slip), at 1e-12 2e-5, converging on it.
# A projection that forgets the masses' weights puts the two up to 6e-2 apart (relative) and breaks 2.
# Usage: materials_exact.sh SPRINGBLOCK PYTHON
set -u
sb=$1
py=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail=0

"$py" - "$dir" <<'PY'
import sys
d = sys.argv[1]
N = 40
with open(f"{d}/twice.tsv", "w") as f:
    f.write("k_s_scale\tmass_scale\tk_int_scale\n" + "2\t2\t2\n" * N)
with open(f"{d}/composite.tsv", "w") as f:
    f.write("k_int_scale\tmass_scale\tk_s_scale\n")
    for i in range(N):
        hard = (i // 5) % 2 == 0
        f.write("10\t3\t1.5\n" if hard else "1\t1\t0.7\n")
PY

mu_s() {  # mu_s ARGS...: each repetition's mu_s, one per line
  "$sb" run --N 40 --pattern periodic:3,2 --reps 6 --seed 5 --threads 2 --stop-after-mu-s true --json "$@" |
    "$py" -c 'import json, sys; [print(repr(r["mu_s"])) for r in json.load(sys.stdin)["runs"]]'
}

compare() {  # compare NAME TOLERANCE FILE_A FILE_B
  "$py" - "$@" <<'PY' || fail=1
import sys
name, tol, a, b = sys.argv[1], float(sys.argv[2]), sys.argv[3], sys.argv[4]
x = [float(v) for v in open(a)]
y = [float(v) for v in open(b)]
worst = max(abs(p - q) / abs(q) for p, q in zip(x, y)) if x and len(x) == len(y) else float("inf")
ok = len(x) == 6 and worst <= tol
print(f"{'ok' if ok else 'FAIL'} {name}: {len(x)} repetitions, largest relative difference {worst:.2e} (tolerance {tol:g})")
sys.exit(0 if ok else 1)
PY
}

for k_int in 1 0; do
  mu_s --materials "$dir/twice.tsv" --k-int-scale $k_int > "$dir/a" || fail=1
  mu_s --shear-modulus 10MPa --density 2.4g/cm3 --k-int-scale $((2 * k_int)) > "$dir/b" || fail=1
  compare "doubled by file = doubled by parameters, k_int_scale $k_int" 1e-9 "$dir/a" "$dir/b" || fail=1
done

mu_s --materials "$dir/composite.tsv" > "$dir/exact" || fail=1
mu_s --materials "$dir/composite.tsv" --stepper dopri5 --tol 1e-12 > "$dir/dopri5" || fail=1
compare "composite chain: exact stepper = Dormand-Prince at tol 1e-12" 1e-4 "$dir/exact" "$dir/dopri5" || fail=1

exit $fail
