#!/bin/bash
# Writes the synthetic tap-test files of projects/tap-test-example.mxproj from the modes stated in
# projects/taps/T9-stated-modes.mxproj, with MillExpert's own UFF writer (millexpert-cli frf-export):
# accelerance, 0 to 4000 Hz in 1 Hz lines, 1 % complex noise (seeded, so the files are reproducible).
# Usage: packaging/make-tap-test-example.sh [MILLEXPERT_CLI] [OUTPUT_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
cli=${1:-build/ci/app/millexpert-cli}
out=${2:-projects/taps}
source=projects/taps/T9-stated-modes.mxproj
common=(--tool T9 --quantity accelerance --from 0 --to 4000 --step 1 --noise-pct 1)
"$cli" frf-export "$source" "${common[@]}" --axis x --format uff58 --seed 9 --output "$out/T9-x.uff" > /dev/null
"$cli" frf-export "$source" "${common[@]}" --axis y --format uff58b --seed 10 --output "$out/T9-y.uff" > /dev/null
