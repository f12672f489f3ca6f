#!/usr/bin/env bash
# Runs clang-tidy (checks in .clang-tidy) over our sources; fails (exit 1) on any finding.
#   scripts/run_clang_tidy.sh BUILD_DIR [FILE_OR_FOLDER...]
# BUILD_DIR must hold compile_commands.json (configure with -DCMAKE_EXPORT_COMPILE_COMMANDS=ON;
# ./run.sh does). Without paths it checks the .cpp files in scripts/checked_paths.txt; headers
# are checked where they are included (HeaderFilterRegex in .clang-tidy). MID_JOBS sets the
# number of parallel clang-tidy processes (default 2).
set -euo pipefail
cd "$(dirname "$0")/.."

CLANG_TIDY=${CLANG_TIDY:-clang-tidy-14}
JOBS=${MID_JOBS:-2}
if [ $# -lt 1 ]; then
  echo "usage: $0 BUILD_DIR [FILE_OR_FOLDER...]" >&2
  exit 2
fi
build_dir=$1
shift
command -v "$CLANG_TIDY" >/dev/null || { echo "run_clang_tidy.sh: $CLANG_TIDY not found" >&2; exit 2; }
[ -f "$build_dir/compile_commands.json" ] ||
  { echo "run_clang_tidy.sh: no $build_dir/compile_commands.json" >&2; exit 2; }

# Translation units only, and only those the build compiles: test/consumer is its own CMake
# project with no compile command here (skipped with a note; it was checked once by hand), and
# the fuzz programs are checked in the fuzz build of ./run.sh test.
mapfile -t sources < <(scripts/list_sources.sh "$@" | grep '\.cpp$')
units=()
for source in "${sources[@]}"; do
  if grep -q "\"file\": \"$PWD/$source\"" "$build_dir/compile_commands.json"; then
    units+=("$source")
  else
    echo "run_clang_tidy.sh: $source is not in $build_dir/compile_commands.json, skipped"
  fi
done
[ ${#units[@]} -gt 0 ] || { echo "run_clang_tidy.sh: nothing to check" >&2; exit 2; }

log=$(mktemp)
trap 'rm -f "$log"' EXIT
status=0
printf '%s\n' "${units[@]}" |
  xargs -P "$JOBS" -I{} sh -c '"$0" -p "$1" --quiet "$2" >"$3.$$" 2>&1 || { cat "$3.$$"; rm -f "$3.$$"; exit 1; }; rm -f "$3.$$"' \
    "$CLANG_TIDY" "$build_dir" {} "$log" || status=1
if [ "$status" -ne 0 ]; then
  echo "run_clang_tidy.sh: findings above (fix them, or NOLINT one with a reason)" >&2
  exit 1
fi
echo "run_clang_tidy.sh: ${#units[@]} files, no findings"
