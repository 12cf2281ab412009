#!/usr/bin/env bash
# Fuzzing of both packages with libFuzzer (Debian's clang), AddressSanitizer and
# UndefinedBehaviorSanitizer.
#   bash scripts/fuzz.sh SECONDS [HARNESS...]
# builds the harnesses (all of them by default: test/*/fuzz_*.cpp) in build-fuzz/ and runs each
# for SECONDS, starting from its seed corpus (test/<Pkg>/data/fuzz/<name>/, read only) and from
# what earlier runs here found (build-fuzz/corpus/<harness>/). On a finding (a crash, a sanitizer
# report, a failed check, a time-out of 30 s or 2 GB of memory on one input) it prints the
# report, keeps the input in build-fuzz/findings/<harness>/ and exits with 1: once the defect is
# fixed, copy that input into the seed corpus, where ctest replays it with every build
# (cmake/Urban_fuzzing.cmake). The fuzzers' random choices start from FUZZ_SEED (default 1, so
# that a run is repeatable; 0: a seed of libFuzzer's choice).
set -euo pipefail
seconds="${1:-}"
case "$seconds" in ''|*[!0-9]*) echo "usage: $0 SECONDS [HARNESS...]" >&2; exit 2 ;; esac
shift
cd "$(dirname "$0")/.."

harnesses=("$@")
if [ ${#harnesses[@]} -eq 0 ]; then
  for source in test/*/fuzz_*.cpp; do harnesses+=("$(basename "$source" .cpp)"); done
fi
jobs="$(nproc 2>/dev/null || echo 2)"
cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++ -DURBAN_FUZZING=ON \
      -DBUILD_TESTING=ON -DURBAN_BUILD_EXAMPLES=OFF -DURBAN_WITH_MPI=OFF -DURBAN_CGAL_DATA_ARCHIVE= \
      > build-fuzz.configure.log 2>&1 ||
  { cat build-fuzz.configure.log; exit 1; }
rm -f build-fuzz.configure.log
cmake --build build-fuzz -j"$jobs" --target "${harnesses[@]}"

status=0
for harness in "${harnesses[@]}"; do
  seeds=(test/*/data/fuzz/"${harness#fuzz_}")
  if [ ! -d "${seeds[0]}" ]; then echo "error: no seed corpus for $harness" >&2; exit 1; fi
  corpus="build-fuzz/corpus/$harness"
  findings="build-fuzz/findings/$harness"
  mkdir -p "$corpus" "$findings"
  log="build-fuzz/$harness.log"
  # the binary sits in the folder of its test/<Pkg>
  program="$(find build-fuzz/test -type f -name "$harness" -perm -u+x | head -n 1)"
  echo "== $harness: ${seconds} s from ${seeds[0]}"
  if "$program" "$corpus" "${seeds[0]}" -seed="${FUZZ_SEED:-1}" -max_total_time="$seconds" -timeout=30 -rss_limit_mb=2048 \
       -artifact_prefix="$findings/" -print_final_stats=1 > "$log" 2>&1; then
    grep -E "^stat::number_of_executed_units|^stat::peak_rss_mb" "$log" | tr '\n' ' '
    echo
  else
    status=1
    echo "FINDING in $harness (input kept in $findings/):"
    grep -v -E "^#[0-9]+|^INFO:|^stat::" "$log" | tail -n 40
  fi
done
exit $status
