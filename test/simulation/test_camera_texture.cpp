#include <mid/simulation/deterministic_random.h>
#include <mid/simulation/pinhole_camera.h>
#include <mid/simulation/procedural_texture.h>
#include <mid/simulation/texture.h>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include <cmath>
#include <vector>

using namespace mid::simulation;

TEST (SimulationCamera, DefaultsAreAKinectLikeVgaCamera)
{
  const PinholeCamera camera;
  EXPECT_EQ (camera.width, 640);
  EXPECT_EQ (camera.height, 480);
  EXPECT_EQ (camera.fx, 538.0);
  EXPECT_EQ (camera.fy, 538.0);
  EXPECT_EQ (camera.cx, 319.5);
  EXPECT_EQ (camera.cy, 239.5);
  std::string problem;
  EXPECT_TRUE (validateCamera (camera, problem)) << problem;
}

TEST (SimulationCamera, ProjectionInvertsThePixelRay)
{
  const PinholeCamera camera;
  const Eigen::Vector3d point = 1.7 * pixelRay (camera, 100.25, 400.5);
  Eigen::Vector2d pixel;
  ASSERT_TRUE (projectPoint (camera, point, pixel));
  EXPECT_NEAR (pixel.x(), 100.25, 1e-9);
  EXPECT_NEAR (pixel.y(), 400.5, 1e-9);
  EXPECT_FALSE (projectPoint (camera, Eigen::Vector3d (0.0, 0.0, -1.0), pixel));
  // The principal point's ray is the optical axis.
  EXPECT_TRUE (
      pixelRay (camera, camera.cx, camera.cy).isApprox (Eigen::Vector3d::UnitZ()));
}

TEST (SimulationCamera, IntrinsicsForTheIoModule)
{
  PinholeCamera camera;
  camera.fx = 500.0;
  const mid::io::CameraIntrinsics intrinsics = toCameraIntrinsics (camera, 0.0001);
  EXPECT_EQ (intrinsics.fx, 500.0);
  EXPECT_EQ (intrinsics.cy, camera.cy);
  EXPECT_EQ (intrinsics.depth_scale, 0.0001);
}

TEST (SimulationTexture, BilinearSamplingHitsTexelCentresExactly)
{
  cv::Mat texture (2, 2, CV_8UC3);
  texture.at<cv::Vec3b> (0, 0) = cv::Vec3b (0, 0, 0);
  texture.at<cv::Vec3b> (0, 1) = cv::Vec3b (100, 200, 50);
  texture.at<cv::Vec3b> (1, 0) = cv::Vec3b (20, 20, 20);
  texture.at<cv::Vec3b> (1, 1) = cv::Vec3b (60, 60, 60);
  // Texel (1, 0) has its centre at s = 0.75, t = 0.25.
  const cv::Vec3f exact = sampleBilinear (texture, 0.75, 0.25);
  EXPECT_FLOAT_EQ (exact[0], 100.0f);
  EXPECT_FLOAT_EQ (exact[1], 200.0f);
  EXPECT_FLOAT_EQ (exact[2], 50.0f);
  // Halfway between the two top texels.
  const cv::Vec3f middle = sampleBilinear (texture, 0.5, 0.25);
  EXPECT_FLOAT_EQ (middle[0], 50.0f);
  EXPECT_FLOAT_EQ (middle[1], 100.0f);
  // Centre of the image: the mean of all four.
  EXPECT_FLOAT_EQ (sampleBilinear (texture, 0.5, 0.5)[0], 45.0f);
  // Clamp keeps the border texel, repeat wraps around to the other side.
  EXPECT_FLOAT_EQ (sampleBilinear (texture, -3.0, 0.25)[1], 0.0f);
  EXPECT_FLOAT_EQ (sampleBilinear (texture, 1.75, 0.25, TextureWrap::REPEAT)[1],
                   200.0f);
  EXPECT_FLOAT_EQ (sampleBilinear (texture, 1.0, 0.25, TextureWrap::REPEAT)[1], 100.0f);
}

TEST (SimulationTexture, ConversionAndChecks)
{
  std::string problem;
  EXPECT_FALSE (checkTexture (cv::Mat(), problem));
  EXPECT_FALSE (problem.empty());
  EXPECT_FALSE (checkTexture (cv::Mat (4, 4, CV_32FC3), problem));
  const cv::Mat gray (3, 5, CV_8UC1, cv::Scalar (77));
  const cv::Mat converted = toTexture (gray);
  ASSERT_TRUE (checkTexture (converted, problem)) << problem;
  EXPECT_EQ (converted.at<cv::Vec3b> (2, 4), cv::Vec3b (77, 77, 77));
}

TEST (SimulationTexture, ProceduralTexturesAreDeterministic)
{
  const cv::Mat a = makeNoiseTexture (
      64, 48, 16.0, 8.0, cv::Vec3b (0, 0, 0), cv::Vec3b (255, 255, 255), 7);
  const cv::Mat b = makeNoiseTexture (
      64, 48, 16.0, 8.0, cv::Vec3b (0, 0, 0), cv::Vec3b (255, 255, 255), 7);
  const cv::Mat c = makeNoiseTexture (
      64, 48, 16.0, 8.0, cv::Vec3b (0, 0, 0), cv::Vec3b (255, 255, 255), 8);
  ASSERT_EQ (a.type(), CV_8UC3);
  EXPECT_EQ (cv::norm (a, b, cv::NORM_INF), 0.0);
  EXPECT_GT (cv::norm (a, c, cv::NORM_INF), 0.0);
  EXPECT_TRUE (makeNoiseTexture (0, 10, 1.0, 1.0, {}, {}, 1).empty());

  const cv::Mat board =
      makeCheckerboardTexture (3, 2, 4, cv::Vec3b (1, 2, 3), cv::Vec3b (9, 9, 9));
  ASSERT_EQ (board.size(), cv::Size (12, 8));
  EXPECT_EQ (board.at<cv::Vec3b> (0, 0), cv::Vec3b (1, 2, 3));
  EXPECT_EQ (board.at<cv::Vec3b> (0, 4), cv::Vec3b (9, 9, 9));
  EXPECT_EQ (board.at<cv::Vec3b> (4, 4), cv::Vec3b (1, 2, 3));
}

TEST (SimulationRandom, SeedsAndStreamsAreReproducibleAndIndependent)
{
  DeterministicRandom a (42), b (42), c (43), d (42, 1);
  std::vector<std::uint32_t> first, second;
  bool differs_seed = false, differs_stream = false;
  for (int i = 0; i < 100; ++i) {
    const std::uint32_t value = a.next();
    EXPECT_EQ (value, b.next());
    differs_seed = differs_seed || value != c.next();
    differs_stream = differs_stream || value != d.next();
  }
  EXPECT_TRUE (differs_seed);
  EXPECT_TRUE (differs_stream);
}

TEST (SimulationRandom, NormalNumbersHaveUnitVariance)
{
  DeterministicRandom random (5);
  const int count = 200000;
  double sum = 0.0, sum_squared = 0.0;
  for (int i = 0; i < count; ++i) {
    const double value = random.normal();
    sum += value;
    sum_squared += value * value;
  }
  const double mean = sum / count;
  EXPECT_NEAR (mean, 0.0, 0.01);
  EXPECT_NEAR (std::sqrt (sum_squared / count - mean * mean), 1.0, 0.01);
  for (int i = 0; i < 1000; ++i) {
    const double value = random.uniform();
    EXPECT_GE (value, 0.0);
    EXPECT_LT (value, 1.0);
    const int index = random.uniformInt (7);
    EXPECT_GE (index, 0);
    EXPECT_LT (index, 7);
  }
}
