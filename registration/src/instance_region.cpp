#include <mid/registration/instance_region.h>
#include <mid/registration/landmark_box.h>

#include <limits>
#include <utility>

namespace mid {

std::vector<std::vector<pcl::Indices>>
computeInstanceRegions (const KeypointCloud& keypoints,
                        const ObjectModels& models,
                        float margin)
{
  // For each keypoint, the (model, instance) whose region holds it; model -1 for none.
  constexpr std::pair<int, int> none (-1, -1);
  std::vector<std::pair<int, int>> owner (keypoints.size(), none);
  std::vector<bool> observed (keypoints.size(), false);
  for (std::size_t m = 0; m < models.size(); ++m)
    for (std::size_t i = 0; i < models[m].instances.size(); ++i)
      for (const auto k : models[m].instances[i].keypoints) {
        owner[static_cast<std::size_t> (k)] = {static_cast<int> (m),
                                               static_cast<int> (i)};
        observed[static_cast<std::size_t> (k)] = true;
      }
  std::vector<float> nearest (keypoints.size(), std::numeric_limits<float>::infinity());
  for (std::size_t m = 0; m < models.size(); ++m) {
    const LandmarkBox box = computeLandmarkBox (models[m]);
    for (std::size_t i = 0; i < models[m].instances.size(); ++i) {
      const Eigen::Matrix4f to_model = models[m].instances[i].pose.inverse();
      for (std::size_t k = 0; k < keypoints.size(); ++k) {
        if (observed[k])
          continue;
        const float distance = box.distanceTo (to_model.topLeftCorner<3, 3>() *
                                                   keypoints[k].getVector3fMap() +
                                               to_model.topRightCorner<3, 1>());
        // NaN (a non-finite pose or keypoint) fails the first test.
        if (!(distance <= margin) || distance > nearest[k])
          continue;
        owner[k] = distance < nearest[k]
                       ? std::make_pair (static_cast<int> (m), static_cast<int> (i))
                       : none;
        nearest[k] = distance;
      }
    }
  }
  std::vector<std::vector<pcl::Indices>> regions (models.size());
  for (std::size_t m = 0; m < models.size(); ++m)
    regions[m].resize (models[m].instances.size());
  for (std::size_t k = 0; k < keypoints.size(); ++k)
    if (owner[k].first >= 0)
      regions[static_cast<std::size_t> (owner[k].first)]
             [static_cast<std::size_t> (owner[k].second)]
                 .push_back (static_cast<pcl::index_t> (k));
  return regions;
}

} // namespace mid
