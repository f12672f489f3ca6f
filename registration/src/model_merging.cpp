#include <mid/registration/model_merging.h>

#include <map>

namespace mid {

namespace {

/** Add an instance, or join it to the existing instance whose pose coincides with it. */
void
addOrJoin (ObjectModel& model,
           const ModelInstance& instance,
           float max_angle,
           float max_distance)
{
  const Eigen::Vector3f center = Eigen::Vector3f::Zero();
  for (auto& existing : model.instances)
    if (posesCoincide (existing.pose, instance.pose, center, max_angle, max_distance)) {
      joinObservations (existing, instance);
      return;
    }
  model.instances.push_back (instance);
}

} // namespace

void
mergeModel (ObjectModel& into,
            const ObjectModel& from,
            const Eigen::Matrix4f& into_to_from,
            const std::vector<std::pair<int, int>>& same_landmarks,
            float max_angle,
            float max_distance,
            std::vector<int>* landmark_map)
{
  const Eigen::Matrix4f from_to_into = into_to_from.inverse();
  std::map<int, int> landmark_of;
  for (const auto& [l_into, l_from] : same_landmarks)
    landmark_of.emplace (l_from, l_into);
  for (std::size_t l = 0; l < from.landmarks.size(); ++l) {
    if (landmark_of.count (static_cast<int> (l)) > 0)
      continue;
    pcl::PointNormal moved = from.landmarks[l];
    moved.getVector3fMap() =
        from_to_into.topLeftCorner<3, 3>() * from.landmarks[l].getVector3fMap() +
        from_to_into.topRightCorner<3, 1>();
    moved.getNormalVector3fMap() =
        from_to_into.topLeftCorner<3, 3>() * from.landmarks[l].getNormalVector3fMap();
    landmark_of[static_cast<int> (l)] = static_cast<int> (into.landmarks.size());
    into.landmarks.push_back (moved);
  }
  for (std::size_t d = 0; d < from.descriptors.size(); ++d) {
    into.descriptors.push_back (from.descriptors[d]);
    into.descriptor_landmarks.push_back (landmark_of.at (from.descriptor_landmarks[d]));
  }
  for (const auto& instance : from.instances) {
    ModelInstance moved = instance;
    moved.pose = instance.pose * into_to_from;
    for (auto& l : moved.landmarks)
      l = landmark_of.at (l);
    addOrJoin (into, moved, max_angle, max_distance);
  }
  updateModelDiameter (into);
  if (landmark_map) {
    landmark_map->assign (from.landmarks.size(), -1);
    for (const auto& [l_from, l_into] : landmark_of)
      if (l_from >= 0 && static_cast<std::size_t> (l_from) < from.landmarks.size())
        (*landmark_map)[static_cast<std::size_t> (l_from)] = l_into;
  }
}

void
addInstance (ObjectModel& model,
             const ModelInstance& instance,
             const SIFTDescriptorCloud& frame_descriptors,
             float max_angle,
             float max_distance)
{
  for (std::size_t o = 0; o < instance.keypoints.size(); ++o) {
    model.descriptors.push_back (
        frame_descriptors[static_cast<std::size_t> (instance.keypoints[o])]);
    model.descriptor_landmarks.push_back (instance.landmarks[o]);
  }
  addOrJoin (model, instance, max_angle, max_distance);
}

} // namespace mid
