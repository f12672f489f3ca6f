#include <mid/registration/model_merging.h>
#include <mid/segmentation/instance_extent.h>
#include <mid/segmentation/model_size.h>
#include <mid/segmentation/model_size_merger.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace mid {

std::string
ModelSizeMerger::inputProblem (const ObjectModels& models) const
{
  if (!keypoints_)
    return "no input keypoints";
  if (!isValidKeypointSurface (surface_, keypoints_->size()))
    return "the keypoint surface is not an organized frame holding every keypoint's "
           "pixel";
  if (!(max_step_ > 0.0f) || !(max_radius_ > 0.0f) || !(plane_tolerance_ > 0.0f))
    return "the step, radius and plane tolerance must be > 0";
  if (!(size_tolerance_ >= 0.0f) || !(relative_size_tolerance_ >= 0.0f))
    return "the size tolerances must be >= 0";
  if (min_agreeing_ < 1)
    return "at least one instance must agree on a size";
  for (const auto& model : models)
    for (const auto& instance : model.instances)
      for (const auto k : instance.keypoints)
        if (k < 0 || static_cast<std::size_t> (k) >= keypoints_->size())
          return "an instance observes a keypoint outside the input keypoints";
  return "";
}

bool
ModelSizeMerger::merge (ObjectModels& models) const
{
  const std::string problem = inputProblem (models);
  if (!problem.empty()) {
    PCL_ERROR ("[mid::ModelSizeMerger::merge] %s.\n", problem.c_str());
    return false;
  }
  if (models.size() < 2)
    return true;
  const auto& organized = *surface_.organized;
  Eigen::Vector4f plane;
  if (!fitSupportPlane (organized, plane_tolerance_, kMinSupportPlaneShare, plane))
    return true;

  const SizeAgreement agree (size_tolerance_, relative_size_tolerance_);
  ModelSizes sizes;
  if (!measureModelSizes (organized,
                          plane,
                          surface_.keypoint_pixels,
                          models,
                          max_step_,
                          max_radius_,
                          plane_tolerance_,
                          agree,
                          min_agreeing_,
                          sizes))
    return false;

  for (std::size_t a = 0; a < models.size(); ++a) {
    for (std::size_t b = a + 1; b < models.size() && sizes[a].valid;) {
      if (!sizes[b].valid || !agree (sizes[a].size, sizes[b].size)) {
        ++b;
        continue;
      }
      if (models[b].instances.size() > models[a].instances.size()) {
        std::swap (models[a], models[b]);
        std::swap (sizes[a], sizes[b]);
      }
      // One box frame in both models: x_b = box_in_b * box_in_a^-1 * x_a.
      const Eigen::Matrix4f into_to_from =
          sizes[b].box_in_model * sizes[a].box_in_model.inverse();
      mergeModel (models[a],
                  models[b],
                  into_to_from,
                  {},
                  duplicate_angle_,
                  duplicate_distance_);
      models.erase (models.begin() + static_cast<std::ptrdiff_t> (b));
      sizes.erase (sizes.begin() + static_cast<std::ptrdiff_t> (b));
    }
  }
  return true;
}

} // namespace mid
