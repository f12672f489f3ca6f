#!/usr/bin/env bash
# Ours and PCL's correspondence grouping (GeometricConsistencyGrouping, Hough3DGrouping) on the
# same frames, keypoints and self-matches, with the same model building and scoring
# (doc/benchmark.md#peers): the benchmark of scripts/benchmark.sh with three methods, and the
# side-by-side table. Takes the same environment settings as scripts/benchmark.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
MID_BENCHMARK_METHODS=${MID_BENCHMARK_METHODS:-triplets gcg hough} exec scripts/benchmark.sh "$@"
