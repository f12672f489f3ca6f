#include <mid/registration/landmark_box.h>
#include <mid/registration/observation_pruning.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <limits>
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

/** True if the model is usable by the pruning step `step`; else false, with a PCL_ERROR. */
bool
usableModel (const char* step, const ObjectModel& model, std::size_t keypoints)
{
  std::string problem = observationProblem (model, keypoints);
  if (problem.empty())
    problem = descriptorProblem (model);
  if (!problem.empty())
    PCL_ERROR ("[mid::%s] The model is not usable: %s.\n", step, problem.c_str());
  return problem.empty();
}

/** Keep the observations for which `keep (n, o)` holds (observation o of instance n) and drop
  * the others, except in an instance that would keep none (it keeps them all). A pruned
  * instance's error is updated; the landmarks that had observations and have none left are
  * removed with their descriptors, and the diameter is updated. Returns how many observations
  * were dropped. `before` is observationCounts (model), which a caller may need too.
  */
template <typename Keep>
std::size_t
keepObservations (const KeypointCloud& keypoints,
                  const std::vector<std::size_t>& before,
                  ObjectModel& model,
                  const Keep& keep)
{
  std::size_t dropped = 0;
  for (std::size_t n = 0; n < model.instances.size(); ++n) {
    ModelInstance& instance = model.instances[n];
    ModelInstance kept = instance;
    kept.keypoints.clear();
    kept.landmarks.clear();
    for (std::size_t o = 0; o < instance.keypoints.size(); ++o)
      if (keep (n, o)) {
        kept.keypoints.push_back (instance.keypoints[o]);
        kept.landmarks.push_back (instance.landmarks[o]);
      }
    if (kept.keypoints.empty() || kept.keypoints.size() == instance.keypoints.size())
      continue;
    dropped += instance.keypoints.size() - kept.keypoints.size();
    updateInstanceError (model, keypoints, kept);
    instance = kept;
  }
  if (dropped == 0)
    return 0;
  const std::vector<std::size_t> after = observationCounts (model);
  std::vector<bool> remove (model.landmarks.size(), false);
  for (std::size_t l = 0; l < remove.size(); ++l)
    remove[l] = before[l] > 0 && after[l] == 0;
  removeLandmarks (remove, model);
  updateModelDiameter (model);
  return dropped;
}

/** Fewest distinct places of an instance's keypoints for its footprint to judge another's. */
constexpr std::size_t kMinFootprintPlaces = 3;

/** An instance's keypoints as points, with their centroid and RMS radius. */
struct KeypointFootprint
{
  std::vector<Eigen::Vector3f, Eigen::aligned_allocator<Eigen::Vector3f>> points;
  Eigen::Vector3f centroid = Eigen::Vector3f::Zero();
  float radius = 0.0f;
  std::size_t places = 0; ///< distinct positions among `points`
};

KeypointFootprint
footprintOf (const KeypointCloud& keypoints, const ModelInstance& instance)
{
  KeypointFootprint footprint;
  for (const auto k : instance.keypoints) {
    const Eigen::Vector3f p = keypoints[static_cast<std::size_t> (k)].getVector3fMap();
    if (!p.allFinite())
      continue;
    bool seen = false;
    for (const auto& q : footprint.points)
      seen = seen || q == p;
    footprint.places += seen ? 0 : 1;
    footprint.points.push_back (p);
    footprint.centroid += p;
  }
  if (footprint.points.empty())
    return footprint;
  footprint.centroid /= static_cast<float> (footprint.points.size());
  float sum = 0.0f;
  for (const auto& p : footprint.points)
    sum += (p - footprint.centroid).squaredNorm();
  footprint.radius = std::sqrt (sum / static_cast<float> (footprint.points.size()));
  return footprint;
}

/** Distance from `p` to the nearest of the footprint's points at another place than p. */
float
nearestOtherPlace (const KeypointFootprint& footprint, const Eigen::Vector3f& p)
{
  float nearest = std::numeric_limits<float>::infinity();
  for (const auto& q : footprint.points)
    if (q != p)
      nearest = std::min (nearest, (q - p).norm());
  return nearest;
}

} // namespace

bool
pruneObservationsOnOtherCopies (const KeypointCloud& keypoints,
                                ObjectModel& model,
                                std::size_t& dropped)
{
  dropped = 0;
  if (!usableModel ("pruneObservationsOnOtherCopies", model, keypoints.size()))
    return false;
  std::vector<KeypointFootprint> footprints;
  for (const auto& instance : model.instances)
    footprints.push_back (footprintOf (keypoints, instance));
  const auto own_copy = [&] (std::size_t a, std::size_t o) {
    const Eigen::Vector3f p =
        keypoints[static_cast<std::size_t> (model.instances[a].keypoints[o])]
            .getVector3fMap();
    const float own = nearestOtherPlace (footprints[a], p);
    for (std::size_t b = 0; b < footprints.size(); ++b)
      if (b != a && footprints[b].places >= kMinFootprintPlaces &&
          (p - footprints[b].centroid).norm() < footprints[b].radius &&
          nearestOtherPlace (footprints[b], p) < own)
        return false;
    return true;
  };
  dropped = keepObservations (keypoints, observationCounts (model), model, own_copy);
  return true;
}

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
  if (!usableModel ("pruneUnexplainedObservations", model, keypoints.size()))
    return false;
  const LandmarkBox box = computeLandmarkBox (model);
  const std::vector<std::size_t> before = observationCounts (model);
  std::vector<Eigen::Matrix4f, Eigen::aligned_allocator<Eigen::Matrix4f>> to_model;
  for (const auto& instance : model.instances)
    to_model.emplace_back (instance.pose.inverse());
  const auto explained = [&] (std::size_t n, std::size_t o) {
    const ModelInstance& instance = model.instances[n];
    if (!instance.pose.allFinite())
      return true;
    const Eigen::Vector3f local =
        to_model[n].topLeftCorner<3, 3>() *
            keypoints[static_cast<std::size_t> (instance.keypoints[o])]
                .getVector3fMap() +
        to_model[n].topRightCorner<3, 1>();
    const Eigen::Vector3f landmark =
        model.landmarks[static_cast<std::size_t> (instance.landmarks[o])]
            .getVector3fMap();
    // A landmark that only this instance observes shows its own surface (a face no other
    // copy shows, as a copy found by its size has): the box of the others does not judge it.
    const bool own = before[static_cast<std::size_t> (instance.landmarks[o])] == 1;
    const bool in_box = own || !box.valid || box.distanceTo (local) <= box_margin;
    return (local - landmark).norm() <= max_residual && in_box;
  };
  dropped = keepObservations (keypoints, before, model, explained);
  return true;
}

} // namespace mid
