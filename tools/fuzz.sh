#!/usr/bin/env bash
# libFuzzer on the job parser (cutcell::parseJob, harness tests/fuzz/job_parser_fuzz.cpp).
# Builds core + the harness with clang-14 in build-fuzz (no Qt, no GUI), or takes the harness
# of a given build configured with clang and -DCUTCELL_FUZZ=ON (tools/setup.sh test passes its
# sanitised build-asan), then fuzzes for the given seconds (default 60) from the seeds in
# tests/fuzz/corpus (never modified; new inputs go to <build>/corpus).
#   tools/fuzz.sh [seconds [build-dir]]
# Every input that crashes, throws anything but JobError, trips ASan/UBSan (float-cast-overflow
# included), allocates over 1 GB or runs over 10 s is saved to <build>/findings/ and run
# again to get its report. Reports that match a line of tests/fuzz/known_findings.txt
# (defects already filed, reproducers in tests/fuzz/findings/) are listed as known; any other
# finding fails the script (exit 1). Remove a line from known_findings.txt once its defect
# is fixed, so a regression fails again.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
build="${2:-build-fuzz}"
if [ -n "${2:-}" ]; then
  grep -q '^CUTCELL_FUZZ:BOOL=ON' "$build/CMakeCache.txt" 2>/dev/null ||
    { echo "$build is not configured with -DCUTCELL_FUZZ=ON (clang)" >&2; exit 2; }
else
  launcher=()
  command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
  # -O1 and line tables only: the fuzzer's reports keep files and lines; about 15 % less build
  # time.
  CC=clang-14 CXX=clang++-14 cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only -DNDEBUG" \
    "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only -DNDEBUG" \
    -DCUTCELL_FUZZ=ON -DCUTCELL_BUILD_GUI=OFF -DCUTCELL_BUILD_TESTS=OFF "${launcher[@]}" >/dev/null
fi
cmake --build "$build" -j 2 --target job_parser_fuzz
fuzzer="$build/tests/fuzz/job_parser_fuzz"
limits=(-timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=1024 -max_len=65536)
mkdir -p "$build/corpus"
rm -rf "$build/findings"
mkdir -p "$build/findings"

# The seeds first, each once: they hold no known crasher (those are in tests/fuzz/findings/),
# so any failure here is a regression. (Fork mode below drops a crashing seed silently.)
echo "== seeds: tests/fuzz/corpus"
"$fuzzer" -runs=0 "${limits[@]}" -artifact_prefix="$build/findings/seed-" tests/fuzz/corpus \
  >"$build/seeds.log" 2>&1 || { tail -30 "$build/seeds.log" >&2; echo "a seed input fails" >&2; exit 1; }

# Fork mode keeps fuzzing after a finding, so a known defect does not end the run early.
echo "== fuzzing cutcell::parseJob for $seconds s"
"$fuzzer" "$build/corpus" tests/fuzz/corpus -dict=tests/fuzz/job.dict "${limits[@]}" \
  -max_total_time="$seconds" -fork=1 -ignore_crashes=1 -ignore_ooms=1 -ignore_timeouts=1 \
  -artifact_prefix="$build/findings/" -print_final_stats=1 >"$build/fuzz.log" 2>&1 || true
grep -E "^#[0-9]+.*DONE|INFO: fuzzed for|stat::number_of_executed_units|exec/s" "$build/fuzz.log" | tail -3 || true

known=0 new=0
shopt -s nullglob
for f in "$build"/findings/{crash,leak,oom,timeout,slow-unit}-*; do
  report=$("$fuzzer" "${limits[@]}" "$f" 2>&1 || true)
  summary=$(grep -m1 -E "SUMMARY|ERROR: libFuzzer|terminate called|what\(\)" <<<"$report" || echo "(no report)")
  if grep -qvE '^[[:space:]]*(#|$)' tests/fuzz/known_findings.txt &&
     grep -qEf <(grep -vE '^[[:space:]]*(#|$)' tests/fuzz/known_findings.txt) <<<"$report"; then
    known=$((known + 1))
    echo "known finding: $f: $summary"
  else
    new=$((new + 1))
    echo "NEW FINDING: $f: $summary" >&2
    echo "$report" | head -40 >&2
  fi
done
echo "== fuzzing: $known known finding(s), $new new"
[ "$new" -eq 0 ]
