#include <mid/segmentation/instance_extent.h>
#include <mid/segmentation/order_statistics.h>
#include <mid/segmentation/support_print_filter.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace mid {

namespace {

/** Narrowest ring of pixels looked at around an instance's keypoints. */
constexpr int kMinRingWidth = 10;

/** Smallest share of the pixels around a print that lie on the plane (half: a sheet near the
  * frame's border or beside an object still shows the plane around most of it).
  */
constexpr float kMinSurroundingsOnPlane = 0.5f;

/** True if at least `min_share` of the instance's keypoints lie within `tolerance` of
  * `plane`; false for an instance without keypoints.
  */
bool
liesInPlane (const KeypointCloud& keypoints,
             const ModelInstance& instance,
             const Eigen::Vector4f& plane,
             float tolerance,
             float min_share)
{
  if (instance.keypoints.empty())
    return false;
  std::size_t on_plane = 0;
  for (const auto k : instance.keypoints)
    if (std::abs (planeDistance (
            plane, keypoints[static_cast<std::size_t> (k)].getVector3fMap())) <=
        tolerance)
      ++on_plane;
  return static_cast<double> (on_plane) >=
         static_cast<double> (min_share) *
             static_cast<double> (instance.keypoints.size());
}

/** The share of the pixels around an instance's keypoints that lie on `plane` (valid, within
  * `tolerance`): the ring between the image box of its keypoints and that box grown by half its
  * longer side (at least kMinRingWidth pixels) on every side, clipped to the frame. A print lies
  * on a plane that goes on around it (the sheet's paper, the table); the top of an object to
  * which the plane was fitted ends at its edges, beyond which the surface falls away.
  */
float
shareOfSurroundingsOnPlane (const KeypointSurface& surface,
                            const ModelInstance& instance,
                            const Eigen::Vector4f& plane,
                            float tolerance)
{
  const auto& organized = *surface.organized;
  const int width = static_cast<int> (organized.width),
            height = static_cast<int> (organized.height);
  int u_min = width, u_max = -1, v_min = height, v_max = -1;
  for (const auto k : instance.keypoints) {
    const int pixel = surface.keypoint_pixels[static_cast<std::size_t> (k)];
    u_min = std::min (u_min, pixel % width);
    u_max = std::max (u_max, pixel % width);
    v_min = std::min (v_min, pixel / width);
    v_max = std::max (v_max, pixel / width);
  }
  if (u_max < 0)
    return 0.0f;
  const int grow =
      std::max (kMinRingWidth, (std::max (u_max - u_min, v_max - v_min) + 1) / 2);
  std::size_t ring = 0, on_plane = 0;
  for (int v = std::max (0, v_min - grow); v <= std::min (height - 1, v_max + grow);
       ++v)
    for (int u = std::max (0, u_min - grow); u <= std::min (width - 1, u_max + grow);
         ++u) {
      if (u >= u_min && u <= u_max && v >= v_min && v <= v_max)
        continue;
      ++ring;
      const auto& p = organized.at (u, v);
      if (std::isfinite (p.z) &&
          std::abs (planeDistance (plane, p.getVector3fMap())) <= tolerance)
        ++on_plane;
    }
  return ring == 0 ? 0.0f
                   : static_cast<float> (static_cast<double> (on_plane) /
                                         static_cast<double> (ring));
}

/** The median signed distance (metres, positive towards the camera) of the instance's
  * keypoints from `plane`; 0 for an instance without keypoints.
  */
float
medianHeight (const KeypointCloud& keypoints,
              const ModelInstance& instance,
              const Eigen::Vector4f& plane)
{
  std::vector<float> heights;
  heights.reserve (instance.keypoints.size());
  for (const auto k : instance.keypoints)
    heights.push_back (planeDistance (
        plane, keypoints[static_cast<std::size_t> (k)].getVector3fMap()));
  return heights.empty() ? 0.0f : median (heights);
}

/** True if `plane` is seen to support the found objects: an instance stands off it towards
  * the camera (its median keypoint more than `tolerance` in front), and none lies beyond it
  * (its median keypoint more than `tolerance` behind). A plane fitted to the top of one object
  * or to a layer of tops, with nothing standing on it or with objects behind it, is not the
  * table under them.
  */
bool
supportsObjects (const KeypointCloud& keypoints,
                 const ObjectModels& models,
                 const Eigen::Vector4f& plane,
                 float tolerance)
{
  bool standing = false;
  for (const auto& model : models)
    for (const auto& instance : model.instances) {
      const float height = medianHeight (keypoints, instance, plane);
      if (height < -tolerance)
        return false;
      standing = standing || height > tolerance;
    }
  return standing;
}

} // namespace

bool
SupportPrintFilter::filter (ObjectModels& models, std::size_t& removed) const
{
  removed = 0;
  std::string problem = planeMeasurementProblem (models);
  if (problem.empty() && !(min_share_on_plane_ > 0.0f && min_share_on_plane_ <= 1.0f))
    problem = "the smallest share of keypoints on the plane must be in (0, 1]";
  if (!problem.empty()) {
    PCL_ERROR ("[mid::SupportPrintFilter::filter] %s.\n", problem.c_str());
    return false;
  }
  Eigen::Vector4f plane;
  if (models.empty() || !fitPlane (plane) ||
      !supportsObjects (*keypoints_, models, plane, plane_tolerance_))
    return true;
  std::vector<std::vector<bool>> prints;
  prints.reserve (models.size());
  for (const auto& model : models) {
    std::vector<bool> print;
    print.reserve (model.instances.size());
    for (const auto& instance : model.instances)
      print.push_back (
          liesInPlane (
              *keypoints_, instance, plane, plane_tolerance_, min_share_on_plane_) &&
          shareOfSurroundingsOnPlane (surface_, instance, plane, plane_tolerance_) >=
              kMinSurroundingsOnPlane);
    prints.push_back (std::move (print));
  }
  removed = removeInstances (prints, models);
  return true;
}

} // namespace mid
