#!/usr/bin/env bash
# Deeper checks that do not fit in the test command's 30 minutes; run before an issue is closed.
#   1. the whole test suite under AddressSanitizer + UndefinedBehaviorSanitizer (preset asan),
#      with the same fresh TMPDIR and HOME as the test command.
# Exits non-zero at the first check that fails.
set -euo pipefail
cd "$(dirname "$0")/.."
echo "run-checks: ASan + UBSan test suite"
MX_PRESET=asan bash packaging/run-tests.sh
echo "run-checks: all checks passed"
