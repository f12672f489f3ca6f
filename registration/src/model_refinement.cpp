#include <mid/registration/model_refinement.h>
#include <mid/registration/rigid_transform.h>

#include <cmath>
#include <set>

namespace mid {

namespace {

/** Mean squared residual over all observations. */
float
meanSquaredResidual (const ObjectModel& model, const KeypointCloud& keypoints)
{
  float sum = 0.0f;
  std::size_t count = 0;
  for (const auto& instance : model.instances) {
    const Eigen::Matrix3f rotation = instance.pose.topLeftCorner<3, 3>();
    const Eigen::Vector3f translation = instance.pose.topRightCorner<3, 1>();
    for (std::size_t o = 0; o < instance.keypoints.size(); ++o) {
      const auto& landmark =
          model.landmarks[static_cast<std::size_t> (instance.landmarks[o])];
      const auto& keypoint =
          keypoints[static_cast<std::size_t> (instance.keypoints[o])];
      sum += (rotation * landmark.getVector3fMap() + translation -
              keypoint.getVector3fMap())
                 .squaredNorm();
      ++count;
    }
  }
  return count > 0 ? sum / static_cast<float> (count) : 0.0f;
}

/** Each pose but the fixed one := Umeyama fit of its landmarks onto its keypoints. */
void
updatePoses (ObjectModel& model,
             const KeypointCloud& keypoints,
             std::size_t fixed_instance)
{
  for (std::size_t n = 0; n < model.instances.size(); ++n) {
    auto& instance = model.instances[n];
    const std::set<int> distinct (instance.landmarks.begin(), instance.landmarks.end());
    if (n == fixed_instance || distinct.size() < 3)
      continue;
    const auto count = static_cast<Eigen::Index> (instance.keypoints.size());
    Eigen::Matrix3Xf from (3, count), to (3, count);
    for (Eigen::Index o = 0; o < count; ++o) {
      const auto k = static_cast<std::size_t> (o);
      from.col (o) = model.landmarks[static_cast<std::size_t> (instance.landmarks[k])]
                         .getVector3fMap();
      to.col (o) =
          keypoints[static_cast<std::size_t> (instance.keypoints[k])].getVector3fMap();
    }
    instance.pose = estimateRigidTransform (from, to);
  }
}

} // namespace

void
updateModelLandmarks (ObjectModel& model, const KeypointCloud& keypoints)
{
  std::vector<Eigen::Vector3f, Eigen::aligned_allocator<Eigen::Vector3f>> sums (
      model.landmarks.size(), Eigen::Vector3f::Zero());
  std::vector<int> counts (model.landmarks.size(), 0);
  for (const auto& instance : model.instances) {
    const Eigen::Matrix3f rotation = instance.pose.topLeftCorner<3, 3>();
    const Eigen::Vector3f translation = instance.pose.topRightCorner<3, 1>();
    for (std::size_t o = 0; o < instance.keypoints.size(); ++o) {
      const auto l = static_cast<std::size_t> (instance.landmarks[o]);
      const Eigen::Vector3f z =
          keypoints[static_cast<std::size_t> (instance.keypoints[o])].getVector3fMap();
      sums[l] += rotation.transpose() * (z - translation);
      ++counts[l];
    }
  }
  for (std::size_t l = 0; l < model.landmarks.size(); ++l)
    if (counts[l] > 0)
      model.landmarks[l].getVector3fMap() = sums[l] / static_cast<float> (counts[l]);
}

float
refineModel (ObjectModel& model,
             const KeypointCloud& keypoints,
             int max_iterations,
             std::size_t fixed_instance,
             std::vector<float>* costs)
{
  float cost = meanSquaredResidual (model, keypoints);
  if (costs != nullptr)
    costs->assign (1, cost);
  for (int iteration = 0; iteration < max_iterations; ++iteration) {
    updateModelLandmarks (model, keypoints);
    updatePoses (model, keypoints, fixed_instance);
    const float next = meanSquaredResidual (model, keypoints);
    if (costs != nullptr)
      costs->push_back (next);
    const bool converged = cost - next <= 1e-6f * cost;
    cost = next;
    if (converged)
      break;
  }
  for (auto& instance : model.instances)
    updateInstanceError (model, keypoints, instance);
  return std::sqrt (cost);
}

} // namespace mid
