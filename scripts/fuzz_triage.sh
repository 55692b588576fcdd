#!/bin/bash
# Sorts the findings of scripts/fuzz.sh by where they happen: for each saved
# input, reruns the target on it and reports the innermost stack frame that
# is not the sanitizer, libFuzzer or the C/C++ runtime: a frame in vslam's
# code is ours to fix (and becomes a regression test); one in libmrpt-* is
# inside MRPT's own deserialization.
#
#   scripts/fuzz_triage.sh [TARGET]      (default fuzz_rawlog)
set -uo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
TARGET="${1:-fuzz_rawlog}"
DIR="$ROOT/build-fuzz/findings/$TARGET"
[[ -d "$DIR" ]] || { echo "no findings folder $DIR" >&2; exit 1; }
for f in "$DIR"/crash-* "$DIR"/timeout-* "$DIR"/oom-*; do
  [[ -e "$f" ]] || continue
  kind="$(basename "$f" | cut -d- -f1)"
  # -malloc_limit_mb: an out-of-memory shows the stack of the one huge allocation.
  frame="$(ASAN_SYMBOLIZER_PATH=/usr/bin/llvm-symbolizer timeout 60 "$ROOT/build-fuzz/bin/$TARGET" -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=512 "$f" 2>&1 |
    grep -E '^ +#[0-9]+ ' |
    grep -vE 'sanitizer_|fuzzer::|RunMallocHooks|__asan::|__asan|__ubsan|libc\.so|libstdc\+\+\.so|libm\.so| in operator new| in malloc| in calloc| in realloc|_start|__libc|LLVMFuzzerTestOneInput|__memset|__memcpy|__memmove' |
    head -n 1)"
  where="other"
  [[ "$frame" == *libmrpt-* ]] && where="MRPT: $(grep -oE ' in .*\(' <<< "$frame" | cut -c5-90)"
  [[ "$frame" == *"$ROOT"* ]] && where="vslam: $(grep -oE "$ROOT/[^ ]+" <<< "$frame" | sed "s|$ROOT/||")"
  [[ -z "$frame" ]] && where="(no stack: did not reproduce)"
  echo "$kind	$where"
done | sort | uniq -c | sort -rn
