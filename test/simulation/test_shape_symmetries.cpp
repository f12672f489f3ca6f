#include <mid/simulation/box_shape.h>
#include <mid/simulation/cylinder_shape.h>
#include <mid/simulation/table_plane.h>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace mid::simulation;

namespace {

/** The eight corners of a box of the given size, centred at the origin. */
std::vector<Eigen::Vector3d>
corners (const Eigen::Vector3d& size)
{
  std::vector<Eigen::Vector3d> points;
  points.reserve (8);
  for (int i = 0; i < 8; ++i)
    points.emplace_back (0.5 * size.x() * (i & 1 ? 1 : -1),
                         0.5 * size.y() * (i & 2 ? 1 : -1),
                         0.5 * size.z() * (i & 4 ? 1 : -1));
  return points;
}

/** True if the rotation maps every corner onto a corner. */
bool
mapsCornersOntoCorners (const Eigen::Matrix3d& rotation, const Eigen::Vector3d& size)
{
  const std::vector<Eigen::Vector3d> points = corners (size);
  for (const auto& point : points) {
    bool onto = false;
    for (const auto& other : points)
      onto = onto || (rotation * point - other).norm() < 1e-9;
    if (!onto)
      return false;
  }
  return true;
}

/** Points on a cylinder's side and caps. */
std::vector<Eigen::Vector3d>
cylinderSurface (double radius, double height)
{
  std::vector<Eigen::Vector3d> points;
  for (int k = 0; k < 12; ++k) {
    const double angle = 0.5 * k;
    points.emplace_back (radius * std::cos (angle),
                         radius * std::sin (angle),
                         height * (k / 12.0 - 0.45));
    points.emplace_back (0.5 * radius * std::cos (angle),
                         0.5 * radius * std::sin (angle),
                         k % 2 == 0 ? 0.5 * height : -0.5 * height);
  }
  return points;
}

} // namespace

TEST (SimulationShapeSymmetries, ABoxHasTheRotationsOfItsSymmetryGroup)
{
  // Group orders: three different sizes 4 (D2), a square cross-section 8 (D4), a cube 24;
  // the identity is not listed.
  const std::vector<std::pair<Eigen::Vector3d, std::size_t>> cases = {
      {{0.16, 0.11, 0.05}, 3}, {{0.07, 0.07, 0.2}, 7}, {{0.1, 0.1, 0.1}, 23}};
  for (const auto& [size, count] : cases) {
    const ShapeSymmetries symmetries =
        BoxShape (size.x(), size.y(), size.z()).getSymmetries();
    EXPECT_TRUE (symmetries.continuous_axes.empty());
    ASSERT_EQ (symmetries.discrete.size(), count) << size.transpose();
    for (std::size_t i = 0; i < count; ++i) {
      const Eigen::Matrix3d& rotation = symmetries.discrete[i];
      EXPECT_TRUE (rotation.isUnitary (1e-12) && rotation.determinant() > 0.0);
      EXPECT_FALSE (rotation.isIdentity());
      EXPECT_TRUE (mapsCornersOntoCorners (rotation, size)) << rotation;
      for (std::size_t j = 0; j < i; ++j)
        EXPECT_FALSE (rotation.isApprox (symmetries.discrete[j]));
    }
  }
  // A quarter turn is no symmetry of a box whose sizes differ across it.
  EXPECT_FALSE (mapsCornersOntoCorners (
      Eigen::AngleAxisd (M_PI / 2.0, Eigen::Vector3d::UnitZ()).toRotationMatrix(),
      Eigen::Vector3d (0.16, 0.11, 0.05)));
}

TEST (SimulationShapeSymmetries, ACylinderTurnsAboutItsAxisAndFlipsItsCaps)
{
  const double radius = 0.035, height = 0.16;
  const CylinderShape can (radius, height);
  const ShapeSymmetries symmetries = can.getSymmetries();
  ASSERT_EQ (symmetries.continuous_axes.size(), 1u);
  EXPECT_TRUE (symmetries.continuous_axes[0].isApprox (Eigen::Vector3d::UnitZ()));
  ASSERT_EQ (symmetries.discrete.size(), 1u);
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd (0.7, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Matrix3d tilt =
      Eigen::AngleAxisd (M_PI / 2.0, Eigen::Vector3d::UnitX()).toRotationMatrix();
  double worst_symmetric = 0.0, worst_tilted = 0.0;
  for (const auto& point : cylinderSurface (radius, height)) {
    EXPECT_NEAR (can.signedDistance (point), 0.0, 1e-12);
    worst_symmetric = std::max (
        {worst_symmetric,
         std::abs (can.signedDistance (turn * point)),
         std::abs (can.signedDistance (symmetries.discrete[0] * turn * point))});
    worst_tilted =
        std::max (worst_tilted, std::abs (can.signedDistance (tilt * point)));
  }
  EXPECT_LT (worst_symmetric, 1e-12);
  EXPECT_GT (worst_tilted, 0.01); // a quarter turn across the axis is none
}

TEST (SimulationShapeSymmetries, ATablePlaneListsNone)
{
  const ShapeSymmetries symmetries = TablePlane (0.1, 0.1).getSymmetries();
  EXPECT_TRUE (symmetries.discrete.empty() && symmetries.continuous_axes.empty());
}
