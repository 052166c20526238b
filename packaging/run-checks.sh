#!/usr/bin/env bash
# Deeper checks that do not fit in the test command's 30 minutes; run before an issue is closed.
#   unity   each test program's files compiled as ONE unit (syntax only, the ci build's flags;
#           packaging/check_unity_folders.py): two test files of a folder that define the same
#           file-scope name would break the test command's unity batches once they share one;
#   asan    the whole test suite under AddressSanitizer + UndefinedBehaviorSanitizer + LeakSanitizer
#           (preset asan, suppressions in packaging/sanitizers/lsan.supp), with the same fresh TMPDIR
#           and HOME as the test command;
#   tsan    the threaded tests (CTest label "threads", tests/CMakeLists.txt) under ThreadSanitizer
#           (preset tsan, suppressions in packaging/sanitizers/tsan.supp); only their test executables
#           are built;
#   monkey  the GUI monkey (docs/testing.md) on the asan build's real window under Xvfb for
#           MX_MONKEY_SECONDS (600 s by default) from MX_MONKEY_SEED (the time by default; printed, so
#           that a failure replays);
#   tidy    clang-tidy (.clang-tidy) over our sources in the asan build's compile database, the
#           units of a folder checked eight to a batch (a batch that passed before with the same
#           preprocessed text skipped; packaging/clang_tidy_cached.py);
#   fuzz    every libFuzzer target (preset fuzz, clang-14, ASan + UBSan; tests/fuzz/README.md), one
#           after the other, each for MX_FUZZ_SECONDS (120 s by default) from its seed corpus in a
#           scratch corpus folder, with -timeout=5 -rss_limit_mb=1024: a crash, leak, timeout or
#           out-of-memory fails it, and the input is kept in build/fuzz/findings/. MX_FUZZ_TARGETS
#           ("learning_location batch_manifest", ...) runs only those, to recheck the parsers an edit
#           touched.
# MX_CHECKS picks and orders the checks ("unity asan tsan monkey tidy fuzz" by default, all of them), so
# that a failed check can be rerun alone. Exits non-zero at the first check that fails.
set -euo pipefail
cd "$(dirname "$0")/.."

run_tmp=$(mktemp -d)
run_home=$(mktemp -d)
chmod 0755 "$run_tmp" "$run_home"
trap 'rm -rf "$run_tmp" "$run_home"' EXIT

# Runs "$@" with the fresh TMPDIR and HOME of the test command.
in_fresh_home() {
  env -u XDG_CONFIG_HOME -u XDG_DATA_HOME -u XDG_STATE_HOME -u XDG_CACHE_HOME -u XDG_RUNTIME_DIR \
    TMPDIR="$run_tmp" HOME="$run_home" "$@"
}

check_unity() {
  cmake --preset ci -G Ninja
  cmake --build --preset ci --parallel "$(nproc)"
  python3 packaging/check_unity_folders.py build/ci
}

check_asan() {
  MX_PRESET=asan bash packaging/run-tests.sh
}

check_tsan() {
  cmake --preset tsan -G Ninja
  # The test executables of the "threads" tests: folder.unit runs in tests_<folder>.
  local targets
  targets=$(ctest --preset tsan -N | sed -n 's/^ *Test *#[0-9]*: \([a-z_]*\)\..*$/tests_\1/p' | sort -u)
  [ -n "$targets" ] || { echo "run-checks: no test has the label threads"; return 1; }
  # The programs those tests start (MX_CLI_PATH and the report writer beside it) are built too.
  # shellcheck disable=SC2086 # one word per target
  cmake --build --preset tsan --parallel "$(nproc)" --target $targets millexpert-cli millexpert-report
  in_fresh_home ctest --preset tsan --parallel "$(nproc)"
}

check_monkey() {
  local seed="${MX_MONKEY_SEED:-$(date +%s)}"
  local seconds="${MX_MONKEY_SECONDS:-600}"
  cmake --preset asan -G Ninja
  cmake --build --preset asan --parallel "$(nproc)" --target millexpert-e2e
  echo "run-checks: GUI monkey, seed $seed, $seconds s (MX_MONKEY_SEED=$seed replays it)"
  in_fresh_home env ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
    LSAN_OPTIONS="suppressions=$PWD/packaging/sanitizers/lsan.supp:print_suppressions=0" \
    xvfb-run -a -s "-screen 0 1920x1080x24" build/asan/tests/millexpert-e2e monkey \
    --seed "$seed" --seconds "$seconds"
}

check_tidy() {
  # The asan build's compile database and the moc files its units include, for every source of
  # this tree (up to date after check_asan; built here when tidy runs alone).
  cmake --preset asan -G Ninja
  cmake --build --preset asan --parallel "$(nproc)"
  # Our translation units: engine, app, widgets, tests (not the tests/data fixtures), bench when
  # built; the generated moc and resource files lie in the build folder and are left out.
  # Units of one folder and command are checked eight to a batch, which shares the cost of the Qt and
  # standard headers; a batch unchanged since it last passed (same preprocessed text, command and
  # .clang-tidy) is skipped: packaging/clang_tidy_cached.py, stamps in build/asan/clang-tidy-passed/.
  python3 packaging/clang_tidy_cached.py build/asan "^$PWD/(engine|app|widgets|bench|tests/(?!data/))" --jobs "$(nproc)"
}

check_fuzz() {
  local seconds="${MX_FUZZ_SECONDS:-120}"
  cmake --preset fuzz -G Ninja
  cmake --build --preset fuzz --parallel "$(nproc)" --target fuzz_all
  local fuzz_dir=build/fuzz/tests/fuzz
  mkdir -p build/fuzz/findings
  # fuzz_targets.txt: one target name a line, written by tests/fuzz/CMakeLists.txt.
  local name ran=0
  for name in ${MX_FUZZ_TARGETS:-}; do
    grep -qx "$name" "$fuzz_dir/fuzz_targets.txt" ||
      { echo "run-checks: unknown fuzz target '$name' in MX_FUZZ_TARGETS; allowed: $(tr '\n' ' ' <"$fuzz_dir/fuzz_targets.txt")"; return 2; }
  done
  while read -r name; do
    [ -z "${MX_FUZZ_TARGETS:-}" ] || [[ " $MX_FUZZ_TARGETS " == *" $name "* ]] || continue
    ran=$((ran + 1))
    local scratch="$run_tmp/corpus-$name"
    mkdir -p "$scratch"
    local dict=()
    [ -f "tests/fuzz/dict/$name.dict" ] && dict=(-dict="tests/fuzz/dict/$name.dict")
    if ! "$fuzz_dir/fuzz_$name" "${dict[@]}" -max_total_time="$seconds" -timeout=5 -rss_limit_mb=1024 \
      -print_final_stats=1 -artifact_prefix="build/fuzz/findings/$name-" "$scratch" "tests/fuzz/corpus/$name" </dev/null; then
      echo "run-checks: fuzz_$name found a bug; replay it with $fuzz_dir/fuzz_$name build/fuzz/findings/$name-*"
      return 1
    fi
  done <"$fuzz_dir/fuzz_targets.txt"
  echo "run-checks: $ran fuzz targets ran, ${seconds} s each"
}

for check in ${MX_CHECKS:-unity asan tsan monkey tidy fuzz}; do
  case "$check" in
    unity | asan | tsan | monkey | tidy | fuzz) ;;
    *) echo "run-checks: unknown check '$check' in MX_CHECKS; allowed: unity asan tsan monkey tidy fuzz"; exit 2 ;;
  esac
  echo "run-checks: $check"
  started=$SECONDS
  # A subshell outside any || list, so that set -e still stops the check at its first failing step.
  set +e
  (
    set -e
    "check_$check"
  )
  status=$?
  set -e
  [ "$status" -eq 0 ] || { echo "run-checks: $check FAILED after $((SECONDS - started)) s"; exit 1; }
  echo "run-checks: $check passed in $((SECONDS - started)) s"
done
echo "run-checks: all checks passed (${MX_CHECKS:-unity asan tsan monkey tidy fuzz})"
