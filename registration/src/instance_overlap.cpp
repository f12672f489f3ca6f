#include <mid/registration/instance_overlap.h>
#include <mid/registration/model_merging.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <utility>

namespace mid {

namespace {

/** Length of the mean of unit normals below which they point too many ways to have a mean
  * direction (0.5: normals spread over a cone of about 60 deg half-angle, or two faces at
  * 120 deg).
  */
constexpr float kMinNormalAgreement = 0.5f;

/** instancesAdjoin()'s default angle, used by model merging. */
const float kAdjoinAngle = static_cast<float> (M_PI / 4.0);

/** Centroid, RMS radius and mean normal of an instance's observed keypoints. The mean normal
  * is the unit mean of the finite keypoint normals, zero when they do not agree (their mean is
  * shorter than kMinNormalAgreement) or none is finite.
  */
struct Footprint
{
  Eigen::Vector3f centroid = Eigen::Vector3f::Zero();
  float radius = 0.0f;
  Eigen::Vector3f normal = Eigen::Vector3f::Zero();
  bool valid = false;
};

Footprint
footprintOf (const KeypointCloud& keypoints, const ModelInstance& instance)
{
  Footprint footprint;
  if (instance.keypoints.empty())
    return footprint;
  std::size_t normals = 0;
  for (const auto k : instance.keypoints) {
    const auto& keypoint = keypoints[static_cast<std::size_t> (k)];
    footprint.centroid += keypoint.getVector3fMap();
    if (keypoint.getNormalVector3fMap().allFinite()) {
      footprint.normal += keypoint.getNormalVector3fMap();
      ++normals;
    }
  }
  footprint.normal =
      normals > 0 && footprint.normal.norm() >=
                         kMinNormalAgreement * static_cast<float> (normals)
          ? footprint.normal.normalized()
          : Eigen::Vector3f::Zero();
  footprint.centroid /= static_cast<float> (instance.keypoints.size());
  float sum = 0.0f;
  for (const auto k : instance.keypoints)
    sum +=
        (keypoints[static_cast<std::size_t> (k)].getVector3fMap() - footprint.centroid)
            .squaredNorm();
  footprint.radius = std::sqrt (sum / static_cast<float> (instance.keypoints.size()));
  footprint.valid = true;
  return footprint;
}

/** The footprints of a model's instances, in order. */
std::vector<Footprint>
footprintsOf (const KeypointCloud& keypoints, const ModelInstances& instances)
{
  std::vector<Footprint> footprints;
  footprints.reserve (instances.size());
  for (const auto& instance : instances)
    footprints.push_back (footprintOf (keypoints, instance));
  return footprints;
}

/** See instancesOverlap(). */
bool
footprintsOverlap (const Footprint& a, const Footprint& b)
{
  return a.valid && b.valid &&
         (a.centroid - b.centroid).norm() < std::max (a.radius, b.radius);
}

/** See instancesAdjoin(). */
bool
footprintsAdjoin (const Footprint& a, const Footprint& b, float min_angle)
{
  if (!a.valid || !b.valid || a.normal.isZero() || b.normal.isZero())
    return false;
  const float cos_angle = std::clamp (a.normal.dot (b.normal), -1.0f, 1.0f);
  return (a.centroid - b.centroid).norm() < a.radius + b.radius &&
         std::acos (cos_angle) >= min_angle;
}

std::size_t
observations (const ObjectModel& model)
{
  return std::accumulate (model.instances.begin(),
                          model.instances.end(),
                          std::size_t{0},
                          [] (std::size_t sum, const ModelInstance& instance) {
                            return sum + instance.keypoints.size();
                          });
}

/** Pairs (landmark of into, landmark of from) observed by one keypoint of the frame. */
std::vector<std::pair<int, int>>
sameLandmarks (const ObjectModel& into, const ObjectModel& from)
{
  std::map<pcl::index_t, int> into_landmark;
  for (const auto& instance : into.instances)
    for (std::size_t o = 0; o < instance.keypoints.size(); ++o)
      into_landmark.emplace (instance.keypoints[o], instance.landmarks[o]);
  std::map<int, int> same;
  for (const auto& instance : from.instances)
    for (std::size_t o = 0; o < instance.keypoints.size(); ++o) {
      const auto found = into_landmark.find (instance.keypoints[o]);
      if (found != into_landmark.end())
        same.emplace (instance.landmarks[o], found->second);
    }
  std::vector<std::pair<int, int>> pairs;
  pairs.reserve (same.size());
  for (const auto& [l_from, l_into] : same)
    pairs.emplace_back (l_into, l_from);
  return pairs;
}

/** Merge `from` into `into` through one instance pair on one physical copy: an overlapping
  * pair if there is one, else an adjoining one, the one with most observations first; false
  * if no pair overlaps or adjoins. Another instance of `from` joins an instance of `into` that
  * it overlaps or whose pose it takes in `into`'s frame (within max_angle, max_distance).
  */
bool
mergeThroughSharedCopy (const KeypointCloud& keypoints,
                        ObjectModel& into,
                        const ObjectModel& from,
                        float max_angle,
                        float max_distance)
{
  // Footprints depend on the observed keypoints only, which moving an instance into another
  // frame keeps: computed once, before the merge.
  const std::vector<Footprint> into_prints = footprintsOf (keypoints, into.instances),
                               from_prints = footprintsOf (keypoints, from.instances);
  const std::size_t none = from.instances.size(), old_instances = into.instances.size();
  std::size_t link_into = 0, link_from = none;
  std::pair<bool, std::size_t> best_rank (false, 0);
  for (std::size_t i = 0; i < old_instances; ++i)
    for (std::size_t j = 0; j < from.instances.size(); ++j) {
      const std::pair<bool, std::size_t> rank (
          footprintsOverlap (into_prints[i], from_prints[j]),
          into.instances[i].keypoints.size() + from.instances[j].keypoints.size());
      if (rank > best_rank &&
          (rank.first ||
           footprintsAdjoin (into_prints[i], from_prints[j], kAdjoinAngle))) {
        link_into = i;
        link_from = j;
        best_rank = rank;
      }
    }
  if (link_from == none)
    return false;
  // from's frame -> camera -> into's frame.
  const Eigen::Matrix4f from_to_into =
      into.instances[link_into].pose.inverse() * from.instances[link_from].pose;
  const auto same = sameLandmarks (into, from);
  ObjectModel moved_from = from;
  moved_from.instances.clear();
  // The landmarks and descriptors first (no instance), then the instances, each compared with
  // into's instances as they were before the merge (joining keeps their poses).
  std::vector<int> landmark_of;
  mergeModel (into, moved_from, from_to_into.inverse(), same, 0.0f, 0.0f, &landmark_of);
  for (std::size_t j = 0; j < from.instances.size(); ++j) {
    ModelInstance moved = from.instances[j];
    moved.pose = moved.pose * from_to_into.inverse();
    for (auto& l : moved.landmarks)
      l = landmark_of[static_cast<std::size_t> (l)];
    // The linking pair is one copy by definition.
    std::size_t joined = j == link_from ? link_into : old_instances;
    for (std::size_t i = 0; i < old_instances && joined == old_instances; ++i)
      if (footprintsOverlap (into_prints[i], from_prints[j]) ||
          posesCoincide (into.instances[i].pose,
                         moved.pose,
                         Eigen::Vector3f::Zero(),
                         max_angle,
                         max_distance))
        joined = i;
    if (joined < old_instances)
      joinObservations (into.instances[joined], moved);
    else
      into.instances.push_back (moved);
  }
  for (auto& instance : into.instances)
    updateInstanceError (into, keypoints, instance);
  return true;
}

} // namespace

bool
instancesOverlap (const KeypointCloud& keypoints,
                  const ModelInstance& a,
                  const ModelInstance& b)
{
  return footprintsOverlap (footprintOf (keypoints, a), footprintOf (keypoints, b));
}

bool
instancesAdjoin (const KeypointCloud& keypoints,
                 const ModelInstance& a,
                 const ModelInstance& b,
                 float min_angle)
{
  return footprintsAdjoin (
      footprintOf (keypoints, a), footprintOf (keypoints, b), min_angle);
}

std::size_t
removeOverlappingInstances (const KeypointCloud& keypoints, ObjectModel& model)
{
  std::vector<std::size_t> order (model.instances.size());
  std::iota (order.begin(), order.end(), std::size_t{0});
  std::stable_sort (
      order.begin(), order.end(), [&model] (std::size_t i, std::size_t j) {
        return model.instances[i].keypoints.size() >
               model.instances[j].keypoints.size();
      });
  const std::vector<Footprint> prints = footprintsOf (keypoints, model.instances);
  std::vector<bool> removed (model.instances.size(), false);
  for (std::size_t i = 0; i < order.size(); ++i)
    if (!removed[order[i]])
      for (std::size_t j = i + 1; j < order.size(); ++j)
        if (!removed[order[j]] &&
            footprintsOverlap (prints[order[i]], prints[order[j]]))
          removed[order[j]] = true;
  ModelInstances kept;
  for (std::size_t i = 0; i < model.instances.size(); ++i)
    if (!removed[i])
      kept.push_back (model.instances[i]);
  const std::size_t count = model.instances.size() - kept.size();
  model.instances.swap (kept);
  return count;
}

std::size_t
mergeOverlappingModels (const KeypointCloud& keypoints,
                        ObjectModels& models,
                        float max_angle,
                        float max_distance)
{
  std::stable_sort (
      models.begin(), models.end(), [] (const ObjectModel& a, const ObjectModel& b) {
        return observations (a) > observations (b);
      });
  std::size_t merged = 0;
  for (std::size_t i = 0; i < models.size(); ++i)
    for (std::size_t j = i + 1; j < models.size();) {
      if (mergeThroughSharedCopy (
              keypoints, models[i], models[j], max_angle, max_distance)) {
        models.erase (models.begin() + static_cast<std::ptrdiff_t> (j));
        ++merged;
      }
      else
        ++j;
    }
  return merged;
}

} // namespace mid
