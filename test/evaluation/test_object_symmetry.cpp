#include "temporary_folder.h"

#include <mid/evaluation/object_symmetry.h>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>

using mid::evaluation::ObjectSymmetries;
using mid::evaluation::symmetricRotationError;

namespace {

Eigen::Matrix3d
turn (double degrees, const Eigen::Vector3d& axis)
{
  return Eigen::AngleAxisd (degrees * M_PI / 180.0, axis.normalized())
      .toRotationMatrix();
}

double
plainAngle (const Eigen::Matrix3d& a, const Eigen::Matrix3d& b)
{
  return Eigen::AngleAxisd (a.transpose() * b).angle() * 180.0 / M_PI;
}

/** A seeded random rotation. */
Eigen::Matrix3d
randomRotation (std::mt19937& random)
{
  std::normal_distribution<double> normal;
  Eigen::Quaterniond q (
      normal (random), normal (random), normal (random), normal (random));
  return q.normalized().toRotationMatrix();
}

/** The half turns about the axes: a box of three different sizes. */
ObjectSymmetries
boxOfThreeSizes ()
{
  ObjectSymmetries box;
  for (const Eigen::Vector3d axis :
       {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ()})
    box.discrete.push_back (turn (180.0, axis));
  return box;
}

/** Any turn about z and the half turn about x: a cylinder. */
ObjectSymmetries
cylinder ()
{
  ObjectSymmetries can;
  can.continuous_axes = {Eigen::Vector3d::UnitZ()};
  can.discrete.push_back (turn (180.0, Eigen::Vector3d::UnitX()));
  return can;
}

} // namespace

TEST (ObjectSymmetry, WithoutSymmetriesTheErrorIsThePlainAngle)
{
  std::mt19937 random (7);
  for (int i = 0; i < 20; ++i) {
    const Eigen::Matrix3d a = randomRotation (random), b = randomRotation (random);
    EXPECT_NEAR (
        symmetricRotationError (a, b, ObjectSymmetries()), plainAngle (a, b), 1e-6);
  }
}

TEST (ObjectSymmetry, ATurnOfTheShapeOntoItselfIsNoError)
{
  std::mt19937 random (11);
  const Eigen::Matrix3d truth = randomRotation (random);
  // 7 deg about an axis across the cylinder's: no turn about its axis makes up for it.
  const Eigen::Matrix3d small = turn (7.0, Eigen::Vector3d (1.0, 2.0, 0.0));
  // Box: a half turn about z, then 7 deg off: 7 deg; a quarter turn is no symmetry of it.
  EXPECT_NEAR (
      symmetricRotationError (truth * turn (180.0, Eigen::Vector3d::UnitZ()) * small,
                              truth,
                              boxOfThreeSizes()),
      7.0,
      1e-6);
  EXPECT_NEAR (symmetricRotationError (truth * turn (90.0, Eigen::Vector3d::UnitZ()),
                                       truth,
                                       boxOfThreeSizes()),
               90.0,
               1e-6);
  // Cylinder: any turn about its axis, also after flipping its caps, then 7 deg off.
  for (const double degrees : {0.0, 33.0, 151.0, 290.0}) {
    const Eigen::Matrix3d about = turn (degrees, Eigen::Vector3d::UnitZ());
    EXPECT_NEAR (
        symmetricRotationError (truth * about * small, truth, cylinder()), 7.0, 1e-6);
    EXPECT_NEAR (symmetricRotationError (
                     truth * turn (180.0, Eigen::Vector3d::UnitX()) * about * small,
                     truth,
                     cylinder()),
                 7.0,
                 1e-6);
  }
  // A quarter turn across the cylinder's axis stays a quarter turn.
  EXPECT_NEAR (symmetricRotationError (
                   truth * turn (90.0, Eigen::Vector3d::UnitY()), truth, cylinder()),
               90.0,
               1e-6);
  // Two different axes: every orientation is the shape's (a sphere).
  ObjectSymmetries sphere;
  sphere.continuous_axes = {Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX()};
  EXPECT_EQ (symmetricRotationError (randomRotation (random), truth, sphere), 0.0);
}

TEST (ObjectSymmetry, TheContinuousMinimumMatchesASearchOverTheTurn)
{
  std::mt19937 random (5);
  const ObjectSymmetries can = cylinder();
  for (int i = 0; i < 10; ++i) {
    const Eigen::Matrix3d a = randomRotation (random), b = randomRotation (random);
    double searched = 180.0;
    for (int step = 0; step < 36000; ++step) {
      const Eigen::Matrix3d about = turn (0.01 * step, Eigen::Vector3d::UnitZ());
      searched = std::min ({searched,
                            plainAngle (a, b * about),
                            plainAngle (a, b * can.discrete[0] * about)});
    }
    EXPECT_NEAR (symmetricRotationError (a, b, can), searched, 0.01);
  }
}

TEST (ObjectSymmetry, ReadsBopModelsInfoAndRefusesBadEntries)
{
  const mid::test::TemporaryFolder folder;
  const std::string path = folder.file ("models_info.json");
  std::ofstream (path) << R"({
    "1": {"diameter": 100, "symmetries_discrete": [[-1, 0, 0, 5, 0, -1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]]},
    "2": {"diameter": 80, "symmetries_continuous": [{"axis": [0, 0, 2], "offset": [0, 0, 0]}]},
    "7": {"diameter": 50}})";
  mid::evaluation::ObjectSymmetryTable table;
  ASSERT_TRUE (mid::evaluation::loadBopModelSymmetries (path, table));
  ASSERT_EQ (table.size(), 3u);
  ASSERT_EQ (table.at (1).discrete.size(), 1u);
  EXPECT_TRUE (
      table.at (1).discrete[0].isApprox (turn (180.0, Eigen::Vector3d::UnitZ())));
  EXPECT_TRUE (table.at (1).continuous_axes.empty());
  ASSERT_EQ (table.at (2).continuous_axes.size(), 1u);
  EXPECT_TRUE (table.at (2).continuous_axes[0].isApprox (Eigen::Vector3d::UnitZ()));
  EXPECT_TRUE (table.at (7).discrete.empty() && table.at (7).continuous_axes.empty());

  for (
      const char* bad :
      {R"({"1": {"symmetries_discrete": [[1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0]]}})",
       R"({"1": {"symmetries_discrete": [[2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1]]}})",
       R"({"1": {"symmetries_discrete": [[1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1]]}})",
       R"({"1": {"symmetries_continuous": [{"axis": [0, 0, 0], "offset": [0, 0, 0]}]}})",
       R"({"1": {"symmetries_continuous": [{"offset": [0, 0, 0]}]}})",
       R"({"one": {"diameter": 10}})",
       R"([1, 2])",
       "{ not json"}) {
    std::ofstream (path) << bad;
    table[3] = ObjectSymmetries();
    EXPECT_FALSE (mid::evaluation::loadBopModelSymmetries (path, table)) << bad;
    EXPECT_TRUE (table.empty()) << bad;
  }
  EXPECT_FALSE (
      mid::evaluation::loadBopModelSymmetries (folder.file ("missing.json"), table));
}
