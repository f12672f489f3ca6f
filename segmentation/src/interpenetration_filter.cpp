#include <mid/segmentation/interpenetration_filter.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <numeric>
#include <vector>

namespace mid {

namespace {

/** Whether each instance of `model` interpenetrates one that observes more keypoints (or as
  * many and comes earlier): its box centre lies closer than `max_distance` to that one's.
  */
std::vector<bool>
interpenetrating (const ObjectModel& model, const ModelSize& size, float max_distance)
{
  const auto& instances = model.instances;
  std::vector<std::size_t> order (instances.size());
  std::iota (order.begin(), order.end(), std::size_t{0});
  std::stable_sort (
      order.begin(), order.end(), [&instances] (std::size_t a, std::size_t b) {
        return instances[a].keypoints.size() > instances[b].keypoints.size();
      });
  std::vector<Eigen::Vector3f, Eigen::aligned_allocator<Eigen::Vector3f>> centres;
  centres.reserve (instances.size());
  for (const auto& instance : instances)
    centres.emplace_back ((instance.pose * size.box_in_model).topRightCorner<3, 1>());
  std::vector<bool> removed (instances.size(), false);
  for (std::size_t i = 0; i < order.size(); ++i)
    if (!removed[order[i]])
      for (std::size_t j = i + 1; j < order.size(); ++j)
        if (!removed[order[j]] &&
            (centres[order[i]] - centres[order[j]]).norm() < max_distance)
          removed[order[j]] = true;
  return removed;
}

} // namespace

bool
InterpenetrationFilter::filter (ObjectModels& models, std::size_t& removed) const
{
  removed = 0;
  std::string problem = measurementProblem (models);
  if (problem.empty() &&
      !(max_centre_distance_ >= 0.0f && max_centre_distance_ <= 1.0f))
    problem = "the largest centre distance must be in [0, 1] shortest edges";
  if (!problem.empty()) {
    PCL_ERROR ("[mid::InterpenetrationFilter::filter] %s.\n", problem.c_str());
    return false;
  }
  Eigen::Vector4f plane;
  if (models.empty() || !fitPlane (plane))
    return true;
  ModelSizes sizes;
  if (!measureSizes (models, plane, sizes))
    return false;
  std::vector<std::vector<bool>> gone (models.size());
  for (std::size_t m = 0; m < models.size(); ++m)
    if (sizes[m].valid)
      gone[m] = interpenetrating (
          models[m], sizes[m], max_centre_distance_ * sizes[m].size.minCoeff());
  removed = removeInstances (gone, models);
  return true;
}

} // namespace mid
