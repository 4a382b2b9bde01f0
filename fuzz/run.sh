#!/usr/bin/env bash
# Runs every harness built in BUILD/fuzz for SECONDS each from its seed corpus
# fuzz/corpus/<harness>/ (new inputs go to BUILD/corpus/<harness>/, the repository's corpus
# is only read), one input at most TIMEOUT seconds. Prints each harness's executions and
# whether it ran clean; findings are saved in BUILD/findings/. Exits 1 if there is one.
# FUZZ_SEED=N fixes libFuzzer's random seed, so that a run from the committed corpus makes the
# same inputs in the same order (CI: a finding there is one anybody can replay; without a
# seed each run explores anew).
# Usage: fuzz/run.sh BUILD [SECONDS] [TIMEOUT] [HARNESS...]   (make fuzz)
set -uo pipefail
build=$1
seconds=${2:-30}
timeout=${3:-5}
shift $(($# < 3 ? $# : 3))
here=$(cd "$(dirname "$0")" && pwd)
harnesses=("$@")
if [ ${#harnesses[@]} -eq 0 ]; then
  for source in "$here"/fuzz_*.cpp; do harnesses+=("$(basename "$source" .cpp)"); done
fi
# Leaks are checked too: OpenCASCADE (not instrumented) needs no suppression so far.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1}
mkdir -p "$build/findings" "$build/logs"
failed=0
summary=()
for h in "${harnesses[@]}"; do
  mkdir -p "$build/corpus/$h"
  log=$build/logs/$h.log
  start=$SECONDS
  "$build/fuzz/$h" ${FUZZ_SEED:+-seed="$FUZZ_SEED"} -max_total_time="$seconds" -timeout="$timeout" -max_len=512 -print_final_stats=1 \
    -artifact_prefix="$build/findings/$h-" "$build/corpus/$h" "$here/corpus/$h" >"$log" 2>&1
  rc=$?
  runs=$(grep -o "stat::number_of_executed_units: [0-9]*" "$log" | tail -1 | grep -o "[0-9]*$")
  rate=$(grep -oE "exec/s: [0-9]+" "$log" | tail -1 | grep -oE "[0-9]+$")
  if [ $rc -eq 0 ]; then
    verdict="clean"
  else
    failed=1
    what=$(grep -m1 -oE "FairSplines fuzz finding in .*|runtime error: .*|ERROR: AddressSanitizer: [a-z-]+|ERROR: libFuzzer: [a-z -]+|ERROR: LeakSanitizer.*" "$log")
    input=$(grep -m1 -oE "Test unit written to .*" "$log" | sed 's/Test unit written to //')
    verdict="FINDING: ${what:-exit code $rc} (input: ${input:-none}; log: $log)"
  fi
  line=$(printf '%-24s %10s executions %7s exec/s %4d s  %s' "$h" "${runs:-?}" "${rate:-?}" $((SECONDS - start)) "$verdict")
  echo "$line"
  summary+=("$line")
done
echo "=== fuzz: ${#harnesses[@]} harnesses, ${seconds} s each"
printf '%s\n' "${summary[@]}"
exit $failed
