#!/usr/bin/env bash
# Before/after comparison of two bench_planner builds on one machine in one run:
#   bash tools/benchmarks/compare_planner.sh BEFORE_BIN AFTER_BIN [ROUNDS] [MIN_TIME]
# The two programs run alternately, ROUNDS times each (default 5, --benchmark_min_time MIN_TIME,
# default 0.5 s), so that load from other work hits both alike. Per problem class it prints the best
# (lowest) over the rounds of the mean per plan (CPU time over the whole set in one loop), the
# per-problem median and the 99th percentile, and the ratios after / before, as a Markdown table.
set -euo pipefail

before="${1:?usage: compare_planner.sh BEFORE_BIN AFTER_BIN [ROUNDS] [MIN_TIME]}"
after="${2:?usage: compare_planner.sh BEFORE_BIN AFTER_BIN [ROUNDS] [MIN_TIME]}"
rounds="${3:-5}"
min_time="${4:-0.5}"
out="$(mktemp -d)"
trap 'rm -rf "${out}"' EXIT

for ((r = 1; r <= rounds; ++r)); do
  for side in before after; do
    bin="${before}"
    [[ "${side}" == after ]] && bin="${after}"
    # Lines: "BM_name <time> ns <cpu> ns <iterations> key=value…"; counters may carry a k suffix.
    "${bin}" --benchmark_min_time="${min_time}" 2> /dev/null | awk -v side="${side}" '
      function num(s) {
        if (s ~ /k$/) return substr(s, 1, length(s) - 1) * 1e3;
        if (s ~ /M$/) return substr(s, 1, length(s) - 1) * 1e6;
        return s + 0;
      }
      /^BM_/ {
        median = ""; p99 = "";
        for (i = 6; i <= NF; ++i) {
          split($i, kv, "=");
          if (kv[1] == "median_ns") median = num(kv[2]);
          if (kv[1] == "p99_ns") p99 = num(kv[2]);
        }
        print side, $1, $4, median, p99;
      }' >> "${out}/runs"
  done
  echo "round ${r}/${rounds} done (load average $(cut -d' ' -f1-3 /proc/loadavg))" >&2
done

awk '
  function best(key, v) { if (!(key in b) || v < b[key]) b[key] = v; }
  { names[$2] = 1; best($1 SUBSEP $2 SUBSEP "mean", $3); best($1 SUBSEP $2 SUBSEP "median", $4);
    best($1 SUBSEP $2 SUBSEP "p99", $5); }
  END {
    print "| benchmark | mean before | mean after | ratio | median before | median after | ratio | p99 before | p99 after | ratio |";
    print "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |";
    n = split("BM_PlanPositionRestToRest BM_PlanPositionFromAnyState BM_PlanVelocity", order, " ");
    for (k = 1; k <= n; ++k) {
      name = order[k];
      if (!(name in names)) continue;
      line = "| " name;
      split("mean median p99", what, " ");
      for (w = 1; w <= 3; ++w) {
        x = b["before" SUBSEP name SUBSEP what[w]]; y = b["after" SUBSEP name SUBSEP what[w]];
        line = line sprintf(" | %.0f ns | %.0f ns | %.2f", x, y, y / x);
      }
      print line " |";
    }
  }' "${out}/runs"
