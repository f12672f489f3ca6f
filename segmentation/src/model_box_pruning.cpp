#include <mid/segmentation/model_box_pruning.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <string>
#include <vector>

namespace mid {

namespace {

/** For each instance of `model`, a flag per observation: true if its keypoint lies within
  * `margin` of the box (box frame -> model frame `box_in_model`, edges `size`) placed by the
  * instance's pose.
  */
void
insideBox (const KeypointCloud& keypoints,
           const ObjectModel& model,
           const Eigen::Matrix4f& box_in_model,
           const Eigen::Vector3f& size,
           float margin,
           std::vector<std::vector<bool>>& inside)
{
  const Eigen::Array3f reach = 0.5f * size.array() + margin;
  inside.assign (model.instances.size(), {});
  for (std::size_t i = 0; i < model.instances.size(); ++i) {
    const ModelInstance& instance = model.instances[i];
    const Eigen::Affine3f to_box (box_in_model.inverse() * instance.pose.inverse());
    for (const auto k : instance.keypoints) {
      const Eigen::Vector3f p =
          to_box * keypoints[static_cast<std::size_t> (k)].getVector3fMap();
      inside[i].push_back ((p.array().abs() <= reach).all());
    }
  }
}

/** Keep the observations flagged `inside`; an instance left with none (that had some) goes,
  * unless fewer than two instances with observations would stay (then nothing changes);
  * landmarks left unobserved go. Returns how many observations went.
  */
std::size_t
keepInside (const KeypointCloud& keypoints,
            const std::vector<std::vector<bool>>& inside,
            ObjectModel& model)
{
  ModelInstances kept;
  std::size_t dropped = 0, observed = 0;
  for (std::size_t i = 0; i < model.instances.size(); ++i) {
    ModelInstance instance = model.instances[i];
    instance.keypoints.clear();
    instance.landmarks.clear();
    for (std::size_t o = 0; o < inside[i].size(); ++o)
      if (inside[i][o]) {
        instance.keypoints.push_back (model.instances[i].keypoints[o]);
        instance.landmarks.push_back (model.instances[i].landmarks[o]);
      }
    dropped += inside[i].size() - instance.keypoints.size();
    observed += instance.keypoints.empty() ? 0 : 1;
    if (!instance.keypoints.empty() || model.instances[i].keypoints.empty())
      kept.push_back (std::move (instance));
  }
  if (dropped == 0 || observed < 2)
    return 0;
  model.instances.swap (kept);
  std::vector<bool> unobserved (model.landmarks.size(), true);
  for (const auto& instance : model.instances)
    for (const int l : instance.landmarks)
      unobserved[static_cast<std::size_t> (l)] = false;
  removeLandmarks (unobserved, model);
  for (auto& instance : model.instances)
    updateInstanceError (model, keypoints, instance);
  updateModelDiameter (model);
  return dropped;
}

} // namespace

bool
ModelBoxPruning::prune (ObjectModels& models, std::size_t& dropped) const
{
  dropped = 0;
  std::string problem = measurementProblem (models);
  for (std::size_t m = 0; problem.empty() && m < models.size(); ++m)
    if (const std::string descriptors = descriptorProblem (models[m]);
        !descriptors.empty())
      problem = "model " + std::to_string (m) + ": " + descriptors;
  if (problem.empty() && !(margin_ >= 0.0f))
    problem = "the margin must be >= 0 (got " + std::to_string (margin_) + ")";
  if (!problem.empty()) {
    PCL_ERROR ("[mid::ModelBoxPruning::prune] %s.\n", problem.c_str());
    return false;
  }
  Eigen::Vector4f plane;
  if (models.empty() || !fitPlane (plane))
    return true;
  ModelSizes sizes;
  if (!measureSizes (models, plane, sizes))
    return false;
  // The box of the size, in the model frame: that of the copy the size came from, placed by
  // that copy's instance (ModelSize::box_in_model).
  for (std::size_t m = 0; m < models.size(); ++m) {
    if (!sizes[m].valid)
      continue;
    std::vector<std::vector<bool>> inside;
    insideBox (
        *keypoints_, models[m], sizes[m].box_in_model, sizes[m].size, margin_, inside);
    dropped += keepInside (*keypoints_, inside, models[m]);
  }
  return true;
}

} // namespace mid
