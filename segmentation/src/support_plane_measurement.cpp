#include <mid/segmentation/instance_extent.h>
#include <mid/segmentation/support_plane_measurement.h>

#include <cmath>

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
  if (has_support_plane_ && !support_plane_.isZero() &&
      !(support_plane_.allFinite() &&
        std::abs (support_plane_.head<3>().norm() - 1.0f) < 1e-3f))
    return "the support plane given is neither zero nor a plane with a unit normal";
  for (const auto& model : models)
    if (std::string problem = observationProblem (model, keypoints_->size());
        !problem.empty())
      return problem;
  return "";
}

bool
SupportPlaneMeasurement::fitPlane (Eigen::Vector4f& plane) const
{
  if (has_support_plane_) {
    plane = support_plane_;
    return !plane.isZero();
  }
  return fitSupportPlane (
      *surface_.organized, plane_tolerance_, kMinSupportPlaneShare, plane);
}

} // namespace mid
