#!/usr/bin/env bash
# Takes the README/docs screenshots under Xvfb (a real X server, 1920x1080), from a Release build.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=build/release/app/gui/millexpert
[ -x "$bin" ] || { cmake --preset release -G Ninja && cmake --build --preset release --target millexpert; }
mkdir -p docs/screenshots
xvfb-run -a -s "-screen 0 1920x1080x24" "$bin" projects/rubio2006-tool-selection.mxproj \
  --screenshot docs/screenshots/main-window.png
xvfb-run -a -s "-screen 0 1920x1080x24" "$bin" projects/benchmark-insperger-1dof.mxproj \
  --screenshot docs/screenshots/insperger-benchmark.png
echo "screenshots written to docs/screenshots/"
