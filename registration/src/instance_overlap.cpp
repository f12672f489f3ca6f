#include <mid/registration/instance_overlap.h>
#include <mid/registration/model_merging.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <utility>

namespace mid {

namespace {

/** Centroid, RMS radius and mean normal (unit, zero if the normals cancel out) of an
  * instance's observed keypoints.
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
  for (const auto k : instance.keypoints) {
    footprint.centroid += keypoints[static_cast<std::size_t> (k)].getVector3fMap();
    footprint.normal += keypoints[static_cast<std::size_t> (k)].getNormalVector3fMap();
  }
  footprint.normal = footprint.normal.norm() > 1e-3f ? footprint.normal.normalized()
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

/** Join `extra`'s observations (landmarks already in `target`'s model) to `target`. */
void
joinInstance (ModelInstance& target, const ModelInstance& extra)
{
  for (std::size_t o = 0; o < extra.keypoints.size(); ++o)
    if (std::find (target.keypoints.begin(),
                   target.keypoints.end(),
                   extra.keypoints[o]) == target.keypoints.end()) {
      target.keypoints.push_back (extra.keypoints[o]);
      target.landmarks.push_back (extra.landmarks[o]);
    }
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
  * if no pair overlaps or adjoins.
  */
bool
mergeThroughSharedCopy (const KeypointCloud& keypoints,
                        ObjectModel& into,
                        const ObjectModel& from)
{
  const ModelInstance* best_into = nullptr;
  const ModelInstance* best_from = nullptr;
  std::pair<bool, std::size_t> best_rank (false, 0);
  for (const auto& a : into.instances)
    for (const auto& b : from.instances) {
      const std::pair<bool, std::size_t> rank (instancesOverlap (keypoints, a, b),
                                               a.keypoints.size() + b.keypoints.size());
      if (rank > best_rank && (rank.first || instancesAdjoin (keypoints, a, b))) {
        best_into = &a;
        best_from = &b;
        best_rank = rank;
      }
    }
  if (!best_into)
    return false;
  const auto linked = static_cast<std::ptrdiff_t> (best_into - into.instances.data());
  // from's frame -> camera -> into's frame.
  const Eigen::Matrix4f from_to_into = best_into->pose.inverse() * best_from->pose;
  const auto same = sameLandmarks (into, from);
  ObjectModel moved_from = from;
  moved_from.instances.clear();
  const std::size_t old_instances = into.instances.size();
  // The landmarks and descriptors first (no instance), then the instances, by overlap.
  std::vector<int> landmark_of;
  mergeModel (into, moved_from, from_to_into.inverse(), same, 0.0f, 0.0f, &landmark_of);
  for (const auto& b : from.instances) {
    ModelInstance moved = b;
    moved.pose = b.pose * from_to_into.inverse();
    for (auto& l : moved.landmarks)
      l = landmark_of[static_cast<std::size_t> (l)];
    // The linking pair is one copy by definition; any other instance joins one it overlaps.
    auto joined = &b == best_from
                      ? into.instances.begin() + linked
                      : std::find_if (into.instances.begin(),
                                      into.instances.begin() +
                                          static_cast<std::ptrdiff_t> (old_instances),
                                      [&] (const ModelInstance& a) {
                                        return instancesOverlap (keypoints, a, moved);
                                      });
    if (joined != into.instances.begin() + static_cast<std::ptrdiff_t> (old_instances))
      joinInstance (*joined, moved);
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
  const Footprint fa = footprintOf (keypoints, a), fb = footprintOf (keypoints, b);
  if (!fa.valid || !fb.valid)
    return false;
  return (fa.centroid - fb.centroid).norm() < std::max (fa.radius, fb.radius);
}

bool
instancesAdjoin (const KeypointCloud& keypoints,
                 const ModelInstance& a,
                 const ModelInstance& b,
                 float min_angle)
{
  const Footprint fa = footprintOf (keypoints, a), fb = footprintOf (keypoints, b);
  if (!fa.valid || !fb.valid || fa.normal.isZero() || fb.normal.isZero())
    return false;
  const float cos_angle = std::clamp (fa.normal.dot (fb.normal), -1.0f, 1.0f);
  return (fa.centroid - fb.centroid).norm() < fa.radius + fb.radius &&
         std::acos (cos_angle) >= min_angle;
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
  std::vector<bool> removed (model.instances.size(), false);
  for (std::size_t i = 0; i < order.size(); ++i)
    if (!removed[order[i]])
      for (std::size_t j = i + 1; j < order.size(); ++j)
        if (!removed[order[j]] && instancesOverlap (keypoints,
                                                    model.instances[order[i]],
                                                    model.instances[order[j]]))
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
mergeOverlappingModels (const KeypointCloud& keypoints, ObjectModels& models)
{
  std::stable_sort (
      models.begin(), models.end(), [] (const ObjectModel& a, const ObjectModel& b) {
        return observations (a) > observations (b);
      });
  std::size_t merged = 0;
  for (std::size_t i = 0; i < models.size(); ++i)
    for (std::size_t j = i + 1; j < models.size();) {
      if (mergeThroughSharedCopy (keypoints, models[i], models[j])) {
        models.erase (models.begin() + static_cast<std::ptrdiff_t> (j));
        ++merged;
      }
      else
        ++j;
    }
  return merged;
}

} // namespace mid
