#include <mid/features/self_matcher.h>

#include <opencv2/core.hpp>
#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <utility>
#include <vector>

namespace mid {

namespace {

/** Rows of the distance matrix computed at once: 256 x N floats stays small for any N. */
constexpr int kRowBlock = 256;

/** The nearest admissible candidates of one query keypoint, nearest first (at most k + 1, the
  * last one only for the ratio test).
  */
struct Nearest
{
  std::vector<std::pair<float, int>> candidates; ///< (descriptor distance, keypoint)

  /** Insert a candidate, keeping the `capacity` nearest; ties go to the smaller index (the
    * candidates arrive in increasing index order).
    */
  void
  offer (float distance, int keypoint, std::size_t capacity)
  {
    if (candidates.size() == capacity && !(distance < candidates.back().first))
      return;
    auto at = std::upper_bound (
        candidates.begin(),
        candidates.end(),
        distance,
        [] (float d, const std::pair<float, int>& c) { return d < c.first; });
    candidates.insert (at, {distance, keypoint});
    if (candidates.size() > capacity)
      candidates.pop_back();
  }

  int
  best () const
  {
    return candidates.empty() ? -1 : candidates.front().second;
  }
};

cv::Mat
descriptorMatrix (const SIFTDescriptorCloud& descriptors)
{
  cv::Mat matrix (static_cast<int> (descriptors.size()), 128, CV_32F);
  for (int i = 0; i < matrix.rows; ++i)
    std::copy (descriptors[static_cast<std::size_t> (i)].histogram,
               descriptors[static_cast<std::size_t> (i)].histogram + 128,
               matrix.ptr<float> (i));
  return matrix;
}

/** For every keypoint, the `capacity` nearest other keypoints in descriptor space that lie at
  * least min_distance away in 3D; ties go to the smaller index.
  */
std::vector<Nearest>
findNearest (const KeypointCloud& keypoints,
             const cv::Mat& descriptors,
             float min_distance,
             std::size_t capacity)
{
  const int n = descriptors.rows;
  const float min_squared = min_distance * min_distance;
  std::vector<Nearest> result (static_cast<std::size_t> (n));
  cv::Mat distances;
  for (int start = 0; start < n; start += kRowBlock) {
    const int rows = std::min (kRowBlock, n - start);
    cv::batchDistance (descriptors.rowRange (start, start + rows),
                       descriptors,
                       distances,
                       CV_32F,
                       cv::noArray(),
                       cv::NORM_L2);
    for (int r = 0; r < rows; ++r) {
      const int i = start + r;
      const float* row = distances.ptr<float> (r);
      const Eigen::Vector3f query =
          keypoints[static_cast<std::size_t> (i)].getVector3fMap();
      Nearest& nearest = result[static_cast<std::size_t> (i)];
      for (int j = 0; j < n; ++j) {
        // A NaN distance (a NaN descriptor) is never a candidate.
        if (j == i || std::isnan (row[j]) ||
            (keypoints[static_cast<std::size_t> (j)].getVector3fMap() - query)
                    .squaredNorm() < min_squared)
          continue;
        nearest.offer (row[j], j, capacity);
      }
    }
  }
  return result;
}

} // namespace

bool
SelfMatcher::match (pcl::Correspondences& matches) const
{
  matches.clear();
  if (!keypoints_ || !descriptors_) {
    PCL_ERROR ("[mid::SelfMatcher::match] No input keypoints or descriptors given.\n");
    return false;
  }
  if (keypoints_->size() != descriptors_->size()) {
    PCL_ERROR ("[mid::SelfMatcher::match] %zu keypoints but %zu descriptors; they must "
               "pair up.\n",
               keypoints_->size(),
               descriptors_->size());
    return false;
  }
  if (!(max_descriptor_distance_ > 0.0f) || !(min_keypoint_distance_ >= 0.0f) ||
      !(max_distance_ratio_ > 0.0f && max_distance_ratio_ <= 1.0f) ||
      max_matches_per_keypoint_ < 1) {
    PCL_ERROR ("[mid::SelfMatcher::match] Invalid parameter: max descriptor distance "
               "%g (> 0), "
               "min keypoint distance %g (>= 0), max distance ratio %g (in (0, 1]), "
               "matches per keypoint %d (>= 1).\n",
               static_cast<double> (max_descriptor_distance_),
               static_cast<double> (min_keypoint_distance_),
               static_cast<double> (max_distance_ratio_),
               max_matches_per_keypoint_);
    return false;
  }
  if (keypoints_->size() < 2)
    return true;

  const auto k = static_cast<std::size_t> (max_matches_per_keypoint_);
  const std::vector<Nearest> nearest = findNearest (
      *keypoints_, descriptorMatrix (*descriptors_), min_keypoint_distance_, k + 1);
  // Each matched keypoint's most similar keypoint first (the paper's matches, both directions
  // of a pair kept), then the further candidates of k > 1 whose pair is not yet matched.
  std::vector<bool> matched (nearest.size(), false);
  std::set<std::pair<pcl::index_t, pcl::index_t>> pairs;
  for (std::size_t i = 0; i < nearest.size(); ++i) {
    const auto& candidates = nearest[i].candidates;
    if (candidates.empty() || candidates.front().first > max_descriptor_distance_)
      continue;
    const float second = candidates.size() > 1 ? candidates[1].first
                                               : std::numeric_limits<float>::infinity();
    if (max_distance_ratio_ < 1.0f &&
        !(candidates.front().first < max_distance_ratio_ * second))
      continue;
    if (mutual_check_ &&
        nearest[static_cast<std::size_t> (candidates.front().second)].best() !=
            static_cast<int> (i))
      continue;
    const auto query = static_cast<pcl::index_t> (i);
    const pcl::index_t j = candidates.front().second;
    matches.emplace_back (query, j, candidates.front().first);
    pairs.emplace (std::min (query, j), std::max (query, j));
    matched[i] = true;
  }
  for (std::size_t i = 0; i < nearest.size(); ++i) {
    if (!matched[i])
      continue;
    const auto& candidates = nearest[i].candidates;
    for (std::size_t c = 1; c < std::min (k, candidates.size()); ++c) {
      const auto query = static_cast<pcl::index_t> (i);
      const auto [distance, j] = candidates[c];
      if (distance <= max_descriptor_distance_ &&
          pairs.emplace (std::min (query, j), std::max (query, j)).second)
        matches.emplace_back (query, j, distance);
    }
  }
  return true;
}

} // namespace mid
