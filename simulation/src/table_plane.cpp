#include <mid/simulation/table_plane.h>
#include <mid/simulation/texture.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace mid {
namespace simulation {

TablePlane::TablePlane (double tile_x, double tile_y) : tile_size_ (tile_x, tile_y) {}

void
TablePlane::setTileSize (double tile_x, double tile_y)
{
  tile_size_ = Eigen::Vector2d (tile_x, tile_y);
}

void
TablePlane::setExtent (double size_x, double size_y)
{
  extent_ = Eigen::Vector2d (size_x, size_y);
}

void
TablePlane::setTexture (const cv::Mat& texture)
{
  texture_ = toTexture (texture);
}

bool
TablePlane::validate (std::string& problem) const
{
  problem.clear();
  if (!tile_size_.allFinite() || !(tile_size_.minCoeff() > 0.0))
    problem = "table tile sizes must be finite and positive (got " +
              std::to_string (tile_size_.x()) + ", " + std::to_string (tile_size_.y()) +
              " m)";
  else if (!extent_.allFinite() || extent_.minCoeff() < 0.0)
    problem = "table extents must be finite and non-negative (0 = infinite)";
  else if (checkTexture (texture_, problem))
    return true;
  else
    problem = "table: " + problem;
  return false;
}

double
TablePlane::getBoundingRadius() const
{
  if (extent_.x() > 0.0 && extent_.y() > 0.0)
    return 0.5 * extent_.norm();
  return std::numeric_limits<double>::infinity();
}

bool
TablePlane::intersect (const Eigen::Vector3d& origin,
                       const Eigen::Vector3d& direction,
                       double t_max,
                       SurfaceHit& hit) const
{
  if (direction.z() == 0.0)
    return false;
  const double t = -origin.z() / direction.z();
  if (!(t > 0.0) || !(t < t_max))
    return false;
  const double x = origin.x() + t * direction.x();
  const double y = origin.y() + t * direction.y();
  if ((extent_.x() > 0.0 && std::abs (x) > 0.5 * extent_.x()) ||
      (extent_.y() > 0.0 && std::abs (y) > 0.5 * extent_.y()))
    return false;
  hit.t = t;
  hit.face = 0;
  hit.normal = Eigen::Vector3d (0.0, 0.0, direction.z() < 0.0 ? 1.0 : -1.0);
  hit.uv = Eigen::Vector2d (0.5 + x / tile_size_.x(), 0.5 - y / tile_size_.y());
  return true;
}

cv::Vec3f
TablePlane::getColor (const SurfaceHit& hit) const
{
  return sampleBilinear (
      texture_, hit.uv.x(), hit.uv.y(), TextureWrap::REPEAT, TextureWrap::REPEAT);
}

double
TablePlane::signedDistance (const Eigen::Vector3d& point) const
{
  const double dx = extent_.x() > 0.0
                        ? std::max (std::abs (point.x()) - 0.5 * extent_.x(), 0.0)
                        : 0.0;
  const double dy = extent_.y() > 0.0
                        ? std::max (std::abs (point.y()) - 0.5 * extent_.y(), 0.0)
                        : 0.0;
  const double distance = std::sqrt (dx * dx + dy * dy + point.z() * point.z());
  return point.z() < 0.0 ? -distance : distance;
}

std::vector<std::pair<std::string, double>>
TablePlane::getDimensions() const
{
  return {{"size_x", extent_.x()},
          {"size_y", extent_.y()},
          {"tile_x", tile_size_.x()},
          {"tile_y", tile_size_.y()}};
}

} // namespace simulation
} // namespace mid
