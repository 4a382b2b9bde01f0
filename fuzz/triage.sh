#!/usr/bin/env bash
# Groups saved fuzz inputs (crash-*, timeout-*, oom-*) by what went wrong: one line per kind
# of finding with its count and one input that shows it. Run each again for the details:
#   FAIRSPLINES_FUZZ_PRINT=1 build-fuzz/fuzz/<harness> <input>
# Usage: fuzz/triage.sh build-fuzz/fuzz/<harness> <input>...
set -uo pipefail
harness=$1
shift
declare -A count example
for input in "$@"; do
  out=$(timeout 60 "$harness" -timeout=20 "$input" 2>&1)
  if line=$(grep -m1 -o "FairSplines fuzz finding in .*" <<<"$out"); then
    # the call and the kind of problem, without the numbers of this input
    sig=$(sed -E 's/ \(.*$//; s/: [^:]*escaped: .*/&/' <<<"$line" | sed -E 's/[-+]?[0-9][0-9.e+-]*//g')
  elif line=$(grep -m1 "runtime error:" <<<"$out"); then
    sig="UBSan $(sed -E 's/^.*\/(cpp|fuzz|usr\/include)\//\1\//; s/runtime error: //' <<<"$line" | sed -E "s/ of type .*//; s/'[^']*'//g")"
  elif line=$(grep -m1 -o "Assertion .* failed" <<<"$out"); then
    frame=$(grep -m1 -oE "/cpp/kernel/src/[a-z_0-9]+\.cpp:[0-9]+" <<<"$out")
    sig="assertion ${line:0:80}... at ${frame#/}"
  elif line=$(grep -m1 -o "ERROR: AddressSanitizer: [a-z-]*" <<<"$out"); then
    frame=$(grep -m1 -oE "/cpp/kernel/src/[a-z_0-9]+\.cpp:[0-9]+" <<<"$out")
    sig="ASan ${line#ERROR: AddressSanitizer: } at ${frame#/}"
  elif grep -q "ALARM: working on the last Unit for\|libFuzzer: timeout" <<<"$out"; then
    sig="timeout"
  elif grep -q "out-of-memory" <<<"$out"; then
    sig="out of memory"
  elif grep -q "deadly signal\|ERROR:" <<<"$out"; then
    sig="other: $(grep -m1 "ERROR:" <<<"$out" | sed -E 's/==[0-9]+==//')"
  else
    sig="no longer reproduces"
  fi
  count[$sig]=$((${count[$sig]:-0} + 1))
  [ -n "${example[$sig]:-}" ] || example[$sig]=$input
done
for sig in "${!count[@]}"; do
  printf '%4d  %s\n      e.g. %s\n' "${count[$sig]}" "$sig" "${example[$sig]}"
done | paste - - | sort -rn | tr '\t' '\n'
