#include <mid/segmentation/model_box_extension.h>

#include <Eigen/Geometry>
#include <pcl/console/print.h>

#include <cmath>
#include <limits>
#include <string>

namespace mid {

namespace {

/** Where a keypoint goes: the instance whose grown box holds it deepest. */
struct Owner
{
  std::size_t model = 0, instance = 0;
  /** The largest of the keypoint's distances outside the box's faces (negative inside). */
  float depth = std::numeric_limits<float>::infinity();
};

/** The box of every instance of a model with a size, grown by `margin`, as camera -> box
  * transforms and the box's half edges; an empty list for a model without a size.
  */
struct PlacedBoxes
{
  std::vector<Eigen::Affine3f, Eigen::aligned_allocator<Eigen::Affine3f>> to_box;
  std::vector<std::size_t> instance;
  Eigen::Vector3f half = Eigen::Vector3f::Zero();

  EIGEN_MAKE_ALIGNED_OPERATOR_NEW
};

PlacedBoxes
placeBoxes (const ObjectModel& model, const ModelSize& size, float margin)
{
  PlacedBoxes boxes;
  if (!size.valid)
    return boxes;
  boxes.half = 0.5f * size.size + Eigen::Vector3f::Constant (margin);
  for (std::size_t i = 0; i < model.instances.size(); ++i) {
    const Eigen::Matrix4f box_to_camera = model.instances[i].pose * size.box_in_model;
    if (!box_to_camera.allFinite())
      continue;
    boxes.to_box.emplace_back (box_to_camera.inverse());
    boxes.instance.push_back (i);
  }
  return boxes;
}

} // namespace

bool
ModelBoxExtender::extend (ObjectModels& models, ModelExtension& extension) const
{
  extension = ModelExtension();
  std::string problem = measurementProblem (models);
  if (problem.empty() && (!descriptors_ || descriptors_->size() != keypoints_->size()))
    problem = "the descriptors are not one per keypoint";
  if (problem.empty() && !(margin_ >= 0.0f && std::isfinite (margin_)))
    problem = "the margin must be >= 0 (" + std::to_string (margin_) + ")";
  if (problem.empty() && !known_sizes_.empty() && known_sizes_.size() != models.size())
    problem = "the known sizes are not one per model (" +
              std::to_string (known_sizes_.size()) + " for " +
              std::to_string (models.size()) + " models)";
  for (std::size_t m = 0; problem.empty() && m < known_sizes_.size(); ++m)
    if (known_sizes_[m].valid && !isModelBox (known_sizes_[m]))
      problem = "the known size of model " + std::to_string (m) + " is no box (" +
                MODEL_BOX_RULE + ")";
  if (!problem.empty()) {
    PCL_ERROR ("[mid::ModelBoxExtender::extend] %s.\n", problem.c_str());
    return false;
  }
  extension.observations.resize (models.size());
  for (const auto& model : models)
    extension.landmarks_before.push_back (model.landmarks.size());
  Eigen::Vector4f plane;
  if (models.empty() || !fitPlane (plane))
    return true;
  ModelSizes sizes = known_sizes_;
  if (sizes.empty() && !measureSizes (models, plane, sizes)) {
    extension = ModelExtension();
    return false;
  }
  std::vector<PlacedBoxes, Eigen::aligned_allocator<PlacedBoxes>> boxes;
  for (std::size_t m = 0; m < models.size(); ++m)
    boxes.push_back (placeBoxes (models[m], sizes[m], margin_));

  const KeypointCloud& keypoints = *keypoints_;
  std::vector<bool> observed (keypoints.size(), false);
  for (const auto& model : models)
    for (const auto& instance : model.instances)
      for (const auto k : instance.keypoints)
        observed[static_cast<std::size_t> (k)] = true;
  for (std::size_t k = 0; k < keypoints.size(); ++k) {
    const Eigen::Vector3f point = keypoints[k].getVector3fMap();
    if (observed[k] || !point.allFinite() ||
        std::abs (planeDistance (plane, point)) <= plane_tolerance_)
      continue;
    Owner owner;
    for (std::size_t m = 0; m < models.size(); ++m)
      for (std::size_t b = 0; b < boxes[m].to_box.size(); ++b) {
        const float depth =
            ((boxes[m].to_box[b] * point).cwiseAbs() - boxes[m].half).maxCoeff();
        if (depth <= 0.0f && depth < owner.depth)
          owner = {m, boxes[m].instance[b], depth};
      }
    if (!std::isfinite (owner.depth))
      continue;
    ObjectModel& model = models[owner.model];
    ModelInstance& instance = model.instances[owner.instance];
    const Eigen::Affine3f to_model (instance.pose.inverse());
    pcl::PointNormal landmark = keypoints[k];
    landmark.getVector3fMap() = to_model * point;
    landmark.getNormalVector3fMap() =
        to_model.linear() * keypoints[k].getNormalVector3fMap();
    const auto index = static_cast<int> (model.landmarks.size());
    model.landmarks.push_back (landmark);
    model.descriptors.push_back ((*descriptors_)[k]);
    model.descriptor_landmarks.push_back (index);
    instance.keypoints.push_back (static_cast<pcl::index_t> (k));
    instance.landmarks.push_back (index);
    extension.observations[owner.model].emplace_back (owner.instance,
                                                      static_cast<pcl::index_t> (k));
  }
  for (auto& model : models)
    updateModelDiameter (model);
  return true;
}

bool
retractModelExtension (const ModelExtension& extension, ObjectModels& models)
{
  bool fits = extension.landmarks_before.size() == models.size() &&
              extension.observations.size() == models.size();
  for (std::size_t m = 0; fits && m < models.size(); ++m) {
    // The keypoints are not known here: only their indices' sign is checked.
    fits =
        extension.landmarks_before[m] <= models[m].landmarks.size() &&
        observationProblem (models[m], std::numeric_limits<std::size_t>::max()).empty();
    for (const auto& [i, k] : extension.observations[m])
      fits = fits && i < models[m].instances.size();
  }
  if (!fits) {
    PCL_ERROR (
        "[mid::retractModelExtension] The extension does not fit the %zu models "
        "(another list of models, models changed otherwise since, or observations "
        "of missing landmarks).\n",
        models.size());
    return false;
  }
  for (std::size_t m = 0; m < models.size(); ++m) {
    ObjectModel& model = models[m];
    const auto before = static_cast<int> (extension.landmarks_before[m]);
    for (const auto& [i, k] : extension.observations[m]) {
      ModelInstance& instance = model.instances[i];
      for (std::size_t o = 0; o < instance.keypoints.size(); ++o)
        if (instance.keypoints[o] == k && instance.landmarks[o] >= before) {
          instance.keypoints.erase (instance.keypoints.begin() +
                                    static_cast<std::ptrdiff_t> (o));
          instance.landmarks.erase (instance.landmarks.begin() +
                                    static_cast<std::ptrdiff_t> (o));
          break;
        }
    }
    std::vector<bool> seen (model.landmarks.size(), false);
    for (const auto& instance : model.instances)
      for (const int l : instance.landmarks)
        seen[static_cast<std::size_t> (l)] = true;
    std::vector<bool> remove (model.landmarks.size(), false);
    for (std::size_t l = extension.landmarks_before[m]; l < remove.size(); ++l)
      remove[l] = !seen[l];
    removeLandmarks (remove, model);
    updateModelDiameter (model);
  }
  return true;
}

} // namespace mid
