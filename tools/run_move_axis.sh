#!/usr/bin/env bash
# The main job: set up, build the MoveAxis sample (seed 000 §4.3) and run it.
#
# Usage: bash tools/run_move_axis.sh [output folder, default out/]
# Writes <out>/move_axis.csv (the scope trace) and <out>/move_axis.svg (the plot) and prints a
# summary. Exits non-zero if the axis does not reach 2000 mm and return to 0 mm.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="${1:-${root}/out}"
build="${root}/build-move-axis"
jobs="$(nproc 2> /dev/null || echo 2)"

bash "${root}/tools/setup.sh"
cmake -S "${root}" -B "${build}" -DCMAKE_BUILD_TYPE=Release \
  -DNCSDK_BUILD_TESTS=OFF -DNCSDK_BUILD_SAMPLES=ON -DNCSDK_BUILD_BENCHMARKS=OFF > /dev/null
cmake --build "${build}" -j "${jobs}" --target move_axis

# The sample prints its summary and where it wrote the trace and the plot.
"${build}/samples/move_axis/move_axis" "${out}"
