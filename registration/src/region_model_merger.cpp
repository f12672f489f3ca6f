#include <mid/registration/instance_region.h>
#include <mid/registration/model_merging.h>
#include <mid/registration/model_refinement.h>
#include <mid/registration/region_model_merger.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace mid {

namespace {

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

/** The pairs the search matched between the copy of `region` (the region model's landmarks are
  * its keypoints, in order) and another copy, found at `found`, as a cluster linking the
  * first copy, at `pose`, to the second.
  */
TripletCluster
copyLink (const pcl::Indices& region,
          const Eigen::Matrix4f& pose,
          const ModelInstance& found)
{
  TripletCluster link;
  for (std::size_t o = 0; o < found.keypoints.size(); ++o) {
    const pcl::index_t source = region[static_cast<std::size_t> (found.landmarks[o])];
    link.correspondences.emplace_back (source, found.keypoints[o], 0.0f);
    link.source_indices.push_back (source);
    link.target_indices.push_back (found.keypoints[o]);
  }
  const auto sort_unique = [] (pcl::Indices& indices) {
    std::sort (indices.begin(), indices.end());
    indices.erase (std::unique (indices.begin(), indices.end()), indices.end());
  };
  sort_unique (link.source_indices);
  sort_unique (link.target_indices);
  link.transformation = found.pose * pose.inverse();
  link.rms_error = found.rms_error;
  return link;
}

} // namespace

RegionModelMerger::PairOutcome
RegionModelMerger::mergePair (ObjectModels& models,
                              const std::vector<std::vector<pcl::Indices>>& regions,
                              std::size_t i,
                              std::size_t j,
                              std::size_t& refused) const
{
  for (std::size_t a = 0; a < models[i].instances.size(); ++a) {
    if (regions[i][a].size() < 3)
      continue;
    ModelInstanceDetector detector = detector_;
    detector.setModel (std::make_shared<const ObjectModel> (regionModel (
        *keypoints_, *descriptors_, regions[i][a], models[i].instances[a].pose)));
    detector.setInputKeypoints (keypoints_);
    detector.setInputDescriptors (descriptors_);
    detector.setMaxInstances (1);
    for (std::size_t b = 0; b < models[j].instances.size(); ++b) {
      if (regions[j][b].size() < 3)
        continue;
      detector.setCandidates (pcl::make_shared<const pcl::Indices> (regions[j][b]));
      ModelInstances found;
      if (!detector.detect (found))
        return PairOutcome::failed;
      if (found.empty())
        continue;
      if (condition_ &&
          !condition_ (
              copyLink (regions[i][a], models[i].instances[a].pose, found.front()))) {
        ++refused;
        continue;
      }
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
RegionModelMerger::mergeChecked (ObjectModels& models,
                                 std::size_t& merged,
                                 std::size_t& refused) const
{
  // One pass over the pairs; the regions change with every merge.
  auto regions = computeInstanceRegions (*keypoints_, models, margin_);
  for (std::size_t i = 0; i < models.size(); ++i)
    for (std::size_t j = i + 1; j < models.size();) {
      const PairOutcome outcome = mergePair (models, regions, i, j, refused);
      if (outcome == PairOutcome::failed)
        return false;
      if (outcome == PairOutcome::apart) {
        ++j;
        continue;
      }
      // models[j] is gone: the next model now stands at j.
      models.erase (models.begin() + static_cast<std::ptrdiff_t> (j));
      ++merged;
      regions = computeInstanceRegions (*keypoints_, models, margin_);
    }
  return true;
}

bool
RegionModelMerger::merge (ObjectModels& models)
{
  merged_ = refused_ = 0;
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
  if (!detector_.hasValidParameters())
    return false;
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
  // Merges change the models: work on a copy, so that a failure leaves them as they were.
  ObjectModels merged = models;
  std::size_t count = 0, refused = 0;
  if (!mergeChecked (merged, count, refused))
    return false;
  merged_ = count;
  refused_ = refused;
  models.swap (merged);
  return true;
}

} // namespace mid
