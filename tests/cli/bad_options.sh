#!/usr/bin/env bash
# Every class of bad option is refused with exit code 2 and a message naming the field, the
# offending value and what is allowed. Usage: bad_options.sh SPRINGBLOCK PYTHON
set -u
sb=$1
fail=0

# expect_error "ARGS" FIELD VALUE_PATTERN RANGE_PATTERN
expect_error() {
  local args=$1 field=$2 value=$3 range=$4 err rc
  # shellcheck disable=SC2086  # ARGS is a list of words on purpose
  local reps="--reps 1"
  [[ $args == *--reps* ]] && reps=""
  err=$("$sb" run $args $reps 2>&1 >/dev/null)
  rc=$?
  if [ "$rc" -ne 2 ]; then
    echo "FAIL [$args]: exit $rc, expected 2 (stderr: $err)"; fail=1; return
  fi
  for pat in "invalid $field" "$value" "$range"; do
    if ! grep -qF -- "$pat" <<<"$err"; then
      echo "FAIL [$args]: message lacks '$pat': $err"; fail=1
    fi
  done
}

# Out of range.
expect_error "--N 0" N "N = 0" "[1, 1000000]"
expect_error "--N 2000000" N "2000000" "[1, 1000000]"
expect_error "--reps 0" reps "reps = 0" "[1, 1000000]"
expect_error "--velocity -1m/s" velocity "-1" "(0, 1000 m/s)"
expect_error "--damping -5/s" damping "-5" "[0, 1e12 /s)"
expect_error "--length 0cm" length "value 0" "(0, 100 m]"
expect_error "--mu-s 0,0.1" mu_s "value 0" "(0, 100]"
expect_error "--mu-d 0.5,-1" mu_d "value -1" "[0, 100]"
expect_error "--k-int-scale -1" k_int_scale "-1" "[0, 1e8]"
expect_error "--dt 10s" dt "10" "(0, 1 s]"
expect_error "--method rk4 --dt 1e-5s" dt "1e-05" "largest stable step"
expect_error "--method rk4 --damping 1e9/s" dt "1e+09" "largest stable step"
expect_error "--tol 1" tol "value 1" "[1e-14, 1e-2]"
expect_error "--sample-dt 0s" sample_dt "value 0" "(0, 10 s]"
# Times that would not stay apart in double arithmetic (more than 1e13 samples or exact steps over
# the run), and a rate that overflowed (omega^2 = inf): the run would never end.
expect_error "--sample-dt 1e-300s" sample_dt "value 1e-300" "at most 1e13 samples over the run"
expect_error "--velocity 1e-300cm/s" sample_dt "duration = 8e+298 s" "from the velocity, load and stiffnesses"
expect_error "--damping 9e11/s --duration 1e4t0" duration "turns 3.6e+15 rad" "at most 7.5e12 rad"
expect_error "--density 1e-300g/cm3" duration "fastest rate inf" "at most 7.5e12 rad"
expect_error "--density 1e-300g/cm3 --k-int-scale 0" duration "fastest rate inf" "at most 7.5e12 rad"
expect_error "--peak-drop 2" peak_drop "value 2" "(0, 1]"
expect_error "--threads 5000" threads "5000" "[0, 1024]"
expect_error "--seed -3" seed "-3" "[0, 18446744073709551615]"
expect_error "--seed 18446744073709551616" seed "18446744073709551616" "[0, 18446744073709551615]"
expect_error "--N 99999999999999999999" N "99999999999999999999" "too large a whole number"
# The largest seed is a seed (results record 64-bit seeds).
"$sb" run --N 10 --reps 1 --duration 2t0 --seed 18446744073709551615 --json 2>/dev/null | grep -q '"seed":18446744073709551615' ||
  { echo "FAIL --seed 18446744073709551615 did not run with that seed"; fail=1; }
expect_error "--pressure 0Pa" pressure "value 0" "(0, 1e12 Pa)"
expect_error "--shear-modulus 0Pa" shear_modulus "value 0" "(0, 1e13 Pa)"
expect_error "--young-modulus 1e14Pa" young_modulus "1e+14" "(0, 1e13 Pa)"
expect_error "--density 0g/cm3" density "value 0" "(0, 1e6 kg/m3)"
expect_error "--l-y 200m" l_y "value 200" "(0, 100 m]"
expect_error "--l-z -1mm" l_z "-0.001" "(0, 100 m]"
expect_error "--duration -1t0" duration "-1" "(0, 1e4] t0"
expect_error "--duration 2e6s" duration "2e+06" "(0, 1e6 s]"
expect_error "--mu-d-skip -1" mu_d_skip "-1" "[0, 1000]"
expect_error "--stop-after-mu-s maybe" stop_after_mu_s "'maybe'" "true or false"
expect_error "--duration 0.5t0 --stress-times 9s" stress_times "9" "[0, duration"
# Not a number / not finite.
expect_error "--velocity nan" velocity "'nan'" "not a finite number"
expect_error "--density NaN" density "'NaN'" "not a finite number"
expect_error "--l-z inf" l_z "'inf'" "not a finite number"
expect_error "--N 1.5" N "'1.5'" "whole number"
expect_error "--mu-d 1" mu_d "'1'" "MEAN,SD"
# Wrong units: the message says which dimension was given and lists the accepted units.
expect_error "--length 5s" length "'5s'" "accepted units: m, cm"
expect_error "--dt 3cm" dt "'3cm'" "accepted units: s, ms"
expect_error "--pressure 5m/s" pressure "'5m/s'" "accepted units: Pa"
expect_error "--velocity 3furlongs" velocity "furlongs" "accepted units"
# Enumerations.
expect_error "--method euler" method "'euler'" "rk4, event"
expect_error "--pair-policy maybe" pair_policy "'maybe'" "clip, keep"
# Surfaces: unknown pattern, grooves longer than the surface, no block in contact.
expect_error "--pattern zigzag:1" pattern "'zigzag'" "expected smooth | periodic:NP,NG"
expect_error "--pattern periodic:0,1" pattern "'0'" "positive"
expect_error "--N 10 --pattern periodic:20,5" pattern "size 20" "N=10"
expect_error "--N 10 --pattern hierarchical:4,16" pattern "size 16" "N=10"
expect_error "--pattern random:0.999" pattern "random:0.999" "no block in contact"
expect_error "--pattern random:1.5" pattern "'1.5'" "[0,1)"
# Scenes that could only give a NaN or an average over no samples (defaults: duration 4 t0 =
# 1.6 s, t0 = 0.4 s, sample_dt 1e-5 s, mu_d_skip 0.25 t0).
# Kinetic friction above static: refused whatever the method or pair policy.
expect_error "--mu-s 1.0,0.1 --mu-d 1.5,0.01" mu_d "value 1.5" "[0, mu_s mean = 1]"
expect_error "--mu-s 1.0,0.1 --mu-d 1.5,0.01 --method rk4" mu_d "value 1.5" "[0, mu_s mean = 1]"
expect_error "--mu-s 1.0,0.1 --mu-d 1.5,0.01 --pair-policy keep" mu_d "value 1.5" "[0, mu_s mean = 1]"
# A sampling step too long for a slip sample and one after it (one, without a mu_d window).
expect_error "--sample-dt 1s" sample_dt "value 1" "(0, duration / 2 = 0.8 s]"
expect_error "--sample-dt 2s --stop-after-mu-s true" sample_dt "value 2" "(0, duration = 1.6 s]"
# A mu_d window that opens after the end of the run, or exactly at it (zero length).
expect_error "--mu-d-skip 10" mu_d_skip "value 10" "[0, (duration - sample_dt) / t0 = 4)"
expect_error "--mu-d-skip 4" mu_d_skip "value 4" "[0, (duration - sample_dt) / t0 = 4)"
expect_error "--duration 0.1t0" mu_d_skip "value 0.25" "lengthen --duration"
expect_error "--duration 0.1s --mu-d-skip 0.3" mu_d_skip "value 0.3" "[0, (duration - sample_dt) / t0 = 0.249998)"

# The pattern subcommand refuses an empty surface too.
"$sb" pattern --N 10 --pattern random:0.99 >/dev/null 2>&1
rc=$?
[ "$rc" -eq 2 ] || { echo "FAIL pattern subcommand with an empty surface: exit $rc"; fail=1; }

[ $fail -eq 0 ] && echo "all bad options refused with exit 2 and a clear message"
exit $fail
