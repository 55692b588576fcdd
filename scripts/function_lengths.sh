#!/bin/bash
# The longest functions of the C++ sources (non-blank lines between a
# function's opening and closing brace at the start of a line, the project's
# layout; functions defined inside class bodies are not measured).
#   scripts/function_lengths.sh [N]     the N longest (default 10)
# Exit status 1 when any function is longer than 80 lines.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
N="${1:-10}"
cd "$ROOT"
find libvslam apps tests -name '*.cpp' | sort | xargs awk '
  FNR == 1 { inside = 0; prev = "" }
  /^\{/ && !inside {
    if (prev !~ /^(namespace|struct|class|enum|union|extern)/ && prev !~ /=\s*$/) {
      inside = 1; name = prev; start = FNR; lines = 0
    }
    next
  }
  inside && /^\}/ { printf "%d %s:%d %s\n", lines, FILENAME, start, name; inside = 0; next }
  inside && NF > 0 { lines++ }
  NF > 0 { prev = $0 }
' | sort -rn > /tmp/vslam_function_lengths.$$
head -n "$N" /tmp/vslam_function_lengths.$$ | cut -c1-160
over=$(awk '$1 > 80' /tmp/vslam_function_lengths.$$ | wc -l)
rm -f /tmp/vslam_function_lengths.$$
echo "functions over 80 lines: $over"
[[ "$over" -eq 0 ]]
