#!/usr/bin/env bash
# Takes the README/docs screenshots on a real X server (Xvfb, 1920x1080) through the end-to-end driver
# millexpert-e2e (tests/e2e, docs/testing.md): each shot opens a bundled project in the real main window
# and waits for what the picture shows (lobes, the point's simulation, a Pareto choice, a supervised run,
# a tap-test fit). The driver is built first when it is missing or stale. MX_PRESET picks the build
# (default release); arguments name single shots, e.g. `bash packaging/screenshots.sh chatter.png`.
set -euo pipefail
cd "$(dirname "$0")/.."
preset=${MX_PRESET:-release}
command -v xvfb-run >/dev/null || { echo "screenshots: xvfb-run is missing (packaging/bootstrap.sh)" >&2; exit 1; }
[ -f "build/$preset/CMakeCache.txt" ] || cmake --preset "$preset" -G Ninja
cmake --build --preset "$preset" --target millexpert-e2e
QT_QPA_PLATFORM=xcb xvfb-run -a -s "-screen 0 1920x1080x24" \
  "build/$preset/tests/millexpert-e2e" screenshots docs/screenshots "$@"
echo "screenshots written to docs/screenshots/"
