#!/usr/bin/env bash
# Installs what is missing, builds (Release) and opens the GUI on the bundled default project
# (or on the project given as the first argument). Idempotent.
set -euo pipefail
cd "$(dirname "$0")/.."
bash packaging/bootstrap.sh
cmake --preset release -G Ninja
cmake --build --preset release --parallel "$(nproc)" --target millexpert millexpert-cli
exec build/release/app/gui/millexpert "${1:-projects/rubio2006-tool-selection.mxproj}"
