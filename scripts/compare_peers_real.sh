#!/usr/bin/env bash
# Ours and PCL's peers on real RGB-D frames of the IC-BIN dataset (juice cartons, coffee cups):
# the number of objects and instances each method finds per frame, and one overlay picture per
# frame and method (doc/benchmark.md#real-frames).
#   scripts/compare_peers_real.sh DATA_DIR OUT_DIR
# DATA_DIR holds icbin_juice/ and icbin_coffee/ with rgb/NNNN.png and depth/NNNN.png (depth in
# millimetres, fx 550, fy 540, cx 316, cy 244; the frames are not part of this repository).
# The peers run with the parameters of scripts/benchmark_methods.sh. MID_BUILD_DIR: build (build).
set -euo pipefail
shopt -s nullglob
if [ $# -ne 2 ]; then
  echo "usage: $0 DATA_DIR OUT_DIR" >&2
  exit 2
fi
DATA=$(realpath "$1")
OUT=$(realpath -m "$2")
cd "$(dirname "$0")/.."
# shellcheck source=scripts/benchmark_methods.sh
. scripts/benchmark_methods.sh
APP=${MID_BUILD_DIR:-build}/apps/pcl_multi_instance_discovery
[ -x "$APP" ] || { echo "$APP is missing: build the project first (./run.sh demo)" >&2; exit 1; }
mkdir -p "$OUT"
echo "| frame | method | objects | instances per object | grouping ms |"
echo "|---|---|---|---|---|"
for set in icbin_juice icbin_coffee; do
  [ -d "$DATA/$set/rgb" ] || { echo "$DATA/$set/rgb is missing" >&2; exit 1; }
  for rgb in "$DATA/$set"/rgb/*.png; do
    frame=$(basename "$rgb" .png)
    for method in triplets gcg hough; do
      picture="$OUT/${set}_${frame}_${method}.png"
      options=$(method_options "$method")
      # shellcheck disable=SC2086 # the options are several words
      if ! log=$("$APP" -rgb "$rgb" -depth "$DATA/$set/depth/$frame.png" -fx 550 -fy 540 \
                   -cx 316 -cy 244 -overlay "$picture" $options 2>&1); then
        echo "| $set/$frame | $method | failed: $(echo "$log" | tail -1) | | |"
        continue
      fi
      objects=$(echo "$log" | sed -n 's/^objects: *//p')
      instances=$(echo "$log" | sed -n 's/^ *object [0-9]*: \([0-9]*\) instances.*/\1/p' |
                  paste -sd+ -)
      grouping=$(echo "$log" |
                 sed -n 's/.*triplets \([0-9.]*\), clustering \([0-9.]*\),.*/\1 \2/p' |
                 awk '{printf "%.1f", $1 + $2}')
      echo "| $set/$frame | $method | $objects | ${instances:-none} | $grouping |"
    done
  done
done
