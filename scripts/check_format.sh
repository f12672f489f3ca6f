#!/usr/bin/env bash
# Fails (exit 1) if a C++ file is not formatted as .clang-format says, and shows the diff.
#   scripts/check_format.sh [--fix] [FILE_OR_FOLDER...]
# Without paths it checks those in scripts/checked_paths.txt; --fix rewrites the files instead.
set -euo pipefail
cd "$(dirname "$0")/.."

CLANG_FORMAT=${CLANG_FORMAT:-clang-format-14}
fix=0
if [ "${1:-}" = "--fix" ]; then
  fix=1
  shift
fi
command -v "$CLANG_FORMAT" >/dev/null || { echo "check_format.sh: $CLANG_FORMAT not found" >&2; exit 2; }

mapfile -t files < <(scripts/list_sources.sh "$@")
if [ "$fix" -eq 1 ]; then
  "$CLANG_FORMAT" -i --style=file "${files[@]}"
  echo "check_format.sh: formatted ${#files[@]} files"
  exit 0
fi

unformatted=0
for file in "${files[@]}"; do
  if ! "$CLANG_FORMAT" --style=file "$file" | diff -u --label "$file" --label "$file (formatted)" "$file" -; then
    unformatted=$((unformatted + 1))
  fi
done
if [ "$unformatted" -ne 0 ]; then
  echo "check_format.sh: $unformatted of ${#files[@]} files are not formatted;" \
       "run scripts/check_format.sh --fix ${*:-}" >&2
  exit 1
fi
echo "check_format.sh: ${#files[@]} files formatted"
