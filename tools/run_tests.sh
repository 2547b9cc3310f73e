#!/usr/bin/env bash
# The whole test suite: set up, then
#   1. a Release build with warnings as errors → ctest (every test, the install checks too);
#   2. a build under AddressSanitizer + UndefinedBehaviorSanitizer → ctest again (tests that
#      count allocations and the install checks are left out there);
#   3. the fuzz targets (tests/fuzz, clang-14 + libFuzzer): those in the timed list
#      (`ncsdk_fuzz_timed` in tests/fuzz/CMakeLists.txt) run NCSDK_FUZZ_SECONDS (60 s) each from
#      their seed corpus, and every target replays its kept inputs, so that a regression shows.
# Exits non-zero when a build or a test fails. The last line sums up the three runs as
# "run_tests: N passed, M failed". No benchmarks. Each step prints its wall and CPU seconds
# ("time: ..."; CPU is user + sys of all its processes), so that a CI log shows where the time goes.
set -uo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
jobs="$(nproc 2> /dev/null || echo 2)"

# phase_time <label>: the report format of the next `time` (bash keyword: the step's own processes).
phase_time() {
  TIMEFORMAT="time: $1 %R s wall, %U s user + %S s sys"
}

phase_time setup
time bash "${root}/tools/setup.sh" || exit 1

# run <label> <build dir> <cmake args…>: configure, build, test; sets result_<label>.
run() {
  local label="$1" build="$2"
  shift 2
  echo "=== ${label}: configure and build (${build}) ==="
  if ! cmake -S "${root}" -B "${build}" -DNCSDK_BUILD_TESTS=ON -DNCSDK_BUILD_SAMPLES=ON \
      -DNCSDK_BUILD_BENCHMARKS=OFF "$@"; then
    printf -v "result_${label}" '%s' "configure failed"
    return 1
  fi
  if ! cmake --build "${build}" -j "${jobs}"; then
    printf -v "result_${label}" '%s' "build failed"
    return 1
  fi
  echo "=== ${label}: ctest ==="
  local log="${build}/ctest-summary.log"
  ctest --test-dir "${build}" --output-on-failure -j "${jobs}" | tee "${log}"
  local status=${PIPESTATUS[0]}
  local summary
  summary="$(grep -E '[0-9]+% tests passed' "${log}" | tail -n1)"
  printf -v "result_${label}" '%s' "${summary:-no ctest summary}"
  return "${status}"
}

failed=0
result_release="not run"
result_sanitize="not run"
result_fuzz="not run"

phase_time release
time run release "${root}/build-tests-release" -DCMAKE_BUILD_TYPE=Release -DNCSDK_WERROR=ON || failed=1

# The sanitizers check every access and every operation at any optimisation level; -Og (rather than
# -O1) compiles a test file about twice as fast and still runs the passes that UBSan's object-size
# check needs (at -O0 that check finds nothing; docs/performance.md, "The test command's time").
# -g1 gives the line tables a report's stack needs (full -g made the slowest test files compile
# about 1.5x longer).
# Warnings are not errors here: GCC's instrumentation gives false maybe-uninitialized warnings
# inside libstdc++ (the Release build above holds the code to zero warnings).
phase_time sanitize
time ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0}" \
  UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}" \
  run sanitize "${root}/build-tests-sanitize" -DNCSDK_SANITIZE=ON -DNCSDK_WERROR=OFF \
  -DCMAKE_BUILD_TYPE=Debug \
  "-DCMAKE_CXX_FLAGS_DEBUG=-Og -g1" || failed=1

# The fuzz build holds only the libraries (instrumented) and the three targets (not the ncsdk_run
# runner, which no target uses); its CTest file lives in tests/fuzz. The targets run one at a time: each uses a whole core for its 60 s.
fuzz_build="${root}/build-tests-fuzz"
echo "=== fuzz: configure and build (${fuzz_build}) ==="
if ! cmake -S "${root}" -B "${fuzz_build}" -DCMAKE_CXX_COMPILER=clang++-14 -DNCSDK_FUZZ=ON \
    -DNCSDK_BUILD_TESTS=OFF -DNCSDK_BUILD_SAMPLES=OFF -DNCSDK_BUILD_BENCHMARKS=OFF \
    -DNCSDK_BUILD_RUNNER=OFF -DCMAKE_BUILD_TYPE=Release -DNCSDK_FUZZ_SECONDS="${NCSDK_FUZZ_SECONDS:-60}"; then
  result_fuzz="configure failed"
  failed=1
elif phase_time fuzz-build && ! time cmake --build "${fuzz_build}" -j "${jobs}"; then
  result_fuzz="build failed"
  failed=1
else
  echo "=== fuzz: ctest (each target ${NCSDK_FUZZ_SECONDS:-60} s) ==="
  fuzz_log="${fuzz_build}/ctest-summary.log"
  rm -f "${fuzz_build}"/tests/fuzz/work/*/artifacts/*  # only this run's findings are shown below
  phase_time fuzz-ctest
  time ctest --test-dir "${fuzz_build}/tests/fuzz" --output-on-failure -j 1 | tee "${fuzz_log}"
  [[ ${PIPESTATUS[0]} -eq 0 ]] || failed=1
  summary="$(grep -E '[0-9]+% tests passed' "${fuzz_log}" | tail -n1)"
  result_fuzz="${summary:-no ctest summary}"
fi

# A fuzz finding in CI is only worth something if it can be replayed: CI keeps the end of the log
# only, so the reason and the input (base64, at most two inputs of 3 kB) are printed again here.
# Replay: base64 -d > input; build-tests-fuzz/tests/fuzz/fuzz_<target> input.
print_fuzz_findings() {
  local artifacts=("${fuzz_build}"/tests/fuzz/work/*/artifacts/*)
  [[ -e "${artifacts[0]}" ]] || return 0
  echo "=== fuzz findings ==="
  grep -E 'fuzz invariant broken|ERROR: (AddressSanitizer|libFuzzer|UndefinedBehaviorSanitizer)|runtime error' \
    "${fuzz_log}" | head -n 5
  local shown=0 artifact
  for artifact in "${artifacts[@]}"; do
    [[ ${shown} -lt 2 ]] || break
    echo "input ${artifact#"${fuzz_build}/tests/fuzz/work/"} ($(stat -c %s "${artifact}") bytes), base64:"
    head -c 3072 "${artifact}" | base64 -w 0
    echo
    shown=$((shown + 1))
  done
}
[[ -z "${fuzz_log:-}" ]] || print_fuzz_findings

# Totals over the three runs; a run that did not get to ctest counts as one failure.
total_passed=0
total_failed=0
for summary in "${result_release}" "${result_sanitize}" "${result_fuzz}"; do
  if [[ "${summary}" =~ ([0-9]+)\ tests\ failed\ out\ of\ ([0-9]+) ]]; then
    total_failed=$((total_failed + BASH_REMATCH[1]))
    total_passed=$((total_passed + BASH_REMATCH[2] - BASH_REMATCH[1]))
  else
    total_failed=$((total_failed + 1))
  fi
done

echo "=== summary ==="
echo "release:   ${result_release}"
echo "sanitize:  ${result_sanitize}"
echo "fuzz:      ${result_fuzz}"
if [[ ${failed} -eq 0 ]]; then
  echo "run_tests: PASSED all three runs (Release, ASan+UBSan, fuzz targets)"
else
  echo "run_tests: FAILED (see above)"
fi
echo "run_tests: ${total_passed} passed, ${total_failed} failed"
exit "${failed}"
