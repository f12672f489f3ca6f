#include <mid/segmentation/chain_splitting.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

namespace mid {

namespace {

/** The phase in [0, 1) at the middle of the largest empty interval of the phases, on the
  * circle.
  */
double
cutOfLargestGap (std::vector<double> phases)
{
  std::sort (phases.begin(), phases.end());
  double best_gap = phases.front() + 1.0 - phases.back(),
         cut = phases.back() + best_gap / 2;
  for (std::size_t i = 1; i < phases.size(); ++i)
    if (phases[i] - phases[i - 1] > best_gap) {
      best_gap = phases[i] - phases[i - 1];
      cut = phases[i - 1] + best_gap / 2;
    }
  return cut - std::floor (cut);
}

} // namespace

std::vector<std::vector<std::size_t>>
splitChainCluster (const TripletCluster& cluster,
                   const TripletMatches& triplets,
                   const KeypointCloud& keypoints,
                   float max_rotation)
{
  std::vector<std::size_t> all (cluster.triplets.size());
  std::iota (all.begin(), all.end(), std::size_t{0});
  const std::vector<std::vector<std::size_t>> whole{all};
  const Eigen::Matrix3f rotation = cluster.transformation.topLeftCorner<3, 3>();
  if (cluster.source_indices.empty() ||
      Eigen::AngleAxisf (rotation).angle() > max_rotation)
    return whole;

  Eigen::Vector3f centroid = Eigen::Vector3f::Zero();
  for (const auto k : cluster.source_indices)
    centroid += keypoints[static_cast<std::size_t> (k)].getVector3fMap();
  centroid /= static_cast<float> (cluster.source_indices.size());
  const Eigen::Vector3f step =
      rotation * centroid + cluster.transformation.topRightCorner<3, 1>() - centroid;
  if (!(step.squaredNorm() > 0.0f))
    return whole;
  const auto chain = [&] (pcl::index_t k) {
    return static_cast<double> (
        (keypoints[static_cast<std::size_t> (k)].getVector3fMap() - centroid)
            .dot (step) /
        step.squaredNorm());
  };

  std::vector<double> phases;
  for (const auto& indices : {cluster.source_indices, cluster.target_indices})
    for (const auto k : indices)
      phases.push_back (chain (k) - std::floor (chain (k)));
  const double cut = cutOfLargestGap (phases);
  const auto copy = [&] (pcl::index_t k) {
    return static_cast<long> (std::floor (chain (k) - cut));
  };

  std::map<long, std::vector<std::size_t>> parts;
  for (std::size_t m = 0; m < cluster.triplets.size(); ++m) {
    const auto& correspondences = triplets[cluster.triplets[m]].correspondences;
    const auto source = [&] (const pcl::Correspondence& c) {
      return cluster.reversed[m] ? c.index_match : c.index_query;
    };
    const auto target = [&] (const pcl::Correspondence& c) {
      return cluster.reversed[m] ? c.index_query : c.index_match;
    };
    const long first = copy (source (correspondences.front()));
    if (std::all_of (correspondences.begin(),
                     correspondences.end(),
                     [&] (const pcl::Correspondence& c) {
                       return copy (source (c)) == first &&
                              copy (target (c)) == first + 1;
                     }))
      parts[first].push_back (m);
  }
  if (parts.size() < 2)
    return whole;
  std::vector<std::vector<std::size_t>> split;
  for (auto& [copy_number, members] : parts)
    split.push_back (std::move (members));
  return split;
}

} // namespace mid
