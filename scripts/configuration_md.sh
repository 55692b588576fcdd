#!/bin/bash
# Writes doc/configuration.md, the configuration reference, from the option
# structs themselves (each app's --print-default-config --markdown): every
# section and key with its default and meaning, written once in the code.
# The test ConfigurationReference.MatchesTheCode fails when it is stale.
#   scripts/configuration_md.sh [BIN_DIR]      (default: build/bin)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BIN="${1:-$ROOT/build/bin}"
{
  cat <<'HEAD'
# Configuration reference

Every key of every INI section (one per component), its default and its meaning, generated from the
code (`scripts/configuration_md.sh`; a test fails when this file is stale). The defaults are the
camera configuration's (`config_ini/camera.ini`, chosen on the development homes); `config_ini/paper.ini`
holds the paper's settings. `--set SECTION.KEY=VALUE` overrides any key; an unknown or misspelled key, or a value out of
range, is an error naming the file, section and key.

## `vslam`
HEAD
  "$BIN/vslam" --print-default-config --markdown
  printf '\n## `vslam-simul` (rendered simulator)\n'
  "$BIN/vslam-simul" --print-default-config --markdown
  printf '\n## `vslam-simul-measurements` (measurement-level simulator)\n'
  "$BIN/vslam-simul-measurements" --print-default-config --markdown
} > "$ROOT/doc/configuration.md"
echo "wrote $ROOT/doc/configuration.md"
