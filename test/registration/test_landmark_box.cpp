#include "rigid_motion.h"

#include <mid/registration/landmark_box.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using mid::test::rigidMotion;

/** A model whose landmarks are a 21 x 9 grid over a 100 x 40 mm rectangle in the plane z = 0
  * of a frame moved by `motion` (5 mm apart).
  */
mid::ObjectModel
rectangleModel (const Eigen::Isometry3f& motion)
{
  mid::ObjectModel model;
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j <= 8; ++j) {
      pcl::PointNormal landmark;
      landmark.getVector3fMap() =
          motion * Eigen::Vector3f (-0.05f + 0.005f * static_cast<float> (i),
                                    -0.02f + 0.005f * static_cast<float> (j),
                                    0.0f);
      model.landmarks.push_back (landmark);
    }
  return model;
}

} // namespace

TEST (LandmarkBox, SpansARotatedRectangleAlongItsSides)
{
  const Eigen::Isometry3f motion = rigidMotion (
      Eigen::Vector3f (0.1f, -0.2f, 0.7f), 0.6f, Eigen::Vector3f (1, 2, 3));
  const mid::LandmarkBox box = mid::computeLandmarkBox (rectangleModel (motion), 0.0f);
  ASSERT_TRUE (box.valid);
  // The largest spread along the rectangle's long side, then its short side, then its normal.
  EXPECT_NEAR (std::abs (box.axes.col (0).dot (motion.linear().col (0))), 1.0f, 1e-4f);
  EXPECT_NEAR (std::abs (box.axes.col (1).dot (motion.linear().col (1))), 1.0f, 1e-4f);
  EXPECT_NEAR (std::abs (box.axes.col (2).dot (motion.linear().col (2))), 1.0f, 1e-4f);
  EXPECT_NEAR (box.half_extent[0], 0.05f, 1e-5f);
  EXPECT_NEAR (box.half_extent[1], 0.02f, 1e-5f);
  EXPECT_NEAR (box.half_extent[2], 0.0f, 1e-5f);
  EXPECT_LT ((box.center - motion.translation()).norm(), 1e-5f);

  // Distances outside the box: 1 mm beyond the long side's end, 1 mm off the plane, both;
  // inside, none.
  EXPECT_NEAR (
      box.distanceTo (motion * Eigen::Vector3f (0.051f, 0.0f, 0.0f)), 0.001f, 1e-5f);
  EXPECT_NEAR (
      box.distanceTo (motion * Eigen::Vector3f (0.0f, 0.0f, 0.001f)), 0.001f, 1e-5f);
  EXPECT_NEAR (
      box.distanceTo (motion * Eigen::Vector3f (-0.053f, 0.024f, 0.0f)), 0.005f, 1e-5f);
  EXPECT_EQ (box.distanceTo (motion * Eigen::Vector3f (0.049f, -0.019f, 0.0f)), 0.0f);
}

TEST (LandmarkBox, TrimsAStrayLandmarkAndSkipsNonFiniteOnes)
{
  mid::ObjectModel model = rectangleModel (Eigen::Isometry3f::Identity());
  pcl::PointNormal stray;
  stray.getVector3fMap() = Eigen::Vector3f (0.5f, 0.0f, 0.0f);
  model.landmarks.push_back (stray);
  pcl::PointNormal missing;
  missing.x = std::numeric_limits<float>::quiet_NaN();
  model.landmarks.push_back (missing);

  // Without trimming, the stray landmark 0.5 m away stretches the box; the default 5 % does
  // not reach it (one landmark of 190).
  EXPECT_GT (mid::computeLandmarkBox (model, 0.0f).half_extent[0], 0.2f);
  const mid::LandmarkBox box = mid::computeLandmarkBox (model);
  ASSERT_TRUE (box.valid);
  // The 5th and 95th percentiles of the x coordinates: the second and the second-to-last
  // column of the grid.
  EXPECT_NEAR (box.half_extent[0], 0.045f, 1e-5f);
  EXPECT_GT (box.distanceTo (stray.getVector3fMap()), 0.4f);
}

TEST (LandmarkBox, NeedsThreeLandmarksAndATrimBelowOneHalf)
{
  mid::ObjectModel model = rectangleModel (Eigen::Isometry3f::Identity());
  EXPECT_FALSE (mid::computeLandmarkBox (model, 0.5f).valid);
  EXPECT_FALSE (mid::computeLandmarkBox (model, -0.1f).valid);
  model.landmarks.resize (3);
  EXPECT_TRUE (mid::computeLandmarkBox (model).valid);
  model.landmarks.resize (2);
  const mid::LandmarkBox box = mid::computeLandmarkBox (model);
  EXPECT_FALSE (box.valid);
  EXPECT_EQ (box.distanceTo (Eigen::Vector3f::Zero()),
             std::numeric_limits<float>::infinity());
}
