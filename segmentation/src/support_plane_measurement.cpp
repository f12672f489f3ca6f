#include <mid/segmentation/instance_extent.h>
#include <mid/segmentation/support_plane_measurement.h>

namespace mid {

std::string
SupportPlaneMeasurement::planeMeasurementProblem (const ObjectModels& models) const
{
  if (!keypoints_)
    return "no input keypoints";
  if (!isValidKeypointSurface (surface_, keypoints_->size()))
    return "the keypoint surface is not an organized frame holding every keypoint's "
           "pixel";
  if (!(max_step_ > 0.0f) || !(max_radius_ > 0.0f) || !(plane_tolerance_ > 0.0f))
    return "the step, radius and plane tolerance must be > 0";
  for (const auto& model : models)
    for (const auto& instance : model.instances)
      for (const auto k : instance.keypoints)
        if (k < 0 || static_cast<std::size_t> (k) >= keypoints_->size())
          return "an instance observes a keypoint outside the input keypoints";
  return "";
}

bool
SupportPlaneMeasurement::fitPlane (Eigen::Vector4f& plane) const
{
  return fitSupportPlane (
      *surface_.organized, plane_tolerance_, kMinSupportPlaneShare, plane);
}

} // namespace mid
