#include "simulation_test_utils.h"

#include <mid/simulation/cylinder_shape.h>
#include <mid/simulation/scene_renderer.h>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include <cmath>

using namespace mid::simulation;
using mid::simulation::test::facingPlanePose;
using mid::simulation::test::makeColoredBox;
using mid::simulation::test::makeFacingPlane;
using mid::simulation::test::makePose;

TEST (SimulationScene, NearerObjectWinsWhateverTheOrder)
{
  const auto near_box = makeColoredBox (0.1, 0.1, 0.1);
  const auto far_box = makeColoredBox (0.3, 0.3, 0.1);
  const Eigen::Isometry3d near_pose = makePose (Eigen::Vector3d (0.0, 0.0, 0.8));
  const Eigen::Isometry3d far_pose = makePose (Eigen::Vector3d (0.02, 0.0, 1.2));
  SceneRenderer renderer;

  Scene near_first;
  near_first.addObject (near_box, near_pose);
  near_first.addObject (far_box, far_pose);
  RenderedFrame frame;
  ASSERT_TRUE (renderer.render (near_first, frame));
  EXPECT_EQ (frame.instances.at<int> (240, 320), 0);
  EXPECT_FLOAT_EQ (frame.depth.at<float> (240, 320), 0.75f);
  // Beside the near box, the far one shows at its front face depth.
  EXPECT_EQ (frame.instances.at<int> (240, 380), 1);
  EXPECT_FLOAT_EQ (frame.depth.at<float> (240, 380), 1.15f);
  const int near_pixels = frame.instance_stats[0].visible_pixels;
  const int far_pixels = frame.instance_stats[1].visible_pixels;

  Scene far_first;
  far_first.addObject (far_box, far_pose);
  far_first.addObject (near_box, near_pose);
  RenderedFrame swapped;
  ASSERT_TRUE (renderer.render (far_first, swapped));
  EXPECT_EQ (cv::norm (frame.depth, swapped.depth, cv::NORM_INF), 0.0);
  EXPECT_EQ (swapped.instances.at<int> (240, 320), 1);
  EXPECT_EQ (swapped.instance_stats[1].visible_pixels, near_pixels);
  EXPECT_EQ (swapped.instance_stats[0].visible_pixels, far_pixels);
  // Occlusion removes the far box's hidden part from its count.
  EXPECT_LT (far_pixels + near_pixels, 200000);
  EXPECT_EQ (cv::countNonZero (frame.instances >= 0), far_pixels + near_pixels);
}

TEST (SimulationScene, TableDepthFollowsThePlaneEquation)
{
  // A table below a camera pitched 20 deg down: its normal (model +z) is up, towards the
  // camera; the plane n . p + d = 0 is hit below the horizon (row 44) only.
  auto table = makeFacingPlane();
  const Eigen::Isometry3d pose =
      makePose (Eigen::Vector3d (0.05, 0.4, 1.0), 1.92, Eigen::Vector3d::UnitX());
  Scene scene;
  scene.addBackgroundObject (table, pose);
  SceneRenderer renderer;
  RenderedFrame frame;
  ASSERT_TRUE (renderer.render (scene, frame));
  const Eigen::Vector3d normal = pose.linear().col (2);
  const double offset = -normal.dot (pose.translation());
  int hits = 0;
  for (int v = 0; v < frame.depth.rows; ++v)
    for (int u = 0; u < frame.depth.cols; ++u) {
      const float z = frame.depth.at<float> (v, u);
      EXPECT_EQ (frame.instances.at<int> (v, u), -1);
      const Eigen::Vector3d ray = pixelRay (frame.camera, u, v);
      const double denominator = normal.dot (ray);
      const double expected = -offset / denominator;
      if (expected > 0.0) {
        ASSERT_GT (z, 0.0f) << "pixel " << u << ", " << v;
        ASSERT_NEAR (z, expected, 1e-6 * expected) << "pixel " << u << ", " << v;
        ++hits;
      }
      else
        ASSERT_EQ (z, 0.0f);
    }
  EXPECT_GT (hits, 100000);
  EXPECT_LT (hits, 640 * 480); // the horizon is in view
  EXPECT_TRUE (frame.instance_stats.empty());
}

TEST (SimulationScene, CylinderPointsLieOnItsSurfaceAndCapsShow)
{
  auto can = std::make_shared<CylinderShape> (0.04, 0.12);
  can->setTexture (makeCheckerboardTexture (
      8, 4, 8, cv::Vec3b (0, 0, 0), cv::Vec3b (255, 255, 255)));
  // Axis tilted towards the camera so that the side and the top cap are both visible.
  const Eigen::Isometry3d pose =
      makePose (Eigen::Vector3d (0.0, 0.02, 0.6), 2.0, Eigen::Vector3d::UnitX());
  Scene scene;
  scene.addObject (can, pose);
  SceneRenderer renderer;
  RenderedFrame frame;
  ASSERT_TRUE (renderer.render (scene, frame));
  const Eigen::Isometry3d camera_to_model = pose.inverse();
  int side = 0, cap = 0;
  for (int v = 0; v < frame.depth.rows; ++v)
    for (int u = 0; u < frame.depth.cols; ++u) {
      if (frame.instances.at<int> (v, u) != 0)
        continue;
      const Eigen::Vector3d model = camera_to_model * (frame.depth.at<float> (v, u) *
                                                       pixelRay (frame.camera, u, v));
      ASSERT_NEAR (can->signedDistance (model), 0.0, 1e-6);
      if (std::abs (std::abs (model.z()) - 0.06) < 1e-6)
        ++cap;
      else
        ++side;
    }
  EXPECT_GT (side, 1000);
  EXPECT_GT (cap, 1000);
  EXPECT_EQ (side + cap, frame.instance_stats[0].visible_pixels);
}

TEST (SimulationScene, EmptySceneShowsTheBackground)
{
  Scene scene;
  scene.setBackgroundColor (cv::Vec3b (1, 2, 3));
  SceneRenderer renderer;
  RenderedFrame frame;
  ASSERT_TRUE (renderer.render (scene, frame));
  EXPECT_EQ (cv::countNonZero (frame.depth), 0);
  EXPECT_EQ (cv::countNonZero (frame.instances != -1), 0);
  EXPECT_EQ (frame.color.at<cv::Vec3b> (100, 100), cv::Vec3b (1, 2, 3));
  EXPECT_TRUE (frame.instance_stats.empty());
}

TEST (SimulationScene, SupersamplingOnlyChangesTheColour)
{
  Scene scene;
  scene.addObject (makeColoredBox (0.1, 0.2, 0.05),
                   makePose (Eigen::Vector3d (0.0, 0.0, 0.7), 0.5));
  scene.addBackgroundObject (makeFacingPlane(), facingPlanePose (1.0));
  // A quarter-VGA camera keeps the 9 rays per pixel quick in debug builds.
  PinholeCamera camera;
  camera.width = 160;
  camera.height = 120;
  camera.fx = camera.fy = 134.5;
  camera.cx = 79.5;
  camera.cy = 59.5;
  SceneRenderer renderer;
  renderer.setCamera (camera);
  RenderedFrame single, multiple;
  ASSERT_TRUE (renderer.render (scene, single));
  renderer.setSupersampling (3);
  ASSERT_TRUE (renderer.render (scene, multiple));
  EXPECT_EQ (cv::norm (single.depth, multiple.depth, cv::NORM_INF), 0.0);
  EXPECT_EQ (cv::countNonZero (single.instances != multiple.instances), 0);
  EXPECT_EQ (single.instance_stats[0].visible_pixels,
             multiple.instance_stats[0].visible_pixels);
  EXPECT_GT (cv::norm (single.color, multiple.color, cv::NORM_L1), 0.0);
  // Inside a uniform face far from edges both agree.
  EXPECT_EQ (single.color.at<cv::Vec3b> (60, 80),
             multiple.color.at<cv::Vec3b> (60, 80));
}

TEST (SimulationScene, SharedShapeInstancesShowTheSameTexture)
{
  auto box = std::make_shared<BoxShape> (0.1, 0.1, 0.1);
  box->setTexture (makeCheckerboardTexture (
      4, 4, 4, cv::Vec3b (10, 20, 30), cv::Vec3b (200, 150, 100)));
  Scene scene;
  scene.addObject (box, makePose (Eigen::Vector3d (-0.15, 0.0, 1.05)));
  scene.addObject (box, makePose (Eigen::Vector3d (0.15, 0.0, 1.05)));
  SceneRenderer renderer;
  renderer.setAmbient (1.0);
  RenderedFrame frame;
  ASSERT_TRUE (renderer.render (scene, frame));
  // Same model point on both front faces -> same colour.
  for (const double x : {-0.03, -0.01, 0.02})
    for (const double y : {-0.04, 0.012, 0.03}) {
      Eigen::Vector2d a, b;
      ASSERT_TRUE (projectPoint (frame.camera, Eigen::Vector3d (-0.15 + x, y, 1.0), a));
      ASSERT_TRUE (projectPoint (frame.camera, Eigen::Vector3d (0.15 + x, y, 1.0), b));
      // The points are at least 4 mm from a square's border: the rounding to whole pixels
      // (under 1 mm) keeps both inside the same square.
      EXPECT_EQ (frame.color.at<cv::Vec3b> (static_cast<int> (std::lround (a.y())),
                                            static_cast<int> (std::lround (a.x()))),
                 frame.color.at<cv::Vec3b> (static_cast<int> (std::lround (b.y())),
                                            static_cast<int> (std::lround (b.x()))));
    }
}
