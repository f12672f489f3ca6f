#!/usr/bin/env bash
# The synthetic benchmark (doc/benchmark.md): writes a fixed dataset of the six scenarios with
# pcl_multi_instance_bench_synth, runs pcl_multi_instance_discovery -json on every frame, and
# prints the Table-2-style report of pcl_multi_instance_eval.
#   scripts/benchmark.sh
# Settings, from the environment (the defaults give the published benchmark):
#   MID_BUILD_DIR               build folder holding apps/ (build); built first if an app is
#                               missing (configured as Release if it has no CMakeCache.txt)
#   MID_BENCHMARK_OUT           where dataset/, results/ and report.md go, replaced
#                               (MID_BUILD_DIR/benchmark)
#   MID_BENCHMARK_FRAMES        frames per scenario (20)
#   MID_BENCHMARK_SCENARIOS     comma-separated scenarios (S-ez,S-d,M-ez,M-d,rows,none)
#   MID_BENCHMARK_SEED          seed of the dataset (1)
#   MID_BENCHMARK_SUPERSAMPLING colour rays per pixel along each axis (3)
#   MID_BENCHMARK_INSTANCES_PER_TYPE  copies of each repeated product in S-ez, S-d, M-ez and
#                               M-d (0: drawn, 2 to 9); 2 with MID_BENCHMARK_SCENARIOS=S-ez,
#                               S-d,M-ez,M-d gives the paper's pair subset (doc/benchmark.md)
#   MID_JOBS                    discovery runs in parallel, and build jobs (2)
#   MID_BENCHMARK_METHODS       space-separated groupings to run on the same frames (triplets):
#                               triplets (ours), gcg (pcl::GeometricConsistencyGrouping),
#                               hough (pcl::Hough3DGrouping); with more than one, the report
#                               also puts them side by side (scripts/compare_peers.sh)
#   MID_BENCHMARK_KEEP_DATASET  1: reuse OUT/dataset when it exists (0)
#   MID_DISCOVERY_OPTIONS       more pcl_multi_instance_discovery options for every method
#                               (none), e.g. -split
set -euo pipefail
cd "$(dirname "$0")/.."

BUILD_DIR=${MID_BUILD_DIR:-build}
OUT=${MID_BENCHMARK_OUT:-$BUILD_DIR/benchmark}
FRAMES=${MID_BENCHMARK_FRAMES:-20}
SCENARIOS=${MID_BENCHMARK_SCENARIOS:-S-ez,S-d,M-ez,M-d,rows,none}
SEED=${MID_BENCHMARK_SEED:-1}
SUPERSAMPLING=${MID_BENCHMARK_SUPERSAMPLING:-3}
INSTANCES=${MID_BENCHMARK_INSTANCES_PER_TYPE:-0}
JOBS=${MID_JOBS:-2}
METHODS=${MID_BENCHMARK_METHODS:-triplets}
KEEP_DATASET=${MID_BENCHMARK_KEEP_DATASET:-0}

# shellcheck source=scripts/benchmark_methods.sh
. scripts/benchmark_methods.sh
for method in $METHODS; do method_options "$method" >/dev/null; done
APPS=$BUILD_DIR/apps
TARGETS=(pcl_multi_instance_bench_synth pcl_multi_instance_discovery pcl_multi_instance_eval)

for target in "${TARGETS[@]}"; do
  if [ ! -x "$APPS/$target" ]; then
    echo "=== building the apps in $BUILD_DIR"
    [ -f "$BUILD_DIR/CMakeCache.txt" ] || cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release
    cmake --build "$BUILD_DIR" -j "$JOBS" --target "${TARGETS[@]}"
    break
  fi
done

start=$(date +%s)
rm -rf "$OUT/results" "$OUT/report.md"
mkdir -p "$OUT/results"

if [ "$KEEP_DATASET" = 1 ] && [ -d "$OUT/dataset" ]; then
  echo "=== dataset: reusing $OUT/dataset"
else
  rm -rf "$OUT/dataset"
  echo "=== dataset: $SCENARIOS, $FRAMES frames each, seed $SEED, copies per type $INSTANCES (0: drawn)"
  "$APPS/pcl_multi_instance_bench_synth" -texture_dir data/textures -out_dir "$OUT/dataset" \
    -frames "$FRAMES" -seed "$SEED" -scenarios "$SCENARIOS" -supersampling "$SUPERSAMPLING" \
    -instances_per_type "$INSTANCES"
fi
generated=$(date +%s)

# One frame: OUT/dataset/<scene>/pcd/<image>.pcd -> RESULTS/<scene>/<image>.json (+ .log).
run_discovery() {
  local pcd=$1 scene image
  scene=$(basename "$(dirname "$(dirname "$pcd")")")
  image=$(basename "$pcd" .pcd)
  mkdir -p "$RESULTS/$scene"
  # shellcheck disable=SC2086 # OPTIONS holds several options
  if ! "$APPS/pcl_multi_instance_discovery" "$pcd" -json "$RESULTS/$scene/$image.json" \
       $OPTIONS > "$RESULTS/$scene/$image.log" 2>&1; then
    echo "discovery failed on $pcd:" >&2
    cat "$RESULTS/$scene/$image.log" >&2
    return 1
  fi
}
export -f run_discovery
export APPS

# -L: the dataset folder may be a symbolic link to one written elsewhere.
count=$(find -L "$OUT/dataset" -path '*/pcd/*.pcd' | wc -l)
if [ "$count" -eq 0 ]; then
  echo "benchmark.sh: no frames (<scene>/pcd/<image>.pcd) in $OUT/dataset" >&2
  exit 1
fi
folders=()
for method in $METHODS; do
  OPTIONS=$(method_options "$method")
  OPTIONS="$OPTIONS${MID_DISCOVERY_OPTIONS:+${OPTIONS:+ }$MID_DISCOVERY_OPTIONS}"
  RESULTS=$OUT/results/$method
  [ "$(echo $METHODS)" = triplets ] && RESULTS=$OUT/results
  export OPTIONS RESULTS
  folders+=("$RESULTS")
  echo "=== discovery ($method${OPTIONS:+: $OPTIONS}) on $count frames ($JOBS at a time)"
  find -L "$OUT/dataset" -path '*/pcd/*.pcd' -print0 | sort -z |
    xargs -0 -r -n 1 -P "$JOBS" bash -c 'run_discovery "$1"' _
done
discovered=$(date +%s)

echo "=== evaluation"
names=$(echo $METHODS | tr ' ' ',')
"$APPS/pcl_multi_instance_eval" "$OUT/dataset" "${folders[@]}" -names "$names" \
  -report "$OUT/report.md"
end=$(date +%s)
echo "=== $count frames in $((end - start)) s (dataset $((generated - start)) s," \
     "discovery $((discovered - generated)) s, evaluation $((end - discovered)) s);" \
     "report in $OUT/report.md"
