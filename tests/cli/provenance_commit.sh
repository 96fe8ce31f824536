#!/usr/bin/env bash
# The provenance of a run names the commit the binary was built from (read at build time), not
# the one the build tree was configured at: it must equal the source tree's HEAD, "-dirty" when
# tracked files differ. (Outside a git checkout there is nothing to compare: skipped.)
# Usage: provenance_commit.sh SPRINGBLOCK PYTHON
set -u
sb=$1
py=$2
src=$(cd "$(dirname "$0")" && git rev-parse --show-toplevel 2>/dev/null) || { echo "not a git checkout: skipped"; exit 0; }
head=$(git -C "$src" rev-parse --short=12 HEAD)
[ -n "$(git -C "$src" status --porcelain --untracked-files=no)" ] && head="$head-dirty"
got=$("$sb" run --N 20 --reps 1 --duration 2t0 --json 2>/dev/null | "$py" -c 'import json,sys; print(json.load(sys.stdin)["provenance"]["commit"])')
[ "$got" = "$head" ] || { echo "FAIL provenance commit '$got', source tree at '$head' (rebuild, or the commit is read at configure time)"; exit 1; }
echo "provenance commit ok ($got)"
