#include "table_layout.h"

#include <algorithm>
#include <cmath>

namespace mid {
namespace simulation {

namespace {

constexpr double kPi = 3.14159265358979323846;

/** Random positions tried per object, and fresh starts of the whole layout. */
constexpr int kMaxPlacementAttempts = 300;
constexpr int kMaxLayoutRestarts = 300;

/** Draw a free spot for a footprint of the given half extents; false if none was found. */
bool
placeFootprint (const Footprint& shape,
                const PlacementView& view,
                double gap,
                DeterministicRandom& random,
                std::vector<Footprint>& placed)
{
  for (int attempt = 0; attempt < kMaxPlacementAttempts; ++attempt) {
    Footprint candidate = shape;
    candidate.center = Eigen::Vector2d (random.uniform (view.min_x, view.max_x),
                                        random.uniform (view.min_y, view.max_y));
    candidate.yaw = random.uniform (0.0, 2.0 * kPi);
    if (footprintFree (candidate, view, placed, gap)) {
      placed.push_back (candidate);
      return true;
    }
  }
  return false;
}

} // namespace

bool
footprintsOverlap (const Footprint& a, const Footprint& b, double gap)
{
  const Eigen::Vector2d axes[4] = {{std::cos (a.yaw), std::sin (a.yaw)},
                                   {-std::sin (a.yaw), std::cos (a.yaw)},
                                   {std::cos (b.yaw), std::sin (b.yaw)},
                                   {-std::sin (b.yaw), std::cos (b.yaw)}};
  const Eigen::Vector2d offset = b.center - a.center;
  // Separating axis test: the rectangles (grown by half the gap) overlap unless one of the
  // four edge directions separates their projections.
  return std::all_of (
      std::begin (axes), std::end (axes), [&] (const Eigen::Vector2d& axis) {
        const double reach_a =
            std::abs ((a.half.x() + 0.5 * gap) * axes[0].dot (axis)) +
            std::abs ((a.half.y() + 0.5 * gap) * axes[1].dot (axis));
        const double reach_b =
            std::abs ((b.half.x() + 0.5 * gap) * axes[2].dot (axis)) +
            std::abs ((b.half.y() + 0.5 * gap) * axes[3].dot (axis));
        return std::abs (offset.dot (axis)) <= reach_a + reach_b;
      });
}

bool
footprintAllowed (const Footprint& footprint, const PlacementView& view)
{
  const double c = std::cos (footprint.yaw), s = std::sin (footprint.yaw);
  for (int corner = 0; corner < 8; ++corner) {
    const double x = ((corner & 1) ? 1.0 : -1.0) * footprint.half.x();
    const double y = ((corner & 2) ? 1.0 : -1.0) * footprint.half.y();
    const Eigen::Vector3d point (footprint.center.x() + c * x - s * y,
                                 footprint.center.y() + s * x + c * y,
                                 (corner & 4) ? footprint.height : 0.0);
    if (point.x() < view.min_x || point.x() > view.max_x || point.y() < view.min_y ||
        point.y() > view.max_y)
      return false;
    Eigen::Vector2d pixel;
    if (!projectPoint (view.camera, view.table_to_camera * point, pixel) ||
        pixel.x() < view.margin || pixel.y() < view.margin ||
        pixel.x() > view.camera.width - 1 - view.margin ||
        pixel.y() > view.camera.height - 1 - view.margin)
      return false;
  }
  return true;
}

bool
footprintFree (const Footprint& footprint,
               const PlacementView& view,
               const std::vector<Footprint>& placed,
               double gap)
{
  if (!footprintAllowed (footprint, view))
    return false;
  return std::none_of (placed.begin(), placed.end(), [&] (const Footprint& other) {
    return footprintsOverlap (footprint, other, gap);
  });
}

bool
layoutFootprints (const std::vector<Footprint>& shapes,
                  const PlacementView& view,
                  double gap,
                  DeterministicRandom& random,
                  std::vector<Footprint>& layout)
{
  std::vector<std::size_t> order (shapes.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  std::stable_sort (
      order.begin(), order.end(), [&shapes] (std::size_t a, std::size_t b) {
        return shapes[a].half.prod() > shapes[b].half.prod();
      });
  for (int restart = 0; restart < kMaxLayoutRestarts; ++restart) {
    std::vector<Footprint> placed;
    layout.assign (shapes.size(), Footprint());
    bool complete = true;
    for (const std::size_t index : order) {
      if (!placeFootprint (shapes[index], view, gap, random, placed)) {
        complete = false;
        break;
      }
      layout[index] = placed.back();
    }
    if (complete)
      return true;
  }
  return false;
}

Eigen::Isometry3d
tableToCamera (double distance, double elevation_deg, double azimuth_deg)
{
  const double elevation = elevation_deg * kPi / 180.0;
  Eigen::Vector3d eye (
      0.0, -distance * std::cos (elevation), distance * std::sin (elevation));
  if (azimuth_deg != 0.0)
    eye = Eigen::AngleAxisd (azimuth_deg * kPi / 180.0, Eigen::Vector3d::UnitZ()) * eye;
  const Eigen::Vector3d forward = (-eye).normalized();
  const Eigen::Vector3d right = forward.cross (Eigen::Vector3d::UnitZ()).normalized();
  const Eigen::Vector3d down = forward.cross (right);
  Eigen::Isometry3d camera_to_table = Eigen::Isometry3d::Identity();
  camera_to_table.linear() << right, down, forward;
  camera_to_table.translation() = eye;
  return camera_to_table.inverse();
}

Footprint
restingFootprint (const Eigen::Vector3d& size, const Eigen::Matrix3d& orientation)
{
  const Eigen::Vector3d extent = orientation.cwiseAbs() * size;
  Footprint footprint;
  footprint.half = 0.5 * extent.head<2>();
  footprint.height = extent.z();
  return footprint;
}

Eigen::Isometry3d
restingPose (const Footprint& footprint, double z, const Eigen::Matrix3d& orientation)
{
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() =
      Eigen::AngleAxisd (footprint.yaw, Eigen::Vector3d::UnitZ()) * orientation;
  pose.translation() = Eigen::Vector3d (footprint.center.x(), footprint.center.y(), z);
  return pose;
}

} // namespace simulation
} // namespace mid
