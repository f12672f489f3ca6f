#include <mid/simulation/box_shape.h>
#include <mid/simulation/texture.h>

#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace mid {
namespace simulation {

namespace {

/** Orientation of a face's texture: the model axis (and its sign) along the image's x axis
  * ("right") and along its y axis ("down").
  */
struct FaceFrame
{
  int right_axis;
  double right_sign;
  int down_axis;
  double down_sign;
};

/** Indexed by BoxShape::Face; right x down is the inward normal, so the image is not mirrored
  * when seen from outside.
  */
constexpr FaceFrame kFaceFrames[BoxShape::FACE_COUNT] = {{1, 1.0, 2, -1.0},  // POS_X
                                                         {1, -1.0, 2, -1.0}, // NEG_X
                                                         {0, -1.0, 2, -1.0}, // POS_Y
                                                         {0, 1.0, 2, -1.0},  // NEG_Y
                                                         {0, 1.0, 1, -1.0},  // POS_Z
                                                         {0, 1.0, 1, 1.0}};  // NEG_Z

const char* const kFaceNames[BoxShape::FACE_COUNT] = {
    "+x", "-x", "+y", "-y", "+z", "-z"};

} // namespace

BoxShape::BoxShape (double size_x, double size_y, double size_z)
: size_ (size_x, size_y, size_z)
{}

void
BoxShape::setFaceTexture (Face face, const cv::Mat& texture)
{
  textures_[face] = toTexture (texture);
}

void
BoxShape::setTexture (const cv::Mat& texture)
{
  const cv::Mat converted = toTexture (texture);
  for (cv::Mat& face_texture : textures_)
    face_texture = converted;
}

bool
BoxShape::validate (std::string& problem) const
{
  problem.clear();
  if (!size_.allFinite() || !(size_.minCoeff() > 0.0)) {
    problem = "box sizes must be finite and positive (got " +
              std::to_string (size_.x()) + ", " + std::to_string (size_.y()) + ", " +
              std::to_string (size_.z()) + " m)";
    return false;
  }
  for (int face = 0; face < FACE_COUNT; ++face) {
    std::string texture_problem;
    if (!checkTexture (textures_[face], texture_problem)) {
      problem = "box face " + std::string (kFaceNames[face]) + ": " + texture_problem;
      return false;
    }
  }
  return true;
}

bool
BoxShape::intersect (const Eigen::Vector3d& origin,
                     const Eigen::Vector3d& direction,
                     double t_max,
                     SurfaceHit& hit) const
{
  const Eigen::Vector3d half = 0.5 * size_;
  double t_enter = -std::numeric_limits<double>::infinity();
  double t_exit = std::numeric_limits<double>::infinity();
  int face = -1;
  for (int axis = 0; axis < 3; ++axis) {
    if (direction[axis] == 0.0) {
      if (std::abs (origin[axis]) > half[axis])
        return false;
      continue;
    }
    // Slab of this axis: entered through -half when moving towards +, through +half otherwise.
    const bool positive = direction[axis] > 0.0;
    const double t_near =
        ((positive ? -half[axis] : half[axis]) - origin[axis]) / direction[axis];
    const double t_far =
        ((positive ? half[axis] : -half[axis]) - origin[axis]) / direction[axis];
    if (t_near > t_enter) {
      t_enter = t_near;
      face = 2 * axis + (positive ? 1 : 0);
    }
    t_exit = std::min (t_exit, t_far);
  }
  if (face < 0 || t_enter > t_exit || !(t_enter > 0.0) || !(t_enter < t_max))
    return false;

  const Eigen::Vector3d point = origin + t_enter * direction;
  const int axis = face / 2;
  hit.t = t_enter;
  hit.face = face;
  hit.normal = Eigen::Vector3d::Zero();
  hit.normal[axis] = (face % 2 == 0) ? 1.0 : -1.0;
  const FaceFrame& frame = kFaceFrames[face];
  const double s =
      (frame.right_sign * point[frame.right_axis] + half[frame.right_axis]) /
      size_[frame.right_axis];
  const double t = (frame.down_sign * point[frame.down_axis] + half[frame.down_axis]) /
                   size_[frame.down_axis];
  hit.uv = Eigen::Vector2d (std::clamp (s, 0.0, 1.0), std::clamp (t, 0.0, 1.0));
  return true;
}

cv::Vec3f
BoxShape::getColor (const SurfaceHit& hit) const
{
  return sampleBilinear (textures_[hit.face], hit.uv.x(), hit.uv.y());
}

double
BoxShape::signedDistance (const Eigen::Vector3d& point) const
{
  const Eigen::Vector3d q = point.cwiseAbs() - 0.5 * size_;
  return q.cwiseMax (0.0).norm() + std::min (q.maxCoeff(), 0.0);
}

std::vector<std::pair<std::string, double>>
BoxShape::getDimensions() const
{
  return {{"size_x", size_.x()}, {"size_y", size_.y()}, {"size_z", size_.z()}};
}

ShapeSymmetries
BoxShape::getSymmetries() const
{
  // A rotation maps the box onto itself iff it permutes the axes (with signs) and each axis
  // goes to one of the same size.
  const double tolerance = 1e-9 * size_.maxCoeff();
  ShapeSymmetries symmetries;
  std::array<int, 3> axes = {0, 1, 2};
  do {
    bool same_sizes = true;
    for (int i = 0; i < 3; ++i)
      same_sizes = same_sizes && std::abs (size_[axes[i]] - size_[i]) <= tolerance;
    if (!same_sizes)
      continue;
    for (int signs = 0; signs < 8; ++signs) {
      Eigen::Matrix3d rotation = Eigen::Matrix3d::Zero();
      for (int i = 0; i < 3; ++i)
        rotation (axes[i], i) = (signs >> i) & 1 ? -1.0 : 1.0;
      if (rotation.determinant() > 0.0 && !rotation.isIdentity())
        symmetries.discrete.push_back (rotation);
    }
  }
  while (std::next_permutation (axes.begin(), axes.end()));
  return symmetries;
}

} // namespace simulation
} // namespace mid
