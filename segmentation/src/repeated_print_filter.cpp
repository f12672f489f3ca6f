#include <mid/segmentation/instance_extent.h>
#include <mid/segmentation/repeated_print_filter.h>

#include <Eigen/Geometry>
#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace mid {

namespace {

/** How far outside the object's box a keypoint may lie and still count as on it (metres):
  * keypoints lie on the box's faces, which the box fit places within a few millimetres.
  */
constexpr float kBoxMargin = 0.005f;

/** The centroid of a model's landmarks (model frame); the origin without landmarks. */
Eigen::Vector3f
landmarkCentroid (const ObjectModel& model)
{
  Eigen::Vector3f centroid = Eigen::Vector3f::Zero();
  for (const auto& landmark : model.landmarks)
    centroid += landmark.getVector3fMap();
  return model.landmarks.empty()
             ? centroid
             : Eigen::Vector3f (centroid / static_cast<float> (model.landmarks.size()));
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
      !(min_inside_share_ >= 0.0f && min_inside_share_ <= 1.0f))
    return "the rotation must be in [0, pi], the shift ratio finite and >= 0, the "
           "inside "
           "share in [0, 1]";
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
  for (auto& model : models) {
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
      pcl::Indices seeds;
      for (const auto k : first.keypoints)
        seeds.push_back (surface_.keypoint_pixels[static_cast<std::size_t> (k)]);
      InstanceExtent box;
      if (!measureInstanceExtent (
              organized, plane, seeds, max_step_, max_radius_, plane_tolerance_, box))
        continue;
      const Eigen::Vector3f first_centre = first.pose.topLeftCorner<3, 3>() * centroid +
                                           first.pose.topRightCorner<3, 1>();
      for (std::size_t j = i + 1; j < order.size(); ++j) {
        const ModelInstance& second = instances[order[j]];
        if (repeat[order[j]])
          continue;
        const Eigen::Matrix3f turn = second.pose.topLeftCorner<3, 3>() *
                                     first.pose.topLeftCorner<3, 3>().transpose();
        const Eigen::Vector3f second_centre =
            second.pose.topLeftCorner<3, 3>() * centroid +
            second.pose.topRightCorner<3, 1>();
        repeat[order[j]] = Eigen::AngleAxisf (turn).angle() < max_rotation_ &&
                           (second_centre - first_centre).norm() <
                               max_shift_ratio_ * box.size.minCoeff() &&
                           shareInside (*keypoints_, second, box) >= min_inside_share_;
      }
    }
    ModelInstances kept;
    for (std::size_t i = 0; i < instances.size(); ++i)
      if (!repeat[i])
        kept.push_back (instances[i]);
    removed += instances.size() - kept.size();
    // A model of repeats alone is no object: it is left empty, and removed below.
    if (kept.size() < 2 && kept.size() < instances.size())
      kept.clear();
    model.instances.swap (kept);
  }
  models.erase (std::remove_if (
                    models.begin(),
                    models.end(),
                    [] (const ObjectModel& model) { return model.instances.empty(); }),
                models.end());
  return true;
}

} // namespace mid
