#!/usr/bin/env bash
# One command for a fresh Debian 12 machine: installs what is missing, builds, and then
#   ./run.sh demo   runs pcl_multi_instance_discovery on the sample scene shipped in data/
#   ./run.sh test   runs every quality gate CI runs (doc/quality_gates.md): format check, the
#                   test suite built with warnings as errors and run under AddressSanitizer +
#                   UndefinedBehaviorSanitizer, clang-tidy on what changed since its last full
#                   run, and a short fuzz run
#   ./run.sh tidy   runs clang-tidy over every file (then move scripts/clang_tidy_baseline)
set -euo pipefail
cd "$(dirname "$0")"

PACKAGES=(cmake g++ make pkg-config libpcl-dev libopencv-dev libvtk9-dev libeigen3-dev
          libflann-dev libboost-dev libboost-graph-dev libgtest-dev libbenchmark-dev
          nlohmann-json3-dev doxygen
          xvfb xauth clang-14 libclang-rt-14-dev clang-tidy-14 clang-format-14)
BUILD_DIR=${MID_BUILD_DIR:-build}
ASAN_BUILD_DIR=${MID_ASAN_BUILD_DIR:-build-asan}
FUZZ_BUILD_DIR=${MID_FUZZ_BUILD_DIR:-build-fuzz}
JOBS=${MID_JOBS:-2}
FUZZ_SECONDS=${MID_FUZZ_SECONDS:-20}
# The newest commit at which clang-tidy found nothing in any file (the last line of the file).
TIDY_BASELINE=$(grep -v '^#' scripts/clang_tidy_baseline | tail -n 1)

install_missing_packages() {
  local missing=()
  for package in "${PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" ||
      missing+=("$package")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  echo "Installing: ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

build() {
  cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release "$@"
  cmake --build "$BUILD_DIR" -j "$JOBS"
}

step() {
  echo
  echo "=== $* ==="
}

# The whole suite with ASan + UBSan on our own targets (PCL, OpenCV, VTK stay as Debian ships
# them), built with warnings as errors: the one GCC build of the gates, because two full builds
# and two runs of the suite do not fit CI's 90 minutes on 2 cores (doc/quality_gates.md, "Cost").
# The Google Benchmark programs are compiled (warnings, clang-tidy) but never run by ctest.
sanitized_suite() {
  # -O1 -g1: line tables are all a sanitizer report needs, and both keep the build short.
  # The compile commands are clang-tidy's; the build's dependency files tell it what changed.
  cmake -S . -B "$ASAN_BUILD_DIR" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DMID_SANITIZE=ON \
        -DMID_WARNINGS_AS_ERRORS=ON -DCMAKE_EXPORT_COMPILE_COMMANDS=ON
  cmake --build "$ASAN_BUILD_DIR" -j "$JOBS"
  # Any report fails the test: halt at the first one, abort (a signal, which the app tests
  # count as a crash), and print where. Leaks are reported too (LeakSanitizer).
  ASAN_OPTIONS=halt_on_error=1:abort_on_error=1:detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1 \
  UBSAN_OPTIONS=halt_on_error=1:abort_on_error=1:print_stacktrace=1 \
    ctest --test-dir "$ASAN_BUILD_DIR" --output-on-failure -j "$JOBS"
}

# libFuzzer on the input path, FUZZ_SECONDS per target, starting from the checked-in seeds;
# new inputs go to the build folder, a crashing input to $FUZZ_BUILD_DIR/artifacts/ (then make
# it a regression test in test/fuzz/regressions/, see doc/quality_gates.md).
fuzz() {
  cmake -S . -B "$FUZZ_BUILD_DIR" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14 \
        -DMID_BUILD_FUZZERS=ON -DMID_WARNINGS_AS_ERRORS=ON -DMID_BUILD_BENCHMARKS=OFF \
        -DCMAKE_EXPORT_COMPILE_COMMANDS=ON
  cmake --build "$FUZZ_BUILD_DIR" -j "$JOBS" --target fuzz_pcd fuzz_rgbd make_fuzz_corpus
  # The fuzz programs are only in this build's compile commands, so clang-tidy checks them here.
  MID_JOBS="$JOBS" scripts/run_clang_tidy.sh "$FUZZ_BUILD_DIR" test/fuzz/fuzz_pcd.cpp \
    test/fuzz/fuzz_rgbd.cpp test/fuzz/make_fuzz_corpus.cpp
  mkdir -p "$FUZZ_BUILD_DIR/artifacts"
  for target in pcd rgbd; do
    mkdir -p "$FUZZ_BUILD_DIR/corpus/$target"
    ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
      "$FUZZ_BUILD_DIR/test/fuzz/fuzz_$target" "$FUZZ_BUILD_DIR/corpus/$target" \
      "test/fuzz/corpus/$target" -max_total_time="$FUZZ_SECONDS" -timeout=10 \
      -rss_limit_mb=2048 -print_final_stats=1 \
      -artifact_prefix="$FUZZ_BUILD_DIR/artifacts/${target}-"
  done
}

case "${1:-}" in
  demo)
    install_missing_packages
    build
    "$BUILD_DIR/apps/pcl_multi_instance_discovery" data/sample_scene/scene.pcd
    ;;
  test)
    install_missing_packages
    step "format (clang-format 14)"
    scripts/check_format.sh
    step "build with warnings as errors, test suite under AddressSanitizer + UndefinedBehaviorSanitizer"
    sanitized_suite
    step "clang-tidy 14 on the files whose result can differ from its last full run ($TIDY_BASELINE)"
    MID_JOBS="$JOBS" scripts/run_clang_tidy.sh "$ASAN_BUILD_DIR" --changed-since "$TIDY_BASELINE"
    step "fuzzing the input path (${FUZZ_SECONDS} s per target)"
    fuzz
    step "all quality gates passed"
    ;;
  tidy)
    install_missing_packages
    # clang-tidy needs the compile commands only, not a build.
    cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release -DCMAKE_EXPORT_COMPILE_COMMANDS=ON
    MID_JOBS="$JOBS" scripts/run_clang_tidy.sh "$BUILD_DIR"
    echo "clang-tidy found nothing: put $(git rev-parse HEAD) in scripts/clang_tidy_baseline" \
         "if the work tree is clean (git status)"
    ;;
  *)
    echo "usage: $0 demo|test|tidy" >&2
    exit 2
    ;;
esac
