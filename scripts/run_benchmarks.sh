#!/bin/bash
# Filter speed and memory (doc/benchmarks.md): one process per configuration
# (so peak memory is per configuration), pinned to one core, median of
# several repetitions. Prints a Markdown table.
#
#   scripts/run_benchmarks.sh [REPETITIONS] [PARTICLES] [LANDMARKS] [VARIANT]
#
# Defaults: 5, "100 200 500 1000 2000", "10 100 1000 10000 100000", optimal_nominal.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BENCH="${VSLAM_BIN:-$ROOT/build/bin}/bench_filter"
REPS="${1:-5}"
PARTICLES="${2:-100 200 500 1000 2000}"
LANDMARKS="${3:-10 100 1000 10000 100000}"
VARIANT="${4:-optimal_nominal}"
[[ -x "$BENCH" ]] || { echo "error: $BENCH not built (scripts/setup.sh build)" >&2; exit 1; }
PIN=()
command -v taskset > /dev/null && PIN=(taskset -c 0)

echo "| particles | landmarks | updates/s (median) | time per update [us] | peak memory [MiB] | resamplings per update |"
echo "|---|---|---|---|---|---|"
for p in $PARTICLES; do
  for l in $LANDMARKS; do
    "${PIN[@]}" "$BENCH" --benchmark_filter="^Update/$VARIANT/$p/$l\$" \
      --benchmark_repetitions="$REPS" --benchmark_report_aggregates_only=true \
      --benchmark_format=csv 2> /dev/null |
      awk -F, -v p="$p" -v l="$l" '$1 ~ /_median"?$/ {
        # name,iterations,real_time,cpu_time,time_unit,bytes_per_second,items_per_second,label,error_occurred,error_message,peak_MiB,resamplings_per_update
        printf "| %s | %s | %.0f | %.1f | %.0f | %.2f |\n", p, l, $7, $4, $11, $12 }'
  done
done
