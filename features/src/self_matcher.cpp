#include <mid/features/self_matcher.h>

#include <opencv2/core.hpp>
#include <pcl/console/print.h>

#include <algorithm>
#include <limits>
#include <vector>

namespace mid {

namespace {

/** Rows of the distance matrix computed at once: 256 x N floats stays small for any N. */
constexpr int kRowBlock = 256;

/** The best and second-best admissible candidate of one query keypoint. */
struct BestTwo
{
  int best = -1;
  float best_distance = std::numeric_limits<float>::infinity();
  float second_distance = std::numeric_limits<float>::infinity();
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

/** For every keypoint, the nearest and second-nearest other keypoint in descriptor space that
  * lies at least min_distance away in 3D; ties go to the smaller index.
  */
std::vector<BestTwo>
findBestTwo (const KeypointCloud& keypoints,
             const cv::Mat& descriptors,
             float min_distance)
{
  const int n = descriptors.rows;
  const float min_squared = min_distance * min_distance;
  std::vector<BestTwo> result (static_cast<std::size_t> (n));
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
      BestTwo& best = result[static_cast<std::size_t> (i)];
      for (int j = 0; j < n; ++j) {
        if (j == i || (keypoints[static_cast<std::size_t> (j)].getVector3fMap() - query)
                              .squaredNorm() < min_squared)
          continue;
        if (row[j] < best.best_distance) {
          best.second_distance = best.best_distance;
          best.best_distance = row[j];
          best.best = j;
        }
        else if (row[j] < best.second_distance)
          best.second_distance = row[j];
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
      !(max_distance_ratio_ > 0.0f && max_distance_ratio_ <= 1.0f)) {
    PCL_ERROR ("[mid::SelfMatcher::match] Invalid parameter: max descriptor distance "
               "%g (> 0), "
               "min keypoint distance %g (>= 0), max distance ratio %g (in (0, 1]).\n",
               static_cast<double> (max_descriptor_distance_),
               static_cast<double> (min_keypoint_distance_),
               static_cast<double> (max_distance_ratio_));
    return false;
  }
  if (keypoints_->size() < 2)
    return true;

  const std::vector<BestTwo> best = findBestTwo (
      *keypoints_, descriptorMatrix (*descriptors_), min_keypoint_distance_);
  for (std::size_t i = 0; i < best.size(); ++i) {
    const BestTwo& candidate = best[i];
    if (candidate.best < 0 || candidate.best_distance > max_descriptor_distance_)
      continue;
    if (max_distance_ratio_ < 1.0f &&
        !(candidate.best_distance < max_distance_ratio_ * candidate.second_distance))
      continue;
    if (mutual_check_ &&
        best[static_cast<std::size_t> (candidate.best)].best != static_cast<int> (i))
      continue;
    matches.emplace_back (
        static_cast<pcl::index_t> (i), candidate.best, candidate.best_distance);
  }
  return true;
}

} // namespace mid
