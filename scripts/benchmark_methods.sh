# The grouping methods of the benchmark and their options, sourced by scripts/benchmark.sh and
# scripts/compare_peers_real.sh. The peers' parameters were tuned on development frames (seed 2,
# five per scenario, never the scored seed) by a grid search on instance F1 (doc/benchmark.md).
#   method_options METHOD   prints the pcl_multi_instance_discovery options of METHOD
method_options() {
  case $1 in
    triplets) echo "" ;;
    gcg) echo "-grouping gcg -gc_size 0.005 -gc_threshold 8" ;;
    hough) echo "-grouping hough -hough_bin 0.02 -hough_threshold 3 -lrf_radius 0.08" ;;
    *) echo "unknown method '$1' (triplets, gcg or hough)" >&2; return 1 ;;
  esac
}
