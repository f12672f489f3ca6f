#include <mid/segmentation/keypoint_patch.h>

#include <pcl/console/print.h>
#include <pcl/kdtree/kdtree_flann.h>

#include <algorithm>

namespace mid {

bool
densestKeypointPatch (const KeypointCloud& keypoints,
                      const std::vector<bool>& free,
                      float radius,
                      std::size_t min_keypoints,
                      pcl::Indices& patch)
{
  patch.clear();
  if (free.size() != keypoints.size() || !(radius > 0.0f) || min_keypoints == 0) {
    PCL_ERROR ("[mid::densestKeypointPatch] Need one free flag per keypoint (%zu for "
               "%zu), a positive radius (%g) and at least one keypoint per patch.\n",
               free.size(),
               keypoints.size(),
               static_cast<double> (radius),
               min_keypoints);
    return false;
  }
  auto candidates = pcl::make_shared<pcl::Indices>();
  for (std::size_t k = 0; k < keypoints.size(); ++k)
    if (free[k] && keypoints[k].getVector3fMap().allFinite())
      candidates->push_back (static_cast<pcl::index_t> (k));
  if (candidates->size() < min_keypoints)
    return true;
  pcl::KdTreeFLANN<pcl::PointNormal> tree;
  tree.setInputCloud (keypoints.makeShared(), candidates);
  pcl::Indices near;
  std::vector<float> distances;
  std::size_t most = 0;
  for (const pcl::index_t k : *candidates) {
    tree.radiusSearch (
        keypoints[static_cast<std::size_t> (k)], radius, near, distances);
    if (near.size() < min_keypoints || near.size() <= most)
      continue;
    most = near.size();
    std::sort (near.begin(), near.end());
    patch.assign (1, k);
    for (const pcl::index_t n : near)
      if (n != k)
        patch.push_back (n);
  }
  return true;
}

} // namespace mid
