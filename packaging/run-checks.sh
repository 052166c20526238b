#!/usr/bin/env bash
# Deeper checks that do not fit in the test command's 30 minutes; run before an issue is closed.
#   1. the whole test suite under AddressSanitizer + UndefinedBehaviorSanitizer + LeakSanitizer (preset
#      asan, suppressions in packaging/sanitizers/lsan.supp), with the same fresh TMPDIR and HOME as the
#      test command;
#   2. the threaded tests (CTest label "threads", tests/CMakeLists.txt) under ThreadSanitizer (preset
#      tsan, suppressions in packaging/sanitizers/tsan.supp); only their test executables are built;
#   3. the GUI monkey (docs/testing.md) on the asan build's real window under Xvfb for MX_MONKEY_SECONDS
#      (600 s by default) from MX_MONKEY_SEED (the time by default; printed, so that a failure replays);
#   4. clang-tidy (.clang-tidy) over our sources in the asan build's compile database;
#   5. every libFuzzer target (preset fuzz, clang-14, ASan + UBSan; tests/fuzz/README.md), one after the
#      other, each for MX_FUZZ_SECONDS (120 s by default) from its seed corpus in a scratch corpus
#      folder, with -timeout=5 -rss_limit_mb=1024: a crash, leak, timeout or out-of-memory fails it,
#      and the input is kept in build/fuzz/findings/.
# Exits non-zero at the first check that fails.
set -euo pipefail
cd "$(dirname "$0")/.."
echo "run-checks: ASan + UBSan + LSan test suite"
MX_PRESET=asan bash packaging/run-tests.sh

echo "run-checks: TSan, the threaded tests"
started=$SECONDS
cmake --preset tsan -G Ninja
# The test executables of the "threads" tests: folder.unit runs in tests_<folder>.
targets=$(ctest --preset tsan -N | sed -n 's/^ *Test *#[0-9]*: \([a-z_]*\)\..*$/tests_\1/p' | sort -u)
[ -n "$targets" ] || { echo "run-checks: no test has the label threads"; exit 1; }
# shellcheck disable=SC2086 # one word per target
cmake --build --preset tsan --parallel "$(nproc)" --target $targets
run_tmp=$(mktemp -d)
run_home=$(mktemp -d)
chmod 0755 "$run_tmp" "$run_home"
trap 'rm -rf "$run_tmp" "$run_home"' EXIT
env -u XDG_CONFIG_HOME -u XDG_DATA_HOME -u XDG_STATE_HOME -u XDG_CACHE_HOME -u XDG_RUNTIME_DIR \
  TMPDIR="$run_tmp" HOME="$run_home" ctest --preset tsan --parallel "$(nproc)"
echo "run-checks: TSan took $((SECONDS - started)) s"

started=$SECONDS
monkey_seed="${MX_MONKEY_SEED:-$(date +%s)}"
monkey_seconds="${MX_MONKEY_SECONDS:-600}"
echo "run-checks: GUI monkey under ASan, seed $monkey_seed, $monkey_seconds s (MX_MONKEY_SEED=$monkey_seed replays it)"
env -u XDG_CONFIG_HOME -u XDG_DATA_HOME -u XDG_STATE_HOME -u XDG_CACHE_HOME -u XDG_RUNTIME_DIR \
  TMPDIR="$run_tmp" HOME="$run_home" ASAN_OPTIONS=detect_leaks=1 \
  LSAN_OPTIONS="suppressions=$PWD/packaging/sanitizers/lsan.supp:print_suppressions=0" \
  xvfb-run -a -s "-screen 0 1920x1080x24" build/asan/tests/millexpert-e2e monkey \
  --seed "$monkey_seed" --seconds "$monkey_seconds"
echo "run-checks: the monkey took $((SECONDS - started)) s"

echo "run-checks: clang-tidy"
started=$SECONDS
# Our translation units: engine, app, widgets, tests (not the tests/data fixtures), bench when built;
# the generated moc and resource files lie in the build folder and are left out.
run-clang-tidy-14 -p build/asan -j "$(nproc)" -quiet "^$PWD/(engine|app|widgets|bench|tests/(?!data/))"
echo "run-checks: clang-tidy took $((SECONDS - started)) s"
echo "run-checks: libFuzzer"
started=$SECONDS
fuzz_seconds="${MX_FUZZ_SECONDS:-120}"
cmake --preset fuzz -G Ninja
cmake --build --preset fuzz --parallel "$(nproc)" --target fuzz_all
fuzz_dir=build/fuzz/tests/fuzz
mkdir -p build/fuzz/findings
# fuzz_targets.txt: one target name a line, written by tests/fuzz/CMakeLists.txt.
while read -r name; do
  scratch="$run_tmp/corpus-$name"
  mkdir -p "$scratch"
  dict=()
  [ -f "tests/fuzz/dict/$name.dict" ] && dict=(-dict="tests/fuzz/dict/$name.dict")
  if ! "$fuzz_dir/fuzz_$name" "${dict[@]}" -max_total_time="$fuzz_seconds" -timeout=5 -rss_limit_mb=1024 \
    -print_final_stats=1 -artifact_prefix="build/fuzz/findings/$name-" "$scratch" "tests/fuzz/corpus/$name" </dev/null; then
    echo "run-checks: fuzz_$name found a bug; replay it with $fuzz_dir/fuzz_$name build/fuzz/findings/$name-*"
    exit 1
  fi
done <"$fuzz_dir/fuzz_targets.txt"
echo "run-checks: libFuzzer took $((SECONDS - started)) s"
echo "run-checks: all checks passed"
