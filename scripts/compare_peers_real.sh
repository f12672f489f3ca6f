#!/usr/bin/env bash
# Ours and PCL's peers on the real RGB-D frames of ../shared/data/real (not part of this
# repository): per frame, what it shows, the number of objects and instances each method finds,
# and one overlay picture per frame and method (doc/benchmark.md#real-frames).
#   scripts/compare_peers_real.sh DATA_DIR OUT_DIR
# DATA_DIR holds the folders below, each described by its SOURCE.md (units and intrinsics are
# written here as that file gives them):
#   icbin_juice/, icbin_coffee/  rgb/NNNN.png + depth/NNNN.png, depth in mm, fx 550 fy 540 cx 316 cy 244
#   wrs_bins_zivid/wrs4/         color.png + depth_image_01mm_resolution.png (0.1 mm), 1944 x 1200
#   uoc_tabletop/                NNNNNN-color.png + NNNNNN-depth.png, depth in mm
#   pcl_bottle_pack/, pcl_milk_scene/, mosd_clutter/  organized PCD files, metres
# A folder that is missing is skipped with a note; a frame that fails is reported in the table.
# The peers run with the parameters of scripts/benchmark_methods.sh. MID_BUILD_DIR: build (build).
# MID_REAL_METHODS: the methods (default "triplets gcg hough"). MID_DISCOVERY_OPTIONS: more
# discovery options for every method (none; e.g. -size_surrounded 0.3), as for benchmark.sh.
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
METHODS=${MID_REAL_METHODS:-triplets gcg hough}
mkdir -p "$OUT"

# run_frame NAME SHOWS INPUT...: one table row per method for the frame NAME (a/b), whose
# content is SHOWS, read with the discovery app's input options INPUT.
run_frame() {
  local name=$1 shows=$2 method picture options log objects instances grouping
  shift 2
  for method in $METHODS; do
    picture="$OUT/$(echo "$name" | tr / _)_${method}.png"
    options="$(method_options "$method") ${MID_DISCOVERY_OPTIONS:-}"
    # shellcheck disable=SC2086 # the options are several words
    if ! log=$("$APP" "$@" -overlay "$picture" $options 2>&1); then
      echo "| $name | $shows | $method | failed: $(echo "$log" | tail -1) | | |"
      continue
    fi
    objects=$(echo "$log" | sed -n 's/^objects: *//p')
    instances=$(echo "$log" | sed -n 's/^ *object [0-9]*: \([0-9]*\) instances.*/\1/p' |
                paste -sd+ -)
    grouping=$(echo "$log" |
               sed -n 's/.*triplets \([0-9.]*\), clustering \([0-9.]*\),.*/\1 \2/p' |
               awk '{printf "%.1f", $1 + $2}')
    echo "| $name | $shows | $method | $objects | ${instances:-none} | $grouping |"
  done
}

# present FOLDER: true if DATA holds FOLDER, otherwise a note on stderr.
present() {
  [ -d "$DATA/$1" ] && return 0
  echo "$DATA/$1 is missing: skipped" >&2
  return 1
}

echo "| frame | shows | method | objects | instances per object | grouping ms |"
echo "|---|---|---|---|---|---|"
declare -A ICBIN_SHOWS=([icbin_juice]="~7 juice cartons" [icbin_coffee]="~11-15 coffee cups")
for set in icbin_juice icbin_coffee; do
  present "$set" || continue
  for rgb in "$DATA/$set"/rgb/*.png; do
    frame=$(basename "$rgb" .png)
    run_frame "$set/$frame" "${ICBIN_SHOWS[$set]}" -rgb "$rgb" \
      -depth "$DATA/$set/depth/$frame.png" -fx 550 -fy 540 -cx 316 -cy 244
  done
done
if present wrs_bins_zivid/wrs4; then
  run_frame wrs_bins_zivid/wrs4 "bins of ~30 pins, 2 motors, ~15 pulleys" \
    -rgb "$DATA/wrs_bins_zivid/wrs4/color.png" \
    -depth "$DATA/wrs_bins_zivid/wrs4/depth_image_01mm_resolution.png" -depth_scale 0.0001 \
    -fx 1786.57788 -fy 1785.74548 -cx 984.213745 -cy 609.480774
fi
if present uoc_tabletop; then
  declare -A UOC_SHOWS=([000000]="10 different objects" [000006]="2 plain cups, 7 others")
  for rgb in "$DATA/uoc_tabletop"/*-color.png; do
    frame=$(basename "$rgb" -color.png)
    run_frame "uoc_tabletop/$frame" "${UOC_SHOWS[$frame]:-?}" -rgb "$rgb" \
      -depth "$DATA/uoc_tabletop/$frame-depth.png" \
      -fx 612.937 -fy 613.173 -cx 322.549 -cy 248.158
  done
fi
if present pcl_bottle_pack; then
  run_frame pcl_bottle_pack/region_growing_rgb_tutorial "a pack of 6 bottles" \
    "$DATA/pcl_bottle_pack/region_growing_rgb_tutorial.pcd"
fi
if present pcl_milk_scene; then
  run_frame pcl_milk_scene/milk_cartoon_all_small_clorox "4 different products" \
    "$DATA/pcl_milk_scene/milk_cartoon_all_small_clorox.pcd"
fi
if present mosd_clutter; then
  declare -A MOSD_SHOWS=([test45]="7 different objects" [test59]="16 different objects")
  for pcd in "$DATA/mosd_clutter"/*.pcd; do
    frame=$(basename "$pcd" .pcd)
    run_frame "mosd_clutter/$frame" "${MOSD_SHOWS[$frame]:-?}" "$pcd"
  done
fi
