#include <mid/registration/landmark_box.h>
#include <mid/registration/observation_pruning.h>

#include <pcl/console/print.h>

#include <string>
#include <vector>

namespace mid {

namespace {

/** How many observations each landmark has among the model's instances. */
std::vector<std::size_t>
observationCounts (const ObjectModel& model)
{
  std::vector<std::size_t> counts (model.landmarks.size(), 0);
  for (const auto& instance : model.instances)
    for (const int l : instance.landmarks)
      ++counts[static_cast<std::size_t> (l)];
  return counts;
}

} // namespace

bool
pruneUnexplainedObservations (const KeypointCloud& keypoints,
                              float max_residual,
                              float box_margin,
                              ObjectModel& model,
                              std::size_t& dropped)
{
  dropped = 0;
  if (!(max_residual > 0.0f) || !(box_margin >= 0.0f)) {
    PCL_ERROR (
        "[mid::pruneUnexplainedObservations] The largest residual must be > 0 and "
        "the box margin >= 0 (given %g and %g).\n",
        static_cast<double> (max_residual),
        static_cast<double> (box_margin));
    return false;
  }
  std::string problem = observationProblem (model, keypoints.size());
  if (problem.empty())
    problem = descriptorProblem (model);
  if (!problem.empty()) {
    PCL_ERROR ("[mid::pruneUnexplainedObservations] The model is not usable: %s.\n",
               problem.c_str());
    return false;
  }
  const LandmarkBox box = computeLandmarkBox (model);
  const std::vector<std::size_t> before = observationCounts (model);
  for (auto& instance : model.instances) {
    if (!instance.pose.allFinite())
      continue;
    const Eigen::Matrix4f to_model = instance.pose.inverse();
    ModelInstance kept = instance;
    kept.keypoints.clear();
    kept.landmarks.clear();
    for (std::size_t o = 0; o < instance.keypoints.size(); ++o) {
      const Eigen::Vector3f local =
          to_model.topLeftCorner<3, 3>() *
              keypoints[static_cast<std::size_t> (instance.keypoints[o])]
                  .getVector3fMap() +
          to_model.topRightCorner<3, 1>();
      const Eigen::Vector3f landmark =
          model.landmarks[static_cast<std::size_t> (instance.landmarks[o])]
              .getVector3fMap();
      // A landmark that only this instance observes shows its own surface (a face no other
      // copy shows, as a copy found by its size has): the box of the others does not judge it.
      const bool own = before[static_cast<std::size_t> (instance.landmarks[o])] == 1;
      const bool in_box = own || !box.valid || box.distanceTo (local) <= box_margin;
      if ((local - landmark).norm() <= max_residual && in_box) {
        kept.keypoints.push_back (instance.keypoints[o]);
        kept.landmarks.push_back (instance.landmarks[o]);
      }
    }
    if (kept.keypoints.empty() || kept.keypoints.size() == instance.keypoints.size())
      continue;
    dropped += instance.keypoints.size() - kept.keypoints.size();
    updateInstanceError (model, keypoints, kept);
    instance = kept;
  }
  if (dropped == 0)
    return true;
  const std::vector<std::size_t> after = observationCounts (model);
  std::vector<bool> remove (model.landmarks.size(), false);
  for (std::size_t l = 0; l < remove.size(); ++l)
    remove[l] = before[l] > 0 && after[l] == 0;
  removeLandmarks (remove, model);
  updateModelDiameter (model);
  return true;
}

} // namespace mid
