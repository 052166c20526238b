#!/usr/bin/env bash
# Installs what is missing, builds (Release, -Werror) and runs every test. Idempotent.
# Set MX_PRESET=asan to run the suite under AddressSanitizer + UndefinedBehaviorSanitizer.
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${MX_PRESET:-ci}"
bash packaging/bootstrap.sh
cmake --preset "$preset" -G Ninja
cmake --build --preset "$preset" --parallel "$(nproc)"
ctest --preset "$preset" --parallel "$(nproc)"
