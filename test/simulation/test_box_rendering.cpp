#include "simulation_test_utils.h"

#include <mid/simulation/scene_renderer.h>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace mid::simulation;
using mid::simulation::test::makeColoredBox;
using mid::simulation::test::makePose;

namespace {

const cv::Vec3b kTopLeft (0, 0, 255);
const cv::Vec3b kTopRight (0, 255, 0);
const cv::Vec3b kBottomLeft (255, 0, 0);
const cv::Vec3b kBottomRight (255, 255, 255);

/** 20 x 20 texture with one colour per quadrant. */
cv::Mat
makeQuadrantTexture ()
{
  cv::Mat texture (20, 20, CV_8UC3);
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 20; ++x)
      texture.at<cv::Vec3b> (y, x) = y < 10 ? (x < 10 ? kTopLeft : kTopRight)
                                            : (x < 10 ? kBottomLeft : kBottomRight);
  return texture;
}

/** Render with unshaded colour (ambient 1) so that pixels show the texture exactly. */
RenderedFrame
renderUnshaded (const Scene& scene)
{
  SceneRenderer renderer;
  renderer.setAmbient (1.0);
  RenderedFrame frame;
  EXPECT_TRUE (renderer.render (scene, frame));
  return frame;
}

cv::Vec3b
colorAt (const RenderedFrame& frame, const Eigen::Vector3d& point)
{
  Eigen::Vector2d pixel;
  EXPECT_TRUE (projectPoint (frame.camera, point, pixel));
  return frame.color.at<cv::Vec3b> (static_cast<int> (std::lround (pixel.y())),
                                    static_cast<int> (std::lround (pixel.x())));
}

} // namespace

TEST (SimulationBox, FaceOnBoxGivesItsExactDistance)
{
  Scene scene;
  scene.addObject (makeColoredBox (0.2, 0.1, 0.1),
                   makePose (Eigen::Vector3d (0.0, 0.0, 1.05)));
  SceneRenderer renderer;
  RenderedFrame frame;
  ASSERT_TRUE (renderer.render (scene, frame));
  ASSERT_EQ (frame.depth.type(), CV_32FC1);
  ASSERT_EQ (frame.color.type(), CV_8UC3);
  ASSERT_EQ (frame.instances.type(), CV_32SC1);
  ASSERT_EQ (frame.depth.size(), cv::Size (640, 480));
  // The front face (z = 1.05 - 0.05) is parallel to the image: every pixel on it has z = 1.
  EXPECT_EQ (frame.depth.at<float> (240, 320), 1.0f);
  EXPECT_EQ (frame.depth.at<float> (239, 319), 1.0f);
  EXPECT_EQ (frame.depth.at<float> (260, 360), 1.0f);
  EXPECT_EQ (frame.instances.at<int> (240, 320), 0);
  const cv::Vec3f normal = frame.normals.at<cv::Vec3f> (240, 320);
  EXPECT_FLOAT_EQ (normal[2], -1.0f);
  // Nothing else in the scene.
  EXPECT_EQ (frame.depth.at<float> (10, 10), 0.0f);
  EXPECT_EQ (frame.instances.at<int> (10, 10), -1);
  EXPECT_EQ (frame.normals.at<cv::Vec3f> (10, 10), cv::Vec3f (0.0f, 0.0f, 0.0f));
  EXPECT_EQ (frame.color.at<cv::Vec3b> (10, 10), scene.getBackgroundColor());
}

TEST (SimulationBox, ProjectedCornersBoundTheInstanceMask)
{
  const Eigen::Vector3d size (0.12, 0.08, 0.2);
  Eigen::Isometry3d pose = makePose (
      Eigen::Vector3d (0.05, -0.03, 0.9), 0.7, Eigen::Vector3d (0.3, 1.0, 0.2));
  pose.rotate (Eigen::AngleAxisd (0.4, Eigen::Vector3d::UnitX()));
  Scene scene;
  scene.addObject (makeColoredBox (size.x(), size.y(), size.z()), pose);
  SceneRenderer renderer;
  RenderedFrame frame;
  ASSERT_TRUE (renderer.render (scene, frame));

  double u_min = std::numeric_limits<double>::max(), v_min = u_min;
  double u_max = -u_min, v_max = -u_min;
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d model (0.5 * size.x() * ((corner & 1) ? 1 : -1),
                                 0.5 * size.y() * ((corner & 2) ? 1 : -1),
                                 0.5 * size.z() * ((corner & 4) ? 1 : -1));
    Eigen::Vector2d pixel;
    ASSERT_TRUE (projectPoint (frame.camera, pose * model, pixel));
    u_min = std::min (u_min, pixel.x());
    u_max = std::max (u_max, pixel.x());
    v_min = std::min (v_min, pixel.y());
    v_max = std::max (v_max, pixel.y());
  }
  ASSERT_EQ (frame.instance_stats.size(), 1u);
  const InstanceStats& stats = frame.instance_stats[0];
  ASSERT_GT (stats.visible_pixels, 1000);
  EXPECT_NEAR (stats.bbox.x, u_min, 1.0);
  EXPECT_NEAR (stats.bbox.y, v_min, 1.0);
  EXPECT_NEAR (stats.bbox.x + stats.bbox.width - 1, u_max, 1.0);
  EXPECT_NEAR (stats.bbox.y + stats.bbox.height - 1, v_max, 1.0);
  EXPECT_EQ (cv::countNonZero (frame.instances == 0), stats.visible_pixels);
}

TEST (SimulationBox, BackProjectedPointsLieOnTheBoxSurface)
{
  const auto box = makeColoredBox (0.15, 0.1, 0.07);
  const Eigen::Isometry3d pose = makePose (
      Eigen::Vector3d (-0.08, 0.04, 0.75), 2.1, Eigen::Vector3d (1.0, -0.5, 0.4));
  Scene scene;
  scene.addObject (box, pose);
  SceneRenderer renderer;
  RenderedFrame frame;
  ASSERT_TRUE (renderer.render (scene, frame));
  const Eigen::Isometry3d camera_to_model = pose.inverse();
  int checked = 0;
  for (int v = 0; v < frame.depth.rows; ++v)
    for (int u = 0; u < frame.depth.cols; ++u) {
      const float z = frame.depth.at<float> (v, u);
      if (frame.instances.at<int> (v, u) != 0) {
        EXPECT_EQ (z, 0.0f);
        continue;
      }
      const Eigen::Vector3d point = z * pixelRay (frame.camera, u, v);
      ASSERT_NEAR (box->signedDistance (camera_to_model * point), 0.0, 1e-6)
          << "pixel " << u << ", " << v;
      // The normal is the model normal of the face the point is on, facing the camera.
      const cv::Vec3f n = frame.normals.at<cv::Vec3f> (v, u);
      EXPECT_LT (n[0] * point.x() + n[1] * point.y() + n[2] * point.z(), 0.0);
      ++checked;
    }
  EXPECT_GT (checked, 2000);
}

TEST (SimulationBox, TextureIsUprightUnmirroredAndAtMetricScale)
{
  // Front face (-z) of an unrotated box: its texture right is +x, down is +y, like the image.
  auto box = makeColoredBox (0.2, 0.1, 0.1);
  box->setFaceTexture (BoxShape::NEG_Z, makeQuadrantTexture());
  Scene scene;
  scene.addObject (box, makePose (Eigen::Vector3d (0.0, 0.0, 1.05)));
  RenderedFrame frame = renderUnshaded (scene);
  EXPECT_EQ (colorAt (frame, Eigen::Vector3d (-0.05, -0.025, 1.0)), kTopLeft);
  EXPECT_EQ (colorAt (frame, Eigen::Vector3d (0.05, -0.025, 1.0)), kTopRight);
  EXPECT_EQ (colorAt (frame, Eigen::Vector3d (-0.05, 0.025, 1.0)), kBottomLeft);
  EXPECT_EQ (colorAt (frame, Eigen::Vector3d (0.05, 0.025, 1.0)), kBottomRight);
  // The texture spans exactly the face: 0.2 m at 1 m is 107.6 pixels.
  EXPECT_EQ (frame.instance_stats[0].bbox.width, 108);
  EXPECT_EQ (colorAt (frame, Eigen::Vector3d (-0.098, -0.048, 1.0)), kTopLeft);
  EXPECT_EQ (colorAt (frame, Eigen::Vector3d (0.098, 0.048, 1.0)), kBottomRight);

  // The "front" face -y, seen by a camera looking along +y with model z up.
  Eigen::Isometry3d upright = Eigen::Isometry3d::Identity();
  upright.linear() << 1, 0, 0, //
      0, 0, -1,                //
      0, 1, 0; // model x -> right, y -> forward, z -> up (-y of the camera)
  upright.translation() = Eigen::Vector3d (0.0, 0.0, 1.05);
  box->setFaceTexture (BoxShape::NEG_Y, makeQuadrantTexture());
  scene.clear();
  scene.addObject (box, upright);
  frame = renderUnshaded (scene);
  // The -y face is 0.2 (x) by 0.1 (z) and lies at camera depth 1.05 - 0.05.
  EXPECT_EQ (colorAt (frame, Eigen::Vector3d (-0.05, -0.025, 1.0)), kTopLeft);
  EXPECT_EQ (colorAt (frame, Eigen::Vector3d (0.05, -0.025, 1.0)), kTopRight);
  EXPECT_EQ (colorAt (frame, Eigen::Vector3d (-0.05, 0.025, 1.0)), kBottomLeft);
  EXPECT_EQ (colorAt (frame, Eigen::Vector3d (0.05, 0.025, 1.0)), kBottomRight);
}

TEST (SimulationBox, LambertianShadingFollowsTheLight)
{
  auto box = std::make_shared<BoxShape> (0.2, 0.2, 0.2);
  box->setTexture (makeUniformTexture (cv::Vec3b (200, 100, 50)));
  Scene scene;
  scene.addObject (box, makePose (Eigen::Vector3d (0.0, 0.0, 1.1)));
  SceneRenderer renderer;
  renderer.setAmbient (0.5);
  RenderedFrame frame;
  // Light from the camera: the front face gets full intensity.
  renderer.setLightDirection (Eigen::Vector3d (0.0, 0.0, -2.0));
  ASSERT_TRUE (renderer.render (scene, frame));
  EXPECT_EQ (frame.color.at<cv::Vec3b> (240, 320), cv::Vec3b (200, 100, 50));
  // Light from the side: ambient only.
  renderer.setLightDirection (Eigen::Vector3d (1.0, 0.0, 0.0));
  ASSERT_TRUE (renderer.render (scene, frame));
  EXPECT_EQ (frame.color.at<cv::Vec3b> (240, 320), cv::Vec3b (100, 50, 25));
}
