#include "simulation_test_utils.h"

#include <mid/simulation/scene_renderer.h>
#include <mid/simulation/sensor_model.h>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include <cmath>
#include <cstring>

using namespace mid::simulation;
using mid::simulation::test::facingPlanePose;
using mid::simulation::test::makeColoredBox;
using mid::simulation::test::makeFacingPlane;
using mid::simulation::test::makePose;

namespace {

/** A box at 0.7 m in front of a wall at 1 m. */
RenderedFrame
renderBoxBeforeWall ()
{
  Scene scene;
  scene.addObject (makeColoredBox (0.2, 0.15, 0.1),
                   makePose (Eigen::Vector3d (0.0, 0.0, 0.75), 0.3));
  scene.addBackgroundObject (makeFacingPlane(), facingPlanePose (1.0));
  SceneRenderer renderer;
  RenderedFrame frame;
  EXPECT_TRUE (renderer.render (scene, frame));
  return frame;
}

/** Exact frame of a wall facing the camera at depth z. */
RenderedFrame
renderWall (double z)
{
  Scene scene;
  scene.addBackgroundObject (makeFacingPlane(), facingPlanePose (z));
  SceneRenderer renderer;
  RenderedFrame frame;
  EXPECT_TRUE (renderer.render (scene, frame));
  return frame;
}

double
maxDifference (const cv::Mat& a, const cv::Mat& b)
{
  return cv::norm (a, b, cv::NORM_INF);
}

} // namespace

TEST (SimulationSensor, DefaultModelIsExact)
{
  const RenderedFrame exact = renderBoxBeforeWall();
  RenderedFrame measured;
  ASSERT_TRUE (applySensorModel (exact, SensorModel(), 3, measured));
  EXPECT_EQ (maxDifference (exact.depth, measured.depth), 0.0);
  EXPECT_EQ (maxDifference (exact.color, measured.color), 0.0);
  EXPECT_EQ (maxDifference (exact.instances, measured.instances), 0.0);
}

TEST (SimulationSensor, SameSeedIsBitIdenticalOtherSeedDiffers)
{
  const RenderedFrame exact = renderBoxBeforeWall();
  const SensorModel kinect = kinectSensorModel();
  RenderedFrame a, b, c;
  ASSERT_TRUE (applySensorModel (exact, kinect, 7, a));
  ASSERT_TRUE (applySensorModel (exact, kinect, 7, b));
  ASSERT_TRUE (applySensorModel (exact, kinect, 8, c));
  EXPECT_EQ (std::memcmp (a.depth.data, b.depth.data, a.depth.total() * sizeof (float)),
             0);
  EXPECT_EQ (std::memcmp (a.color.data, b.color.data, a.color.total() * 3), 0);
  EXPECT_GT (maxDifference (a.depth, c.depth), 0.0);
  EXPECT_GT (maxDifference (a.color, c.color), 0.0);
  // Ground truth is untouched.
  EXPECT_EQ (maxDifference (a.instances, exact.instances), 0.0);
  EXPECT_EQ (a.instance_stats[0].visible_pixels,
             exact.instance_stats[0].visible_pixels);

  // In place gives the same result.
  RenderedFrame in_place = exact;
  in_place.depth = exact.depth.clone();
  in_place.color = exact.color.clone();
  ASSERT_TRUE (applySensorModel (in_place, kinect, 7, in_place));
  EXPECT_EQ (maxDifference (a.depth, in_place.depth), 0.0);
  EXPECT_EQ (maxDifference (a.color, in_place.color), 0.0);
}

TEST (SimulationSensor, DepthNoiseFollowsSigmaOfZ)
{
  SensorModel model;
  model.depth_noise = true;
  for (const double z : {0.6, 1.0, 1.5}) {
    const RenderedFrame exact = renderWall (z);
    RenderedFrame measured;
    ASSERT_TRUE (applySensorModel (exact, model, 11, measured));
    double sum = 0.0, sum_squared = 0.0;
    int count = 0;
    for (int v = 0; v < exact.depth.rows; ++v)
      for (int u = 0; u < exact.depth.cols; ++u) {
        ASSERT_GT (measured.depth.at<float> (v, u), 0.0f);
        const double error =
            measured.depth.at<float> (v, u) - exact.depth.at<float> (v, u);
        sum += error;
        sum_squared += error * error;
        ++count;
      }
    const double mean = sum / count;
    const double sigma = std::sqrt (sum_squared / count - mean * mean);
    const double expected = 0.0012 + 0.0019 * (z - 0.4) * (z - 0.4);
    EXPECT_DOUBLE_EQ (depthNoiseSigma (model, z), expected);
    EXPECT_NEAR (sigma, expected, 0.03 * expected) << "z = " << z;
    EXPECT_NEAR (mean, 0.0, 0.02 * expected) << "z = " << z;
  }
}

TEST (SimulationSensor, DepthVanishesBeyondTheMaximumIncidenceAngle)
{
  Scene scene;
  // A wall turned 70 deg about y: incidence goes from about 40 to 100 deg across the image.
  scene.addBackgroundObject (makeFacingPlane(),
                             facingPlanePose (1.0) *
                                 Eigen::AngleAxisd (1.22, Eigen::Vector3d::UnitY()));
  SceneRenderer renderer;
  RenderedFrame exact, measured;
  ASSERT_TRUE (renderer.render (scene, exact));
  SensorModel model;
  model.max_incidence_angle = 78.0;
  ASSERT_TRUE (applySensorModel (exact, model, 1, measured));
  const double limit = std::cos (78.0 * M_PI / 180.0);
  int kept = 0, removed = 0;
  for (int v = 0; v < exact.depth.rows; ++v)
    for (int u = 0; u < exact.depth.cols; ++u) {
      if (exact.depth.at<float> (v, u) == 0.0f)
        continue;
      const cv::Vec3f n = exact.normals.at<cv::Vec3f> (v, u);
      const Eigen::Vector3d ray = pixelRay (exact.camera, u, v).normalized();
      const double cosine = std::abs (n[0] * ray.x() + n[1] * ray.y() + n[2] * ray.z());
      if (std::abs (cosine - limit) < 1e-4)
        continue; // on the border
      const bool should_keep = cosine > limit;
      EXPECT_EQ (measured.depth.at<float> (v, u) > 0.0f, should_keep) << u << ", " << v;
      (should_keep ? kept : removed)++;
    }
  EXPECT_GT (kept, 10000);
  EXPECT_GT (removed, 10000);
}

TEST (SimulationSensor, DiscontinuitiesLoseTheFarSide)
{
  const RenderedFrame exact = renderBoxBeforeWall();
  SensorModel model;
  model.discontinuity_threshold = 0.05;
  RenderedFrame measured;
  ASSERT_TRUE (applySensorModel (exact, model, 1, measured));
  int removed = 0;
  for (int v = 1; v + 1 < exact.depth.rows; ++v)
    for (int u = 1; u + 1 < exact.depth.cols; ++u) {
      const bool on_box = exact.instances.at<int> (v, u) == 0;
      if (on_box) {
        ASSERT_EQ (measured.depth.at<float> (v, u), exact.depth.at<float> (v, u));
        continue;
      }
      const bool next_to_box = exact.instances.at<int> (v, u - 1) == 0 ||
                               exact.instances.at<int> (v, u + 1) == 0 ||
                               exact.instances.at<int> (v - 1, u) == 0 ||
                               exact.instances.at<int> (v + 1, u) == 0;
      ASSERT_EQ (measured.depth.at<float> (v, u) == 0.0f, next_to_box)
          << u << ", " << v;
      removed += next_to_box ? 1 : 0;
    }
  EXPECT_GT (removed, 300);

  // A wider band removes more, still only behind the edge.
  model.discontinuity_width = 3;
  RenderedFrame wide;
  ASSERT_TRUE (applySensorModel (exact, model, 1, wide));
  const cv::Mat box = exact.instances == 0;
  EXPECT_EQ (cv::countNonZero ((wide.depth == 0) & box), 0);
  EXPECT_GT (cv::countNonZero (wide.depth == 0), 2 * removed);
}

TEST (SimulationSensor, QuantizationAndDropout)
{
  const RenderedFrame exact = renderBoxBeforeWall();
  SensorModel model;
  model.disparity_quantization = 0.003;
  RenderedFrame measured;
  ASSERT_TRUE (applySensorModel (exact, model, 1, measured));
  for (int v = 0; v < exact.depth.rows; v += 7)
    for (int u = 0; u < exact.depth.cols; u += 7) {
      const double z = measured.depth.at<float> (v, u);
      ASSERT_GT (z, 0.0);
      const double steps = 1.0 / z / 0.003;
      EXPECT_NEAR (steps, std::round (steps), 1e-3);
      // The step at 1 m is z^2 * 0.003 = 3 mm: the error is at most half of it.
      EXPECT_LE (std::abs (z - exact.depth.at<float> (v, u)),
                 0.5 * 0.003 * z * z * 1.01);
    }

  model = SensorModel();
  model.random_dropout = 0.1;
  ASSERT_TRUE (applySensorModel (exact, model, 1, measured));
  const double fraction = cv::countNonZero (measured.depth == 0) / (640.0 * 480.0);
  EXPECT_NEAR (fraction, 0.1, 0.005);

  model = SensorModel();
  model.hole_count = 10;
  model.hole_max_radius = 8.0;
  ASSERT_TRUE (applySensorModel (exact, model, 1, measured));
  const int holes = cv::countNonZero (measured.depth == 0);
  EXPECT_GT (holes, 0);
  EXPECT_LT (holes, 10 * 4 * 8 * 8);
}

TEST (SimulationSensor, ImageBlurAndNoise)
{
  const RenderedFrame exact = renderBoxBeforeWall();
  SensorModel model;
  model.image_noise_sigma = 3.0;
  RenderedFrame measured;
  ASSERT_TRUE (applySensorModel (exact, model, 1, measured));
  cv::Mat difference;
  cv::subtract (measured.color, exact.color, difference, cv::noArray(), CV_32F);
  cv::Scalar mean, stddev;
  cv::meanStdDev (difference.reshape (1), mean, stddev);
  EXPECT_NEAR (
      stddev[0], 3.0, 0.2); // a little less: saturation at 0 and 255 is rare here
  EXPECT_EQ (maxDifference (exact.depth, measured.depth), 0.0);

  model = SensorModel();
  model.image_blur_sigma = 1.0;
  ASSERT_TRUE (applySensorModel (exact, model, 1, measured));
  EXPECT_GT (maxDifference (exact.color, measured.color), 0.0);
  EXPECT_EQ (maxDifference (exact.depth, measured.depth), 0.0);
}
