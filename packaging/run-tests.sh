#!/usr/bin/env bash
# The README's test command: installs what is missing, builds (Release, -Werror) and runs every test.
# Idempotent. The tests run with a fresh TMPDIR and HOME (mktemp -d, mode 0755 so that a service user
# such as postgres can enter), removed afterwards: nothing an earlier run left behind can hide a
# missing step. Extra arguments go to ctest (for example -R '^engine\.').
# MX_PRESET=asan runs the suite under AddressSanitizer + UndefinedBehaviorSanitizer instead.
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${MX_PRESET:-ci}"
started=$SECONDS
bash packaging/bootstrap.sh
cmake --preset "$preset" -G Ninja
cmake --build --preset "$preset" --parallel "$(nproc)"
echo "run-tests: install and build took $((SECONDS - started)) s"

run_tmp=$(mktemp -d)
run_home=$(mktemp -d)
chmod 0755 "$run_tmp" "$run_home"
trap 'rm -rf "$run_tmp" "$run_home"' EXIT
env -u XDG_CONFIG_HOME -u XDG_DATA_HOME -u XDG_STATE_HOME -u XDG_CACHE_HOME -u XDG_RUNTIME_DIR \
  TMPDIR="$run_tmp" HOME="$run_home" ctest --preset "$preset" --parallel "$(nproc)" "$@"
