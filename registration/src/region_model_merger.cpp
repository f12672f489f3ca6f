#include <mid/registration/landmark_box.h>
#include <mid/registration/model_merging.h>
#include <mid/registration/model_refinement.h>
#include <mid/registration/region_model_merger.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <limits>
#include <vector>

namespace mid {

namespace {

/** For each keypoint, the instance whose region holds it, numbered over all models in order,
  * or -1. A keypoint an instance observes is in that instance's region. Any other keypoint is
  * in the region of the instance whose landmark box (boxes[m] of its model, placed by its pose)
  * lies nearest to it, if that box lies within `margin`; in no region on a tie. So regions are
  * disjoint, and the free keypoints between two touching copies go to the nearer one.
  */
std::vector<int>
regionOwners (const KeypointCloud& frame,
              const ObjectModels& models,
              const std::vector<LandmarkBox>& boxes,
              float margin)
{
  std::vector<int> owner (frame.size(), -1);
  std::vector<float> nearest (frame.size(), std::numeric_limits<float>::infinity());
  std::vector<bool> observed (frame.size(), false);
  int id = 0;
  for (const auto& model : models)
    for (const auto& instance : model.instances) {
      for (const auto k : instance.keypoints) {
        owner[static_cast<std::size_t> (k)] = id;
        observed[static_cast<std::size_t> (k)] = true;
      }
      ++id;
    }
  id = 0;
  for (std::size_t m = 0; m < models.size(); ++m)
    for (const auto& instance : models[m].instances) {
      const Eigen::Matrix4f to_model = instance.pose.inverse();
      for (std::size_t k = 0; k < frame.size(); ++k) {
        if (observed[k])
          continue;
        const float distance = boxes[m].distanceTo (to_model.topLeftCorner<3, 3>() *
                                                        frame[k].getVector3fMap() +
                                                    to_model.topRightCorner<3, 1>());
        if (distance > margin || distance > nearest[k])
          continue;
        owner[k] = distance < nearest[k] ? id : -1;
        nearest[k] = distance;
      }
      ++id;
    }
  return owner;
}

/** The number of the first instance of models[m] in regionOwners(). */
int
firstInstanceId (const ObjectModels& models, std::size_t m)
{
  int id = 0;
  for (std::size_t n = 0; n < m; ++n)
    id += static_cast<int> (models[n].instances.size());
  return id;
}

/** The keypoints in the region of instance `id` (sorted). */
pcl::Indices
regionOf (const std::vector<int>& owner, int id)
{
  pcl::Indices region;
  for (std::size_t k = 0; k < owner.size(); ++k)
    if (owner[k] == id)
      region.push_back (static_cast<pcl::index_t> (k));
  return region;
}

/** The keypoints of a region as a model in the frame of the instance at `pose`: one landmark
  * and one descriptor per keypoint.
  */
ObjectModel
regionModel (const KeypointCloud& frame,
             const SIFTDescriptorCloud& descriptors,
             const pcl::Indices& region,
             const Eigen::Matrix4f& pose)
{
  ObjectModel model;
  const Eigen::Matrix4f to_model = pose.inverse();
  for (const auto k : region) {
    pcl::PointNormal point = frame[static_cast<std::size_t> (k)];
    point.getVector3fMap() = to_model.topLeftCorner<3, 3>() * point.getVector3fMap() +
                             to_model.topRightCorner<3, 1>();
    point.getNormalVector3fMap() =
        to_model.topLeftCorner<3, 3>() * point.getNormalVector3fMap();
    model.descriptor_landmarks.push_back (static_cast<int> (model.landmarks.size()));
    model.landmarks.push_back (point);
    model.descriptors.push_back (descriptors[static_cast<std::size_t> (k)]);
  }
  updateModelDiameter (model);
  return model;
}

} // namespace

RegionModelMerger::PairOutcome
RegionModelMerger::mergePair (ObjectModels& models, std::size_t i, std::size_t j) const
{
  std::vector<LandmarkBox> boxes;
  for (const auto& model : models)
    boxes.push_back (computeLandmarkBox (model));
  if (!boxes[i].valid || !boxes[j].valid)
    return PairOutcome::apart;
  const std::vector<int> owner = regionOwners (*keypoints_, models, boxes, margin_);
  const int first_i = firstInstanceId (models, i),
            first_j = firstInstanceId (models, j);
  for (std::size_t a = 0; a < models[i].instances.size(); ++a) {
    const pcl::Indices region_a = regionOf (owner, first_i + static_cast<int> (a));
    if (region_a.size() < 3)
      continue;
    ModelInstanceDetector detector = detector_;
    detector.setModel (std::make_shared<const ObjectModel> (regionModel (
        *keypoints_, *descriptors_, region_a, models[i].instances[a].pose)));
    detector.setInputKeypoints (keypoints_);
    detector.setInputDescriptors (descriptors_);
    detector.setMaxInstances (1);
    for (std::size_t b = 0; b < models[j].instances.size(); ++b) {
      auto region_b = pcl::make_shared<pcl::Indices> (
          regionOf (owner, first_j + static_cast<int> (b)));
      if (region_b->size() < 3)
        continue;
      detector.setCandidates (region_b);
      ModelInstances found;
      if (!detector.detect (found))
        return PairOutcome::failed;
      if (found.empty())
        continue;
      // found.pose maps i's frame onto the copy of b, whose pose maps j's frame there.
      const Eigen::Matrix4f into_to_from =
          models[j].instances[b].pose.inverse() * found.front().pose;
      mergeModel (models[i], models[j], into_to_from, {}, max_angle_, max_distance_);
      refineModel (models[i], *keypoints_, refinement_iterations_);
      return PairOutcome::merged;
    }
  }
  return PairOutcome::apart;
}

bool
RegionModelMerger::mergeChecked (ObjectModels& models, std::size_t& merged) const
{
  for (std::size_t i = 0; i < models.size(); ++i)
    for (std::size_t j = i + 1; j < models.size();) {
      const PairOutcome outcome = mergePair (models, i, j);
      if (outcome == PairOutcome::failed)
        return false;
      if (outcome == PairOutcome::apart) {
        ++j;
        continue;
      }
      models.erase (models.begin() + static_cast<std::ptrdiff_t> (j));
      ++merged;
    }
  return true;
}

bool
RegionModelMerger::merge (ObjectModels& models)
{
  merged_ = 0;
  const char* name = "[mid::RegionModelMerger::merge]";
  if (!keypoints_ || !descriptors_ || keypoints_->size() != descriptors_->size()) {
    PCL_ERROR (
        "%s Keypoints and descriptors must be set and pair up (%zu keypoints, %zu "
        "descriptors).\n",
        name,
        keypoints_ ? keypoints_->size() : std::size_t{0},
        descriptors_ ? descriptors_->size() : std::size_t{0});
    return false;
  }
  if (!(margin_ >= 0.0f) || !std::isfinite (margin_) || !(max_angle_ >= 0.0f) ||
      !(max_distance_ >= 0.0f) || refinement_iterations_ < 0) {
    PCL_ERROR (
        "%s Invalid parameter: region margin %g (finite, >= 0), duplicate angle %g "
        "and distance %g (>= 0), refinement iterations %d (>= 0).\n",
        name,
        static_cast<double> (margin_),
        static_cast<double> (max_angle_),
        static_cast<double> (max_distance_),
        refinement_iterations_);
    return false;
  }
  for (const auto& model : models)
    for (const auto& instance : model.instances)
      for (const auto k : instance.keypoints)
        if (k < 0 || static_cast<std::size_t> (k) >= keypoints_->size()) {
          PCL_ERROR ("%s An instance observes keypoint %d; the frame has %zu.\n",
                     name,
                     k,
                     keypoints_->size());
          return false;
        }
  ObjectModels merged = models;
  std::size_t count = 0;
  if (!mergeChecked (merged, count))
    return false;
  merged_ = count;
  models.swap (merged);
  return true;
}

} // namespace mid
