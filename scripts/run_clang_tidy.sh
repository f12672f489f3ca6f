#!/usr/bin/env bash
# Runs clang-tidy (checks in .clang-tidy) over our sources; fails (exit 1) on any finding.
#   scripts/run_clang_tidy.sh BUILD_DIR [--changed-since REV] [FILE_OR_FOLDER...]
# BUILD_DIR must hold compile_commands.json (configure with -DCMAKE_EXPORT_COMPILE_COMMANDS=ON;
# ./run.sh does). Without paths it checks the .cpp files in scripts/checked_paths.txt; headers
# are checked where they are included (HeaderFilterRegex in .clang-tidy). MID_JOBS sets the
# number of parallel clang-tidy processes (default 2).
# --changed-since REV keeps only the files whose result can differ from the run at REV: a .cpp
# file that changed since REV (committed or not), or one whose compiler dependency file in
# BUILD_DIR (*.o.d, written by the build) names a changed header. A file the build has not
# compiled yet is checked. When a CMake file changed, REV is configured with BUILD_DIR's options
# and a .cpp file whose compile command differs is checked too. Everything is checked when REV
# is not in this clone's history (or does not configure), or when .clang-tidy or
# scripts/checked_paths.txt changed (other checks or files).
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
since=""
if [ "${1:-}" = "--changed-since" ]; then
  [ $# -ge 2 ] || { echo "run_clang_tidy.sh: --changed-since needs a revision" >&2; exit 2; }
  since=$2
  shift 2
fi
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

# Prints the first prerequisite of each dependency file given: the source it was compiled from.
depfile_sources_awk='FNR == 1 { after_colon = 0 }
  { for (i = 1; i <= NF; i++) {
      if ($i == "\\") continue
      if (after_colon) { print $i; nextfile }
      if ($i ~ /:$/) after_colon = 1 } }'

# Prints "file<TAB>command" for each entry of a compile_commands.json, with the source and
# build folders of its configuration ($2, $3) written as those of this run's ($PWD, $build_dir).
compile_commands_of() {
  awk -v src="$2" -v bld="$3" -v src_now="$PWD" -v bld_now="$(cd "$build_dir" && pwd)" '
    function now(text) { gsub(bld, bld_now, text); gsub(src, src_now, text); return text }
    /^ *"command": / { command = now($0); sub(/^ *"command": /, "", command) }
    /^ *"file": / { file = now($0); sub(/^ *"file": "/, "", file); sub(/",?$/, "", file)
                    print file "\t" command }' "$1" | sort
}

# Prints the sources whose compile command differs from the one they had at $since (or that
# had none): $since's tree is configured with this build's options and the commands compared.
# Fails when that configuration fails.
commands_changed_since() {
  local tree config status=0
  tree=$(mktemp -d)
  config=$(mktemp -d)
  local options=()
  mapfile -t options < <(grep -E '^(CMAKE_BUILD_TYPE|CMAKE_(C|CXX)_(COMPILER|FLAGS[A-Z_]*)|MID_[A-Z_]+):' \
                           "$build_dir/CMakeCache.txt" | sed 's/^/-D/')
  if git archive "$since" | tar -x -C "$tree" &&
     cmake -S "$tree" -B "$config" "${options[@]}" -DCMAKE_EXPORT_COMPILE_COMMANDS=ON \
       >/dev/null 2>&1; then
    # Regular-expression characters in the folder names stand for themselves closely enough:
    # mktemp's names and a checkout path hold none but '.', which then matches itself too.
    compile_commands_of "$build_dir/compile_commands.json" "$PWD" "$(cd "$build_dir" && pwd)" \
      >"$tree.now"
    compile_commands_of "$config/compile_commands.json" "$tree" "$config" >"$tree.then"
    comm -23 "$tree.now" "$tree.then" | cut -f1 | sort -u
  else
    status=1
  fi
  rm -rf "$tree" "$config" "$tree.now" "$tree.then"
  return $status
}

# Prints the units (arguments) whose clang-tidy result can differ from the run at $since.
changed_units() {
  if ! git rev-parse -q --verify "$since^{commit}" >/dev/null ||
     ! git merge-base --is-ancestor "$since" HEAD; then
    echo "run_clang_tidy.sh: $since is not in this clone's history, so every file is checked" >&2
    printf '%s\n' "$@"
    return
  fi
  local changed
  mapfile -t changed < <({ git diff --name-only "$since" --; git ls-files --others --exclude-standard; } | sort -u)
  local file cmake_changed=""
  for file in "${changed[@]}"; do
    case $file in
      .clang-tidy | scripts/checked_paths.txt)
        echo "run_clang_tidy.sh: $file changed since $since, so every file is checked" >&2
        printf '%s\n' "$@"
        return
        ;;
      CMakeLists.txt | */CMakeLists.txt | cmake/*) cmake_changed=$file ;;
    esac
  done
  local recompiled=""
  if [ -n "$cmake_changed" ]; then
    if ! recompiled=$(commands_changed_since); then
      echo "run_clang_tidy.sh: $cmake_changed changed since $since and $since does not" \
           "configure here, so every file is checked" >&2
      printf '%s\n' "$@"
      return
    fi
  fi
  [ ${#changed[@]} -gt 0 ] || return 0
  local changed_paths depfiles
  changed_paths=$(mktemp)
  depfiles=$(mktemp)
  for file in "${changed[@]}"; do echo "$PWD/$file"; done >"$changed_paths"
  find "$build_dir" -name '*.o.d' -print >"$depfiles"
  local compiled hit
  compiled=$(xargs -r awk "$depfile_sources_awk" <"$depfiles" | sort -u)
  hit=$(xargs -r grep -lF -f "$changed_paths" <"$depfiles" |
          xargs -r awk "$depfile_sources_awk" | sort -u || true)
  rm -f "$changed_paths" "$depfiles"
  local unit
  for unit in "$@"; do
    if ! grep -qxF "$PWD/$unit" <<<"$compiled" || grep -qxF "$PWD/$unit" <<<"$hit" ||
       grep -qxF "$PWD/$unit" <<<"$recompiled"; then
      echo "$unit"
    fi
  done
}

if [ -n "$since" ]; then
  total=${#units[@]}
  mapfile -t units < <(changed_units "${units[@]}")
  if [ ${#units[@]} -eq 0 ]; then
    echo "run_clang_tidy.sh: none of the $total files can give another result than at $since"
    exit 0
  fi
  echo "run_clang_tidy.sh: ${#units[@]} of $total files can give another result than at $since"
fi

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
