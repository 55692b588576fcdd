#!/bin/bash
# Checks the module layers the build declares (BUILD/module_graph.txt, written
# by libvslam/CMakeLists.txt from each module's DEPENDS):
#  1. every #include <libvslam/X/...> in a module's code (tests aside) names
#     the module itself or one it builds on, directly or through others, so a
#     back-edge through a header alone fails too (the layer-check links catch
#     calls);
#  2. doc/architecture.md's module table lists the same graph.
# Usage: scripts/check_layers.sh BUILD/module_graph.txt [SOURCE_DIR]
set -euo pipefail
graph_file="$1"
src="${2:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)}"
declare -A deps
while IFS=: read -r module list; do
  [[ -n "$module" ]] && deps[$module]="${list//,/ }"
done <"$graph_file"

# The modules a module may include: itself and its dependencies' closure.
reachable() {
  local -A seen=()
  local todo=("$1") m d
  while ((${#todo[@]})); do
    m="${todo[0]}"
    todo=("${todo[@]:1}")
    [[ -n "${seen[$m]:-}" ]] && continue
    seen[$m]=1
    for d in ${deps[$m]:-}; do todo+=("$d"); done
  done
  echo "${!seen[@]}"
}

failures=0
for module in "${!deps[@]}"; do
  allowed=" $(reachable "$module") "
  while IFS= read -r hit; do
    file="${hit%%:*}"
    target="$(sed -E 's/.*#include <libvslam\/([a-z]+)\/.*/\1/' <<<"$hit")"
    if [[ "$allowed" != *" $target "* ]]; then
      echo "layer violation: $file includes libvslam/$target/, but module $module does not build on $target" >&2
      failures=$((failures + 1))
    fi
  done < <(grep -HE '#include <libvslam/[a-z]+/' "$src/libvslam/$module"/*.h "$src/libvslam/$module"/*.cpp 2>/dev/null |
    grep -v '_unittest\.cpp:' || true)
done

# doc/architecture.md: one row per module, "| `module/` | dep, dep |" ("-" for none).
for module in "${!deps[@]}"; do
  want="$(tr ' ' '\n' <<<"${deps[$module]}" | sed '/^$/d' | sort | paste -sd, | sed 's/,/, /g')"
  [[ -z "$want" ]] && want="-"
  row="$(grep -E "^\| \`$module/\` \|" "$src/doc/architecture.md" || true)"
  got="$(awk -F'|' '{gsub(/^ +| +$/, "", $3); print $3}' <<<"$row")"
  if [[ -z "$row" ]]; then
    echo "doc/architecture.md: no row for module $module/ (builds on: $want)" >&2
    failures=$((failures + 1))
  elif [[ "$got" != "$want" ]]; then
    echo "doc/architecture.md: module $module/ builds on \"$want\" in CMake, the table says \"$got\"" >&2
    failures=$((failures + 1))
  fi
done

if ((failures)); then
  echo "check_layers: $failures problem(s)" >&2
  exit 1
fi
echo "check_layers: ${#deps[@]} modules, includes and doc/architecture.md agree with the declared graph"
