#include <mid/registration/object_model.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>
#include <utility>

namespace mid {

std::string
observationProblem (const ObjectModel& model, std::size_t keypoints)
{
  for (const auto& instance : model.instances) {
    if (instance.keypoints.size() != instance.landmarks.size())
      return "an instance's keypoints and landmarks differ in number";
    for (std::size_t o = 0; o < instance.keypoints.size(); ++o)
      if (instance.keypoints[o] < 0 ||
          static_cast<std::size_t> (instance.keypoints[o]) >= keypoints ||
          instance.landmarks[o] < 0 ||
          static_cast<std::size_t> (instance.landmarks[o]) >= model.landmarks.size())
        return "an observation lies outside the keypoints or the landmarks";
  }
  return {};
}

std::string
descriptorProblem (const ObjectModel& model)
{
  if (model.descriptors.size() != model.descriptor_landmarks.size() ||
      !std::all_of (model.descriptor_landmarks.begin(),
                    model.descriptor_landmarks.end(),
                    [&model] (int l) {
                      return l >= 0 &&
                             static_cast<std::size_t> (l) < model.landmarks.size();
                    }))
    return "every model descriptor must describe a landmark of the model";
  return {};
}

std::vector<int>
sharedLandmarkGroups (const ObjectModel& model)
{
  const std::size_t n = model.instances.size();
  std::vector<std::size_t> parent (n);
  std::iota (parent.begin(), parent.end(), std::size_t{0});
  const auto root = [&parent] (std::size_t i) {
    while (parent[i] != i)
      i = parent[i] = parent[parent[i]];
    return i;
  };
  std::vector<int> first_observer (model.landmarks.size(), -1);
  for (std::size_t i = 0; i < n; ++i)
    for (const int l : model.instances[i].landmarks) {
      if (l < 0 || static_cast<std::size_t> (l) >= first_observer.size())
        continue;
      auto& first = first_observer[static_cast<std::size_t> (l)];
      if (first < 0)
        first = static_cast<int> (i);
      else
        parent[root (i)] = root (static_cast<std::size_t> (first));
    }
  std::vector<int> group (n, -1), group_of_root (n, -1);
  int groups = 0;
  for (std::size_t i = 0; i < n; ++i) {
    int& g = group_of_root[root (i)];
    if (g < 0)
      g = groups++;
    group[i] = g;
  }
  return group;
}

void
updateInstanceError (const ObjectModel& model,
                     const KeypointCloud& keypoints,
                     ModelInstance& instance)
{
  if (instance.keypoints.empty()) {
    instance.rms_error = 0.0f;
    return;
  }
  const Eigen::Matrix3f rotation = instance.pose.topLeftCorner<3, 3>();
  const Eigen::Vector3f translation = instance.pose.topRightCorner<3, 1>();
  float sum = 0.0f;
  for (std::size_t o = 0; o < instance.keypoints.size(); ++o) {
    const Eigen::Vector3f landmark =
        model.landmarks[static_cast<std::size_t> (instance.landmarks[o])]
            .getVector3fMap();
    const Eigen::Vector3f observed =
        keypoints[static_cast<std::size_t> (instance.keypoints[o])].getVector3fMap();
    sum += (rotation * landmark + translation - observed).squaredNorm();
  }
  instance.rms_error = std::sqrt (sum / static_cast<float> (instance.keypoints.size()));
}

void
joinObservations (ModelInstance& target, const ModelInstance& extra)
{
  const std::set<pcl::index_t> seen (target.keypoints.begin(), target.keypoints.end());
  for (std::size_t o = 0; o < extra.keypoints.size(); ++o)
    if (seen.count (extra.keypoints[o]) == 0) {
      target.keypoints.push_back (extra.keypoints[o]);
      target.landmarks.push_back (extra.landmarks[o]);
    }
}

bool
posesCoincide (const Eigen::Matrix4f& a,
               const Eigen::Matrix4f& b,
               const Eigen::Vector3f& center,
               float max_angle,
               float max_distance)
{
  const Eigen::Matrix3f relative =
      a.topLeftCorner<3, 3>().transpose() * b.topLeftCorner<3, 3>();
  const float angle = Eigen::AngleAxisf (relative).angle();
  const Eigen::Vector3f pa =
      a.topLeftCorner<3, 3>() * center + a.topRightCorner<3, 1>();
  const Eigen::Vector3f pb =
      b.topLeftCorner<3, 3>() * center + b.topRightCorner<3, 1>();
  return angle < max_angle && (pa - pb).norm() < max_distance;
}

void
extractModelPart (const ObjectModel& model,
                  const std::vector<std::size_t>& instances,
                  ObjectModel& part)
{
  std::vector<int> renumbered (model.landmarks.size(), -1);
  part = ObjectModel();
  for (const std::size_t i : instances) {
    ModelInstance instance = model.instances[i];
    for (int& l : instance.landmarks) {
      int& to = renumbered[static_cast<std::size_t> (l)];
      if (to < 0) {
        to = static_cast<int> (part.landmarks.size());
        part.landmarks.push_back (model.landmarks[static_cast<std::size_t> (l)]);
      }
      l = to;
    }
    part.instances.push_back (std::move (instance));
  }
  for (std::size_t d = 0; d < model.descriptors.size(); ++d) {
    const int to = renumbered[static_cast<std::size_t> (model.descriptor_landmarks[d])];
    if (to < 0)
      continue;
    part.descriptors.push_back (model.descriptors[d]);
    part.descriptor_landmarks.push_back (to);
  }
  updateModelDiameter (part);
}

void
removeLandmarks (const std::vector<bool>& remove, ObjectModel& model)
{
  std::vector<int> renumbered (model.landmarks.size(), -1);
  KeypointCloud landmarks;
  for (std::size_t l = 0; l < model.landmarks.size(); ++l)
    if (!remove[l]) {
      renumbered[l] = static_cast<int> (landmarks.size());
      landmarks.push_back (model.landmarks[l]);
    }
  SIFTDescriptorCloud descriptors;
  std::vector<int> descriptor_landmarks;
  for (std::size_t d = 0; d < model.descriptors.size(); ++d) {
    const int l = renumbered[static_cast<std::size_t> (model.descriptor_landmarks[d])];
    if (l >= 0) {
      descriptors.push_back (model.descriptors[d]);
      descriptor_landmarks.push_back (l);
    }
  }
  for (auto& instance : model.instances)
    for (auto& l : instance.landmarks)
      l = renumbered[static_cast<std::size_t> (l)];
  model.landmarks = landmarks;
  model.descriptors = descriptors;
  model.descriptor_landmarks = descriptor_landmarks;
}

void
updateModelDiameter (ObjectModel& model)
{
  float diameter = 0.0f;
  for (std::size_t i = 0; i < model.landmarks.size(); ++i)
    for (std::size_t j = i + 1; j < model.landmarks.size(); ++j)
      diameter = std::max (
          diameter,
          (model.landmarks[i].getVector3fMap() - model.landmarks[j].getVector3fMap())
              .norm());
  model.diameter = diameter;
}

Eigen::Vector3f
landmarkCentroid (const ObjectModel& model)
{
  Eigen::Vector3f centroid = Eigen::Vector3f::Zero();
  for (const auto& l : model.landmarks)
    centroid += l.getVector3fMap();
  if (!model.landmarks.empty())
    centroid /= static_cast<float> (model.landmarks.size());
  return centroid;
}

void
centerModelFrame (ObjectModel& model)
{
  if (model.landmarks.empty())
    return;
  const Eigen::Vector3f centroid = landmarkCentroid (model);
  for (auto& l : model.landmarks)
    l.getVector3fMap() -= centroid;
  for (auto& instance : model.instances)
    instance.pose.topRightCorner<3, 1>() +=
        instance.pose.topLeftCorner<3, 3>() * centroid;
}

void
addInstanceOfKeypoints (const KeypointCloud& keypoints,
                        const SIFTDescriptorCloud& descriptors,
                        const pcl::Indices& observed,
                        const Eigen::Matrix4f& pose,
                        ObjectModel& model)
{
  const Eigen::Matrix4f camera_to_model = pose.inverse();
  ModelInstance instance;
  instance.pose = pose;
  for (const auto k : observed) {
    const auto& keypoint = keypoints[static_cast<std::size_t> (k)];
    pcl::PointNormal landmark = keypoint;
    landmark.getVector3fMap() =
        camera_to_model.topLeftCorner<3, 3>() * keypoint.getVector3fMap() +
        camera_to_model.topRightCorner<3, 1>();
    landmark.getNormalVector3fMap() =
        camera_to_model.topLeftCorner<3, 3>() * keypoint.getNormalVector3fMap();
    const auto index = static_cast<int> (model.landmarks.size());
    model.landmarks.push_back (landmark);
    model.descriptors.push_back (descriptors[static_cast<std::size_t> (k)]);
    model.descriptor_landmarks.push_back (index);
    instance.keypoints.push_back (k);
    instance.landmarks.push_back (index);
  }
  updateInstanceError (model, keypoints, instance);
  model.instances.push_back (instance);
  updateModelDiameter (model);
}

ObjectModel
modelOfKeypoints (const KeypointCloud& keypoints,
                  const SIFTDescriptorCloud& descriptors,
                  const pcl::Indices& observed)
{
  ObjectModel model;
  if (observed.empty())
    return model;
  addInstanceOfKeypoints (
      keypoints, descriptors, observed, Eigen::Matrix4f::Identity(), model);
  centerModelFrame (model);
  return model;
}

std::size_t
removeInstances (const std::vector<std::vector<bool>>& remove, ObjectModels& models)
{
  std::size_t removed = 0;
  for (std::size_t m = 0; m < models.size() && m < remove.size(); ++m) {
    auto& instances = models[m].instances;
    ModelInstances kept;
    for (std::size_t i = 0; i < instances.size(); ++i)
      if (i >= remove[m].size() || !remove[m][i])
        kept.push_back (instances[i]);
    if (kept.size() < 2 && kept.size() < instances.size())
      kept.clear();
    removed += instances.size() - kept.size();
    instances.swap (kept);
  }
  models.erase (std::remove_if (
                    models.begin(),
                    models.end(),
                    [] (const ObjectModel& model) { return model.instances.empty(); }),
                models.end());
  return removed;
}

bool
isModelBox (const ModelSize& box)
{
  const Eigen::Matrix3f rotation = box.box_in_model.topLeftCorner<3, 3>();
  return box.size.allFinite() && box.size.x() > 0.0f && box.size.x() <= box.size.y() &&
         box.size.y() <= box.size.z() && box.agreeing >= 1 &&
         box.box_in_model.allFinite() &&
         box.box_in_model.row (3) == Eigen::RowVector4f (0.0f, 0.0f, 0.0f, 1.0f) &&
         (rotation.transpose() * rotation).isIdentity (1e-3f) &&
         rotation.determinant() > 0.0f;
}

} // namespace mid
