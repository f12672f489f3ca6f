// Cost of the transformation-space DBSCAN as the number of triplet matches grows (1k, 5k, 20k),
// with the peak memory of one call: the clusterer as shipped (exact centroid lower bound before
// the paper's distance) next to a plain all-pairs evaluation of the paper's distance.
//
//   build/test/benchmark/bench_clustering

#include "memory_counter.h"
#include "rigid_motion.h"

#include <mid/registration/rigid_transform.h>
#include <mid/segmentation/dbscan.h>
#include <mid/segmentation/transformation_space_clustering.h>
#include <mid/segmentation/triplet_distance.h>

#include <benchmark/benchmark.h>

#include <random>

namespace {

struct SyntheticTriplets
{
  mid::KeypointCloud::Ptr keypoints = pcl::make_shared<mid::KeypointCloud>();
  std::shared_ptr<mid::TripletMatches> triplets =
      std::make_shared<mid::TripletMatches>();
};

/** n triplet matches between 8 instances of a 60-keypoint object (1 mm noise), in random
  * directions between random pairs; 30 % are random triangles (outliers).
  */
SyntheticTriplets
makeSyntheticTriplets (int n, unsigned seed = 2)
{
  constexpr int kInstances = 8, kPoints = 60;
  std::mt19937 rng (seed);
  std::uniform_real_distribution<float> unit (-0.5f, 0.5f);
  std::normal_distribution<float> noise (0.0f, 0.001f);
  std::vector<Eigen::Vector3f> model;
  model.reserve (kPoints);
  for (int k = 0; k < kPoints; ++k)
    model.emplace_back (unit (rng) * 0.12f, unit (rng) * 0.12f, unit (rng) * 0.12f);
  SyntheticTriplets s;
  for (int i = 0; i < kInstances; ++i) {
    const int row = i / 4, column = i % 4; // a grid of instances, four per row
    const Eigen::Vector3f translation (0.15f * static_cast<float> (column) - 0.2f,
                                       0.15f * static_cast<float> (row),
                                       0.9f);
    const Eigen::Isometry3f pose = mid::test::rigidMotion (
        translation, 3.0f * unit (rng), {unit (rng), unit (rng), 1.0f});
    for (const auto& m : model) {
      pcl::PointNormal p;
      p.getVector3fMap() =
          pose * m + Eigen::Vector3f (noise (rng), noise (rng), noise (rng));
      p.getNormalVector3fMap() = Eigen::Vector3f::UnitZ();
      s.keypoints->push_back (p);
    }
  }
  std::uniform_int_distribution<int> instance (0, kInstances - 1),
      point (0, kPoints - 1);
  std::uniform_int_distribution<int> any (0, kInstances * kPoints - 1);
  while (static_cast<int> (s.triplets->size()) < n) {
    const bool outlier = s.triplets->size() % 10 >= 7;
    const int i = instance (rng),
              j = (i + 1 + instance (rng) % (kInstances - 1)) % kInstances;
    std::array<int, 3> p{}, q{};
    for (std::size_t k = 0; k < 3; ++k) {
      const int m = point (rng);
      p[k] = outlier ? any (rng) : i * kPoints + m;
      q[k] = outlier ? any (rng) : j * kPoints + m;
    }
    if (p[0] == p[1] || p[1] == p[2] || p[0] == p[2])
      continue;
    mid::TripletMatch t;
    Eigen::Matrix3Xf from (3, 3), to (3, 3);
    for (std::size_t k = 0; k < 3; ++k) {
      t.correspondences[k] = pcl::Correspondence (p[k], q[k], 100.0f);
      from.col (static_cast<Eigen::Index> (k)) =
          (*s.keypoints)[static_cast<std::size_t> (p[k])].getVector3fMap();
      to.col (static_cast<Eigen::Index> (k)) =
          (*s.keypoints)[static_cast<std::size_t> (q[k])].getVector3fMap();
    }
    t.transformation = mid::estimateRigidTransform (from, to, &t.rms_error);
    s.triplets->push_back (t);
  }
  return s;
}

void
BM_ClusteringAsShipped (benchmark::State& state)
{
  const SyntheticTriplets s =
      makeSyntheticTriplets (static_cast<int> (state.range (0)));
  mid::TransformationSpaceClustering clustering;
  clustering.setInputCloud (s.keypoints);
  clustering.setSceneCloud (s.keypoints);
  clustering.setInputTriplets (s.triplets);
  mid::TransformationSpaceClustering::Transformations poses;
  std::size_t peak = 0;
  for (auto _ : state) {
    const std::size_t before = mid::bench::currentAllocatedBytes();
    mid::bench::resetPeakAllocatedBytes();
    clustering.recognize (poses);
    peak = mid::bench::peakAllocatedBytes() - before;
  }
  state.counters["clusters"] = static_cast<double> (poses.size());
  state.counters["peak_MiB"] = static_cast<double> (peak) / (1024.0 * 1024.0);
  state.SetComplexityN (state.range (0));
}
BENCHMARK (BM_ClusteringAsShipped)
    ->Arg (1000)
    ->Arg (5000)
    ->Arg (20000)
    ->Unit (benchmark::kMillisecond)
    ->Complexity()
    ->Iterations (1);

/** The reference: DBSCAN with the paper's distance evaluated for every pair, no bound. */
void
BM_DbscanAllPairsReference (benchmark::State& state)
{
  const SyntheticTriplets s =
      makeSyntheticTriplets (static_cast<int> (state.range (0)));
  std::vector<mid::TripletGeometry, Eigen::aligned_allocator<mid::TripletGeometry>>
      geometry;
  for (const auto& t : *s.triplets)
    geometry.push_back (mid::makeTripletGeometry (t, *s.keypoints, *s.keypoints));
  mid::DBSCAN dbscan;
  const auto query = mid::makeAllPairsRegionQuery (
      geometry.size(), 0.035, [&geometry] (std::size_t i, std::size_t j) {
        return static_cast<double> (mid::tripletDistance (geometry[i], geometry[j]));
      });
  std::vector<int> labels;
  std::size_t clusters = 0;
  for (auto _ : state)
    clusters = dbscan.cluster (geometry.size(), query, labels);
  state.counters["clusters"] = static_cast<double> (clusters);
  state.SetComplexityN (state.range (0));
}
BENCHMARK (BM_DbscanAllPairsReference)
    ->Arg (1000)
    ->Arg (5000)
    ->Arg (20000)
    ->Unit (benchmark::kMillisecond)
    ->Complexity()
    ->Iterations (1);

} // namespace

BENCHMARK_MAIN();
