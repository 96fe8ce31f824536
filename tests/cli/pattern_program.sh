#!/usr/bin/env bash
# springblock_pattern (the figures' mask builder, built by reproduce-all instead of the whole tool)
# prints exactly what `springblock pattern` prints, and refuses bad input the same way (exit 2,
# nothing on stdout). Usage: pattern_program.sh SPRINGBLOCK PYTHON
set -u
sb=$1
sp="$(dirname "$sb")/springblock_pattern"
fail=0
[ -x "$sp" ] || { echo "FAIL: $sp is not built"; exit 1; }

for args in "--N 120 --pattern smooth" "--N 360 --pattern periodic:10,10" \
            "--N 120 --pattern hierarchical:40,8,1" "--N 90 --pattern periodic:3,6 --layout symmetric" \
            "--N 240 --pattern hierarchical:60,6 --layout groove_first,pawl_first" \
            "--N 24 --pattern hierarchical:6/2,2/1" "--N 6 --pattern mask:011101"; do
  # shellcheck disable=SC2086  # ARGS is a list of words on purpose
  want=$("$sb" pattern $args) || { echo "FAIL springblock pattern $args: exit $?"; fail=1; continue; }
  # shellcheck disable=SC2086
  got=$("$sp" pattern $args) || { echo "FAIL springblock_pattern pattern $args: exit $?"; fail=1; continue; }
  [ "$got" = "$want" ] || { echo "FAIL [$args]: the two programs differ"; fail=1; }
  # A mask of N characters of 0/1, then S/S_tot.
  n=${args#--N }; n=${n%% *}
  mask=$(head -1 <<<"$got")
  [[ ${#mask} -eq $n && $mask =~ ^[01]+$ ]] || { echo "FAIL [$args]: mask '$mask' is not $n zeros and ones"; fail=1; }
done

# ARGS|what the message must name (the field and its allowed range or the offending value).
err=$(mktemp)
for case in "--N 0 --pattern smooth|--N: Value 0 not in range 1 to 1000000" \
            "--N 10 --pattern periodic:20,5|invalid pattern" "--N 10 --pattern zigzag:1|invalid pattern" \
            "--N 5 --pattern mask:011101|N = 5" "--N 4 --pattern mask:01a1|character 3 of 4"; do
  bad=${case%%|*} named=${case#*|}
  # shellcheck disable=SC2086
  out=$("$sp" pattern $bad 2>"$err"); rc=$?
  [ "$rc" -eq 2 ] || { echo "FAIL [$bad]: exit $rc, expected 2"; fail=1; }
  [ -z "$out" ] || { echo "FAIL [$bad]: printed '$out' on a refusal"; fail=1; }
  grep -qF -- "$named" "$err" || { echo "FAIL [$bad]: message lacks '$named': $(cat "$err")"; fail=1; }
done
rm -f "$err"
[ "$fail" -eq 0 ] && echo "springblock_pattern: same masks as springblock pattern, bad input refused"
exit "$fail"
