#!/usr/bin/env bash
# Reproduction targets under mpirun: on 1, 2 and 4 oversubscribed ranks a target writes the
# document of one process, bit for bit (same_documents.py: the results without provenance, wall
# times and thread counts), with a plain scene (fig_s1), a borrowed scene whose repetition 0 is
# traced again for its mu(t) series (fig1), stress snapshots (fig3) and scenes sharing one
# trajectory (sensitivity); only rank 0 speaks and writes, once. Bad input is refused once, with
# exit 2 and nothing written; rank 0 interrupted exits 130 and writes nothing.
# Usage: targets_mpi.sh BIN_DIR PYTHON MPIEXEC
set -u
bin=$1 py=$2 mpirun=$3
here=$(cd "$(dirname "$0")" && pwd)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail=0
mpi() { "$mpirun" --oversubscribe --allow-run-as-root "$@"; }
# Each target with its extra options; fig1 reads the one-process fig_s1 (every run reads the same).
targets=(fig_s1 fig1 fig3 sensitivity)
extra() { [ "$1" = fig1 ] && echo "--input $dir/one/fig_s1.json"; }

for t in "${targets[@]}"; do
  # shellcheck disable=SC2046  # extra's words are options
  "$bin/$t" --tier smoke --threads 2 --out "$dir/one" $(extra "$t") >/dev/null 2>"$dir/one_$t.err" ||
    { echo "FAIL $t in one process"; cat "$dir/one_$t.err"; exit 1; }
done
for np in 1 2 4; do
  threads=$([ $np -eq 2 ] && echo 2 || echo 1)  # rank 0 with several threads too
  for t in "${targets[@]}"; do
    out="$dir/np$np" err="$dir/np${np}_$t.err"
    # shellcheck disable=SC2046
    mpi -np $np "$bin/$t" --tier smoke --threads $threads --out "$out" $(extra "$t") >/dev/null 2>"$err" ||
      { echo "FAIL $t under mpirun -np $np"; cat "$err"; fail=1; continue; }
    "$py" "$here/same_documents.py" "$dir/one/$t.json" "$out/$t.json" >/dev/null ||
      { echo "FAIL $t under mpirun -np $np differs from one process"; fail=1; }
    ranks=$("$py" -c 'import json,sys; print(json.load(open(sys.argv[1]))["provenance"]["ranks"])' "$out/$t.json")
    [ "$ranks" = "$np" ] || { echo "FAIL $t -np $np: provenance says $ranks ranks"; fail=1; }
    [ "$(grep -c "^\[$t\] wrote " "$err")" -eq 1 ] || { echo "FAIL $t -np $np: not written exactly once"; cat "$err"; fail=1; }
    first=$(grep -m1 "^\[$t\]   " "$err")
    [ "$(grep -cxF -- "$first" "$err")" -eq 1 ] || { echo "FAIL $t -np $np: a scene reported twice"; fail=1; }
  done
  [ "$(ls -A "$dir/np$np" | wc -l)" -eq ${#targets[@]} ] || { echo "FAIL -np $np left other files:"; ls -A "$dir/np$np"; fail=1; }
  [ $fail -eq 0 ] && echo "mpirun -np $np: ${targets[*]} identical to one process, each written once by rank 0"
done

# Bad input: refused by rank 0 alone, once, exit 2, nothing written.
check_refused() {  # NAME EXPECTED_MESSAGE ARGS...
  local name=$1 msg=$2 rc
  shift 2
  mpi -np 2 "$@" --out "$dir/bad_$name" >/dev/null 2>"$dir/bad_$name.err"
  rc=$?
  [ $rc -eq 2 ] || { echo "FAIL $name under mpirun exited $rc, not 2"; cat "$dir/bad_$name.err"; fail=1; }
  [ "$(grep -cF -- "$msg" "$dir/bad_$name.err")" -eq 1 ] ||
    { echo "FAIL $name: '$msg' not said exactly once"; cat "$dir/bad_$name.err"; fail=1; }
  [ -e "$dir/bad_$name" ] && { echo "FAIL $name left $(ls -A "$dir/bad_$name")"; fail=1; }
}
check_refused tier "fig_s1: --tier: nope not in" "$bin/fig_s1" --tier nope
check_refused input "fig5: invalid input: fig5 needs --input <tab_pat0.json>" "$bin/fig5" --tier smoke
[ $fail -eq 0 ] && echo "bad input under mpirun: refused once by rank 0, exit 2, nothing written"

# Rank 0 interrupted once the run is under way: exit 130, the others stopped, nothing written.
mpi -np 2 "$bin/fig2" --tier paper --threads 1 --out "$dir/int" >/dev/null 2>"$dir/int.err" &
job=$!
rank0=""
for _ in $(seq 600); do
  for p in $(pgrep -f "fig2 --tier paper --threads 1 --out $dir/int"); do
    tr '\0' '\n' <"/proc/$p/environ" 2>/dev/null | grep -qx 'OMPI_COMM_WORLD_RANK=0' && rank0=$p
  done
  [ -n "$rank0" ] && grep -q "scenes," "$dir/int.err" && break
  sleep 0.05
done
[ -n "$rank0" ] && kill -INT "$rank0"
wait $job
rc=$?
[ $rc -eq 130 ] || { echo "FAIL rank 0 interrupted: mpirun exited $rc, not 130"; cat "$dir/int.err"; fail=1; }
grep -q "fig2: interrupted; nothing written" "$dir/int.err" || { echo "FAIL the interrupt was not reported"; fail=1; }
[ -z "$(ls -A "$dir/int" 2>/dev/null)" ] || { echo "FAIL an interrupted run left $(ls -A "$dir/int")"; fail=1; }
[ $fail -eq 0 ] && echo "rank 0 interrupted: exit 130, nothing written"
exit $fail
