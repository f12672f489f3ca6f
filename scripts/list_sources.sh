#!/usr/bin/env bash
# Prints the C++ files (.h, .hpp, .cpp) under the given files and folders, relative to the
# repository root; without arguments, under those listed in scripts/checked_paths.txt.
set -euo pipefail
cd "$(dirname "$0")/.."

paths=("$@")
if [ ${#paths[@]} -eq 0 ]; then
  mapfile -t paths < <(grep -v -e '^#' -e '^[[:space:]]*$' scripts/checked_paths.txt)
fi
for path in "${paths[@]}"; do
  path=${path%/}
  if [ -d "$path" ]; then
    find "$path" -type f \( -name '*.h' -o -name '*.hpp' -o -name '*.cpp' \) -print
  elif [ -f "$path" ]; then
    echo "$path"
  else
    echo "list_sources.sh: no such file or folder: $path" >&2
    exit 2
  fi
done | sort -u
