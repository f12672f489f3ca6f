// Cost of the PPF triplet rejector as the number of matches M grows, with the peak memory of
// one call, on synthetic keypoints of repeated random objects (70 % true matches, 30 % outliers,
// 1 mm noise); and, on a VGA frame, its time next to SIFT extraction in the same run.
//
//   build/test/benchmark/bench_rejector [--benchmark_filter=...]

#include "memory_counter.h"
#include "rigid_motion.h"
#include "two_copies_scene.h"

#include <mid/features/self_matcher.h>
#include <mid/features/sift_keypoint_extractor.h>
#include <mid/registration/correspondence_rejection_ppf_triplet.h>

#include <benchmark/benchmark.h>
#include <Eigen/Geometry>
#include <pcl/common/time.h>

#include <cmath>
#include <random>

namespace {

struct SyntheticMatches
{
  mid::KeypointCloud::Ptr keypoints = pcl::make_shared<mid::KeypointCloud>();
  pcl::Correspondences matches;
};

/** M matches among `instances` copies of a random object of `per_instance` keypoints in a 12 cm
  * cube, placed side by side on a grid (15 cm apart) at about 0.9 m; 70 % of the matches join a
  * keypoint to the same keypoint on another instance, 30 % are random.
  */
SyntheticMatches
makeSyntheticMatches (int m, int instances, int per_instance, unsigned seed = 1)
{
  std::mt19937 rng (seed);
  std::uniform_real_distribution<float> unit (-0.5f, 0.5f);
  std::normal_distribution<float> noise (0.0f, 0.001f);
  std::vector<Eigen::Vector3f> points, normals;
  for (int k = 0; k < per_instance; ++k) {
    points.emplace_back (unit (rng) * 0.12f, unit (rng) * 0.12f, unit (rng) * 0.12f);
    normals.push_back (Eigen::Vector3f (unit (rng), unit (rng), -1.0f).normalized());
  }
  SyntheticMatches s;
  const int columns =
      static_cast<int> (std::ceil (std::sqrt (static_cast<double> (instances))));
  for (int i = 0; i < instances; ++i) {
    const int row = i / columns, column = i % columns; // a grid of instances
    const Eigen::Vector3f translation (0.15f * static_cast<float> (column),
                                       0.15f * static_cast<float> (row),
                                       0.9f + unit (rng) * 0.1f);
    const float angle = unit (rng) * 3.0f;
    const Eigen::Vector3f axis (unit (rng), unit (rng), unit (rng));
    const Eigen::Isometry3f pose = mid::test::rigidMotion (translation, angle, axis);
    for (int k = 0; k < per_instance; ++k) {
      pcl::PointNormal p;
      p.getVector3fMap() = pose * points[static_cast<std::size_t> (k)] +
                           Eigen::Vector3f (noise (rng), noise (rng), noise (rng));
      p.getNormalVector3fMap() = pose.linear() * normals[static_cast<std::size_t> (k)];
      s.keypoints->push_back (p);
    }
  }
  std::uniform_int_distribution<int> instance (0, instances - 1),
      keypoint (0, per_instance - 1);
  std::uniform_int_distribution<int> any (0, instances * per_instance - 1);
  std::uniform_real_distribution<float> distance (50.0f, 250.0f);
  while (static_cast<int> (s.matches.size()) < m) {
    const bool outlier = s.matches.size() % 10 >= 7;
    const int i = instance (rng), k = keypoint (rng);
    const int other = (i + 1 + instance (rng) % (instances - 1)) % instances;
    const int a = i * per_instance + k;
    const int b = outlier ? any (rng) : other * per_instance + k;
    if (a != b)
      s.matches.emplace_back (a, b, distance (rng));
  }
  return s;
}

/** Runs the rejector on the matches, reporting triplets and the peak memory of one call. */
void
runRejector (benchmark::State& state, const SyntheticMatches& s)
{
  mid::CorrespondenceRejectorPPFTriplet rejector;
  rejector.setInputSource (s.keypoints);
  pcl::Correspondences remaining;
  std::size_t peak = 0;
  for (auto _ : state) {
    const std::size_t before = mid::bench::currentAllocatedBytes();
    mid::bench::resetPeakAllocatedBytes();
    rejector.getRemainingCorrespondences (s.matches, remaining);
    peak = mid::bench::peakAllocatedBytes() - before;
  }
  state.counters["triplets"] =
      static_cast<double> (rejector.getTripletMatches().size());
  state.counters["peak_MiB"] = static_cast<double> (peak) / (1024.0 * 1024.0);
  state.SetComplexityN (state.range (0));
}

/** Constant keypoint density: 60 keypoints per instance, more instances as M grows. */
void
BM_RejectorSpread (benchmark::State& state)
{
  const int m = static_cast<int> (state.range (0));
  runRejector (state, makeSyntheticMatches (m, std::max (2, m / 42), 60));
}
BENCHMARK (BM_RejectorSpread)
    ->Arg (250)
    ->Arg (500)
    ->Arg (1000)
    ->Arg (2000)
    ->Arg (4000)
    ->Unit (benchmark::kMillisecond)
    ->Complexity();

/** Worst case: six instances whose keypoints get denser as M grows (all pairs are near). */
void
BM_RejectorDense (benchmark::State& state)
{
  const int m = static_cast<int> (state.range (0));
  runRejector (state, makeSyntheticMatches (m, 6, std::max (3, m * 7 / 30)));
}
BENCHMARK (BM_RejectorDense)
    ->Arg (250)
    ->Arg (500)
    ->Arg (1000)
    ->Arg (2000)
    ->Arg (4000)
    ->Unit (benchmark::kMillisecond)
    ->Complexity();

/** SIFT extraction and the rejector on the same VGA frame, timed in the same iteration. */
void
BM_VgaFrameRejectorVersusSift (benchmark::State& state)
{
  const auto scene = mid::test::makeTwoCopiesScene();
  mid::SIFTKeypointExtractor<pcl::PointXYZRGB> extractor;
  extractor.setInputCloud (scene.cloud);
  auto keypoints = pcl::make_shared<mid::KeypointCloud>();
  auto descriptors = pcl::make_shared<mid::SIFTDescriptorCloud>();
  mid::SelfMatcher matcher;
  mid::CorrespondenceRejectorPPFTriplet rejector;
  double sift_ms = 0.0, rejector_ms = 0.0;
  pcl::Correspondences matches, remaining;
  for (auto _ : state) {
    pcl::StopWatch watch;
    extractor.compute (*keypoints, *descriptors);
    sift_ms += watch.getTime();
    matcher.setInputKeypoints (keypoints);
    matcher.setInputDescriptors (descriptors);
    matcher.match (matches);
    rejector.setInputSource (keypoints);
    watch.reset();
    rejector.getRemainingCorrespondences (matches, remaining);
    rejector_ms += watch.getTime();
  }
  const auto runs = static_cast<double> (state.iterations());
  state.counters["sift_ms"] = sift_ms / runs;
  state.counters["rejector_ms"] = rejector_ms / runs;
  state.counters["rejector_over_sift"] = rejector_ms / sift_ms;
  state.counters["matches"] = static_cast<double> (matches.size());
}
BENCHMARK (BM_VgaFrameRejectorVersusSift)->Unit (benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
