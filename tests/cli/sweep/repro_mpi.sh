#!/usr/bin/env bash
# A reproduction target started by mpirun -np 2 refuses with exit 2, names mpirun, and writes
# nothing: the targets run on one process's threads, and each rank would run the whole target and
# write the same file. Under mpirun -np 1 it is not refused (it reaches its own option check).
# Usage: repro_mpi.sh TARGET MPIEXEC
set -u
target=$1 mpirun=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail=0
"$mpirun" --oversubscribe --allow-run-as-root -np 2 "$target" --tier smoke --out "$dir/out" >/dev/null 2>"$dir/err"
rc=$?
[ $rc -eq 2 ] || { echo "FAIL under mpirun -np 2 the target exited $rc, not 2"; cat "$dir/err"; fail=1; }
grep -q "invalid mpirun: OMPI_COMM_WORLD_SIZE = 2" "$dir/err" || { echo "FAIL mpirun was not named"; cat "$dir/err"; fail=1; }
[ -e "$dir/out" ] && { echo "FAIL a refused target left its output directory"; fail=1; }
"$mpirun" --oversubscribe --allow-run-as-root -np 1 "$target" --tier no-such-tier --out "$dir/out" >/dev/null 2>"$dir/err1"
grep -q "invalid mpirun" "$dir/err1" && { echo "FAIL one rank was refused"; cat "$dir/err1"; fail=1; }
[ $fail -eq 0 ] && echo "a reproduction target under mpirun -np 2 is refused with exit 2, nothing written"
exit $fail
