#include <mid/segmentation/instance_extent.h>
#include <mid/segmentation/repeated_print_filter.h>

#include <Eigen/Geometry>
#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

namespace mid {

namespace {

/** How far outside the object's box a keypoint may lie and still count as on it (metres):
  * keypoints lie on the box's faces, which the box fit places within a few millimetres.
  */
constexpr float kBoxMargin = 0.005f;

/** Width of `box` along the unit direction `direction` (metres). */
float
widthAlong (const InstanceExtent& box, const Eigen::Vector3f& direction)
{
  float width = 0.0f;
  for (int axis = 0; axis < 3; ++axis)
    width += std::abs (direction.dot (box.pose.block<3, 1> (0, axis))) * box.size[axis];
  return width;
}

/** Where `pose` (model -> camera) puts the model point `point`. */
Eigen::Vector3f
placed (const Eigen::Matrix4f& pose, const Eigen::Vector3f& point)
{
  return pose.topLeftCorner<3, 3>() * point + pose.topRightCorner<3, 1>();
}

/** Share of `instance`'s keypoints inside `box` (within kBoxMargin of it). */
float
shareInside (const KeypointCloud& keypoints,
             const ModelInstance& instance,
             const InstanceExtent& box)
{
  if (instance.keypoints.empty())
    return 0.0f;
  const Eigen::Matrix4f to_box = box.pose.inverse();
  const Eigen::Array3f limit = 0.5f * box.size.array() + kBoxMargin;
  std::size_t inside = 0;
  for (const auto k : instance.keypoints) {
    const Eigen::Vector3f local =
        to_box.topLeftCorner<3, 3>() *
            keypoints[static_cast<std::size_t> (k)].getVector3fMap() +
        to_box.topRightCorner<3, 1>();
    if ((local.array().abs() <= limit).all())
      ++inside;
  }
  return static_cast<float> (inside) / static_cast<float> (instance.keypoints.size());
}

} // namespace

std::string
RepeatedPrintFilter::inputProblem (const ObjectModels& models) const
{
  if (std::string problem = planeMeasurementProblem (models); !problem.empty())
    return problem;
  if (!(max_rotation_ >= 0.0f && max_rotation_ <= static_cast<float> (M_PI)) ||
      !(max_shift_ratio_ >= 0.0f) || !std::isfinite (max_shift_ratio_) ||
      !(max_shift_along_width_ >= 0.0f) || !std::isfinite (max_shift_along_width_) ||
      !(min_inside_share_ >= 0.0f && min_inside_share_ <= 1.0f))
    return "the rotation must be in [0, pi], the shift ratios finite and >= 0, the "
           "inside share in [0, 1]";
  return "";
}

bool
RepeatedPrintFilter::filter (ObjectModels& models, std::size_t& removed) const
{
  removed = 0;
  const std::string problem = inputProblem (models);
  if (!problem.empty()) {
    PCL_ERROR ("[mid::RepeatedPrintFilter::filter] %s.\n", problem.c_str());
    return false;
  }
  Eigen::Vector4f plane;
  if (models.empty() || !fitPlane (plane))
    return true;
  const auto& organized = *surface_.organized;
  const float any_distance = std::numeric_limits<float>::infinity();
  std::vector<std::vector<bool>> repeats;
  repeats.reserve (models.size());
  for (const auto& model : models) {
    const Eigen::Vector3f centroid = landmarkCentroid (model);
    const auto& instances = model.instances;
    std::vector<std::size_t> order (instances.size());
    std::iota (order.begin(), order.end(), std::size_t{0});
    std::stable_sort (
        order.begin(), order.end(), [&instances] (std::size_t a, std::size_t b) {
          return instances[a].keypoints.size() > instances[b].keypoints.size();
        });
    std::vector<bool> repeat (instances.size(), false);
    for (std::size_t i = 0; i < order.size(); ++i) {
      const ModelInstance& first = instances[order[i]];
      if (repeat[order[i]])
        continue;
      // Only the instances turned by less than max_rotation can repeat it: the object box
      // is grown for those alone.
      std::vector<std::size_t> turned_alike;
      for (std::size_t j = i + 1; j < order.size(); ++j)
        if (!repeat[order[j]] && posesCoincide (first.pose,
                                                instances[order[j]].pose,
                                                centroid,
                                                max_rotation_,
                                                any_distance))
          turned_alike.push_back (order[j]);
      if (turned_alike.empty())
        continue;
      pcl::Indices seeds;
      for (const auto k : first.keypoints)
        seeds.push_back (surface_.keypoint_pixels[static_cast<std::size_t> (k)]);
      InstanceExtent box;
      if (!measureInstanceExtent (
              organized, plane, seeds, max_step_, max_radius_, plane_tolerance_, box))
        continue;
      for (const std::size_t j : turned_alike) {
        const ModelInstance& second = instances[j];
        const Eigen::Vector3f shift =
            placed (second.pose, centroid) - placed (first.pose, centroid);
        const float distance = shift.norm();
        // Two instances at one place (no shift) have no direction: the widest is taken.
        const float width =
            distance > 0.0f ? widthAlong (box, shift / distance) : box.size.maxCoeff();
        repeat[j] = distance < std::min (max_shift_ratio_ * box.size.minCoeff(),
                                         max_shift_along_width_ * width) &&
                    shareInside (*keypoints_, second, box) >= min_inside_share_;
      }
    }
    repeats.push_back (repeat);
  }
  // A model of repeats alone is no object: its last instance goes too, and the model.
  removed = removeInstances (repeats, models);
  return true;
}

} // namespace mid
