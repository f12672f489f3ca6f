#include <mid/simulation/cylinder_shape.h>
#include <mid/simulation/texture.h>

#include <algorithm>
#include <cmath>

namespace mid {
namespace simulation {

namespace {

constexpr double kPi = 3.14159265358979323846;

const char* const kFaceNames[CylinderShape::FACE_COUNT] = {"side", "top", "bottom"};

} // namespace

CylinderShape::CylinderShape (double radius, double height)
: radius_ (radius), height_ (height)
{}

void
CylinderShape::setFaceTexture (Face face, const cv::Mat& texture)
{
  textures_[face] = toTexture (texture);
}

void
CylinderShape::setTexture (const cv::Mat& texture)
{
  const cv::Mat converted = toTexture (texture);
  for (cv::Mat& face_texture : textures_)
    face_texture = converted;
}

bool
CylinderShape::validate (std::string& problem) const
{
  problem.clear();
  if (!std::isfinite (radius_) || !std::isfinite (height_) || !(radius_ > 0.0) ||
      !(height_ > 0.0)) {
    problem = "cylinder radius and height must be finite and positive (got " +
              std::to_string (radius_) + ", " + std::to_string (height_) + " m)";
    return false;
  }
  for (int face = 0; face < FACE_COUNT; ++face) {
    std::string texture_problem;
    if (!checkTexture (textures_[face], texture_problem)) {
      problem = "cylinder " + std::string (kFaceNames[face]) + ": " + texture_problem;
      return false;
    }
  }
  return true;
}

double
CylinderShape::getBoundingRadius() const
{
  return std::hypot (radius_, 0.5 * height_);
}

bool
CylinderShape::intersect (const Eigen::Vector3d& origin,
                          const Eigen::Vector3d& direction,
                          double t_max,
                          SurfaceHit& hit) const
{
  const double half_height = 0.5 * height_;
  bool found = false;
  double best = t_max;

  // Side: the nearer root of |origin_xy + t direction_xy|^2 = r^2 (numerically stable form).
  const double a = direction.x() * direction.x() + direction.y() * direction.y();
  if (a > 0.0) {
    const double b = origin.x() * direction.x() + origin.y() * direction.y();
    const double c =
        origin.x() * origin.x() + origin.y() * origin.y() - radius_ * radius_;
    const double discriminant = b * b - a * c;
    if (discriminant >= 0.0) {
      const double q = -(b + std::copysign (std::sqrt (discriminant), b));
      const double root_a = q / a;
      const double root_b = (q != 0.0) ? c / q : root_a;
      const double t = std::min (root_a, root_b);
      const double z = origin.z() + t * direction.z();
      if (t > 0.0 && t < best && std::abs (z) <= half_height) {
        const Eigen::Vector3d point = origin + t * direction;
        best = t;
        found = true;
        hit.t = t;
        hit.face = SIDE;
        hit.normal = Eigen::Vector3d (point.x(), point.y(), 0.0).normalized();
        const double angle = std::atan2 (point.y(), point.x());
        hit.uv = Eigen::Vector2d (
            (angle + kPi) / (2.0 * kPi),
            std::clamp ((half_height - point.z()) / height_, 0.0, 1.0));
      }
    }
  }

  // Caps, entered from outside: the top when moving down, the bottom when moving up.
  if (direction.z() != 0.0) {
    const bool top = direction.z() < 0.0;
    const double t = ((top ? half_height : -half_height) - origin.z()) / direction.z();
    if (t > 0.0 && t < best) {
      const Eigen::Vector3d point = origin + t * direction;
      if (point.x() * point.x() + point.y() * point.y() <= radius_ * radius_) {
        found = true;
        hit.t = t;
        hit.face = top ? TOP : BOTTOM;
        hit.normal = Eigen::Vector3d (0.0, 0.0, top ? 1.0 : -1.0);
        const double diameter = 2.0 * radius_;
        const double s = (point.x() + radius_) / diameter;
        const double v = ((top ? -point.y() : point.y()) + radius_) / diameter;
        hit.uv = Eigen::Vector2d (std::clamp (s, 0.0, 1.0), std::clamp (v, 0.0, 1.0));
      }
    }
  }
  return found;
}

cv::Vec3f
CylinderShape::getColor (const SurfaceHit& hit) const
{
  if (hit.face == SIDE)
    return sampleBilinear (textures_[SIDE],
                           hit.uv.x(),
                           hit.uv.y(),
                           TextureWrap::REPEAT,
                           TextureWrap::CLAMP);
  return sampleBilinear (textures_[hit.face], hit.uv.x(), hit.uv.y());
}

double
CylinderShape::signedDistance (const Eigen::Vector3d& point) const
{
  const double radial = std::hypot (point.x(), point.y()) - radius_;
  const double axial = std::abs (point.z()) - 0.5 * height_;
  const double outside = std::hypot (std::max (radial, 0.0), std::max (axial, 0.0));
  return outside + std::min (std::max (radial, axial), 0.0);
}

std::vector<std::pair<std::string, double>>
CylinderShape::getDimensions() const
{
  return {{"radius", radius_}, {"height", height_}};
}

ShapeSymmetries
CylinderShape::getSymmetries() const
{
  ShapeSymmetries symmetries;
  symmetries.continuous_axes = {Eigen::Vector3d::UnitZ()};
  symmetries.discrete = {
      Eigen::Vector3d (1.0, -1.0, -1.0).asDiagonal()}; // half turn about x
  return symmetries;
}

} // namespace simulation
} // namespace mid
