// widenToRoundSide() on exact cross-sections (a can lying down seen from either side, flat
// tops that must stay as they are), and fitInstanceBox() on rendered objects lying on a table
// seen at a slant: a can measures its diameter across, as a box of that size does.
#include <mid/segmentation/instance_extent.h>
#include <mid/segmentation/round_side.h>
#include <mid/simulation/box_shape.h>
#include <mid/simulation/cylinder_shape.h>
#include <mid/simulation/frame_io.h>
#include <mid/simulation/procedural_texture.h>
#include <mid/simulation/scene.h>
#include <mid/simulation/scene_renderer.h>
#include <mid/simulation/table_plane.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <vector>

namespace {

using mid::widenToRoundSide;

constexpr float kRadius = 0.035f;
constexpr double kPi = 3.14159265358979323846;

/** The cross-section of a can of kRadius lying on the plane, its axis at `centre` across,
  * as a camera at `elevation` degrees above the plane sees it (the half of the circle turned
  * towards it, from the side of positive positions), points 0.5 deg apart, each moved by up
  * to `noise` (metres) along the circle's normal.
  */
struct Section
{
  std::vector<float> across, heights;
  float low = std::numeric_limits<float>::infinity();
  float high = -std::numeric_limits<float>::infinity();

  void
  add (float position, float height)
  {
    across.push_back (position);
    heights.push_back (height);
    low = std::min (low, position);
    high = std::max (high, position);
  }
};

Section
lyingCan (float centre, double elevation, float noise = 0.0f, int side = 1)
{
  Section section;
  std::mt19937 random (7);
  std::uniform_real_distribution<float> offset (-noise, noise);
  for (double angle = elevation - 90.0; angle <= elevation + 90.0; angle += 0.5) {
    const float radius = kRadius + offset (random);
    const auto a = static_cast<float> (angle * kPi / 180.0);
    section.add (centre + static_cast<float> (side) * radius * std::cos (a),
                 kRadius + radius * std::sin (a));
  }
  return section;
}

/** A box's cross-section `width` across and `height` high, centred at 0, as a camera above
  * the positive side sees it: its flat top and its side face towards the camera, points 1 mm
  * apart.
  */
Section
box (float width, float height)
{
  Section section;
  for (float x = -0.5f * width; x <= 0.5f * width + 1e-6f; x += 0.001f)
    section.add (x, height);
  for (float z = 0.0f; z < height; z += 0.001f)
    section.add (0.5f * width, z);
  return section;
}

TEST (WidenToRoundSide, WidensALyingCanToItsDiameterFromEitherSide)
{
  for (const int side : {1, -1})
    for (const double elevation : {20.0, 35.0, 50.0}) {
      Section section = lyingCan (0.012f, elevation, 0.0f, side);
      ASSERT_LT (section.high - section.low, 2.0f * kRadius - 0.005f);
      EXPECT_TRUE (widenToRoundSide (
          section.across, section.heights, 2.0f * kRadius, section.low, section.high))
          << "elevation " << elevation << ", side " << side;
      EXPECT_NEAR (section.low, 0.012f - kRadius, 0.0006f);
      EXPECT_NEAR (section.high, 0.012f + kRadius, 0.0006f);
    }
}

TEST (WidenToRoundSide, FindsTheRadiusUnderNoiseAndATopMeasuredHigh)
{
  // The height is a high quantile of noisy points: 2 mm too high; the radius is fitted.
  Section section = lyingCan (-0.03f, 35.0, 0.0015f);
  EXPECT_TRUE (widenToRoundSide (section.across,
                                 section.heights,
                                 2.0f * kRadius + 0.002f,
                                 section.low,
                                 section.high));
  EXPECT_NEAR (section.high - section.low, 2.0f * kRadius, 0.001f);
  EXPECT_NEAR (0.5f * (section.low + section.high), -0.03f, 0.0015f);
}

TEST (WidenToRoundSide, LeavesFlatTopsAsTheyAre)
{
  // A square box, a box narrower than high (a cookie box on its side), a can standing up
  // (its top a disc, the section through its middle) and a can seen whole from above.
  for (const auto& [width, height] : {std::pair{0.055f, 0.062f},
                                      std::pair{0.05f, 0.11f},
                                      std::pair{0.066f, 0.162f}}) {
    Section section = box (width, height);
    const float low = section.low, high = section.high;
    EXPECT_FALSE (widenToRoundSide (
        section.across, section.heights, height, section.low, section.high))
        << width << " x " << height;
    EXPECT_EQ (section.low, low);
    EXPECT_EQ (section.high, high);
  }
  Section above = lyingCan (0.0f, 90.0);
  EXPECT_FALSE (widenToRoundSide (
      above.across, above.heights, 2.0f * kRadius, above.low, above.high));
}

TEST (WidenToRoundSide, LeavesABoxSeenAlongItsTopEdgeAsItIs)
{
  // Only a box's top edge and a steep face below it: points near the ridge, most of them
  // close to any circle through it, but reaching far beyond its radius on one side.
  Section section;
  for (float x = 0.0f; x <= 0.005f; x += 0.0005f)
    section.add (x, 0.07f);
  for (float t = 0.0f; t <= 1.0f; t += 0.01f)
    section.add (0.005f + 0.05f * t, 0.07f - 0.01f * t);
  const float low = section.low, high = section.high;
  EXPECT_FALSE (widenToRoundSide (
      section.across, section.heights, 0.07f, section.low, section.high));
  EXPECT_EQ (section.low, low);
  EXPECT_EQ (section.high, high);
}

TEST (WidenToRoundSide, RefusesBadInput)
{
  Section section = lyingCan (0.0f, 35.0);
  float low = section.low, high = section.high;
  std::vector<float> fewer (section.heights.begin() + 1, section.heights.end());
  EXPECT_FALSE (widenToRoundSide (section.across, fewer, 2.0f * kRadius, low, high));
  std::vector<float> nan = section.heights;
  nan[3] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_FALSE (widenToRoundSide (section.across, nan, 2.0f * kRadius, low, high));
  EXPECT_FALSE (widenToRoundSide (section.across,
                                  section.heights,
                                  std::numeric_limits<float>::infinity(),
                                  low,
                                  high));
  float reversed_low = high, reversed_high = low;
  EXPECT_FALSE (widenToRoundSide (
      section.across, section.heights, 2.0f * kRadius, reversed_low, reversed_high));
  EXPECT_EQ (low, section.low);
  EXPECT_EQ (high, section.high);
  std::vector<float> none;
  EXPECT_FALSE (widenToRoundSide (none, none, 2.0f * kRadius, low, high));
}

/** A table tilted by 55 deg about the camera's x axis (seen at 35 deg above it), 0.9 m away,
  * with one object lying on it, its longest axis along the camera's x axis. Returns the
  * object's box (fitInstanceBox() on its pixels) and the table's plane.
  */
mid::InstanceExtent
measureLyingObject (const mid::simulation::Shape::Ptr& shape,
                    const Eigen::Matrix3d& shape_to_table,
                    double height)
{
  mid::simulation::Scene scene;
  const Eigen::Matrix3d tilt =
      Eigen::AngleAxisd (55.0 * kPi / 180.0, Eigen::Vector3d::UnitX())
          .toRotationMatrix();
  Eigen::Isometry3d table_pose = Eigen::Isometry3d::Identity();
  table_pose.linear() = tilt;
  table_pose.translation() = Eigen::Vector3d (0.0, 0.0, 0.9);
  auto table = std::make_shared<mid::simulation::TablePlane> (1.0, 1.0);
  table->setTexture (mid::simulation::makeUniformTexture (cv::Vec3b (120, 120, 120)));
  scene.addBackgroundObject (table, table_pose);
  // The table's normal towards the camera.
  Eigen::Vector3d normal = tilt.col (2);
  if (normal.dot (table_pose.translation()) > 0.0)
    normal = -normal;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = tilt * shape_to_table;
  pose.translation() = table_pose.translation() + 0.5 * height * normal;
  scene.addObject (shape, pose);
  mid::simulation::SceneRenderer renderer;
  mid::simulation::RenderedFrame frame;
  pcl::PointCloud<pcl::PointXYZRGBA> cloud;
  EXPECT_TRUE (renderer.render (scene, frame));
  EXPECT_TRUE (mid::simulation::frameToCloud (frame, 1e-4, cloud));

  const Eigen::Vector3f n = normal.cast<float>();
  const Eigen::Vector4f plane (
      n.x(), n.y(), n.z(), -n.dot (table_pose.translation().cast<float>()));
  pcl::PointCloud<pcl::PointXYZ> organized (cloud.width, cloud.height);
  pcl::Indices surface;
  for (std::size_t p = 0; p < cloud.size(); ++p) {
    organized[p] = pcl::PointXYZ (cloud[p].x, cloud[p].y, cloud[p].z);
    if (std::isfinite (cloud[p].z) &&
        mid::planeDistance (plane, cloud[p].getVector3fMap()) > 0.002f)
      surface.push_back (static_cast<pcl::index_t> (p));
  }
  mid::InstanceExtent extent;
  EXPECT_TRUE (mid::fitInstanceBox (organized, plane, surface, extent));
  return extent;
}

TEST (FitInstanceBox, MeasuresACanLyingDownAcrossItsDiameter)
{
  auto can = std::make_shared<mid::simulation::CylinderShape> (kRadius, 0.16);
  can->setTexture (mid::simulation::makeUniformTexture (cv::Vec3b (200, 200, 200)));
  // The can's axis (model z) along the table's x axis.
  const mid::InstanceExtent extent = measureLyingObject (
      can,
      Eigen::AngleAxisd (0.5 * kPi, Eigen::Vector3d::UnitY()).toRotationMatrix(),
      0.07);
  // Without the round side, 46 mm across: 35 mm + 35 mm * sin (35 deg) = 55 mm seen, less the
  // points that graze the silhouette.
  EXPECT_NEAR (extent.size[0], 2.0f * kRadius, 0.003f);
  EXPECT_NEAR (extent.size[1], 2.0f * kRadius, 0.003f);
  EXPECT_NEAR (extent.size[2], 0.16f, 0.003f);
}

TEST (FitInstanceBox, MeasuresABoxNarrowerThanHighAsItIs)
{
  // A cookie box on its long side: 50 mm across, 110 mm high, 160 mm long.
  auto cookies = std::make_shared<mid::simulation::BoxShape> (0.16, 0.05, 0.11);
  cookies->setTexture (mid::simulation::makeUniformTexture (cv::Vec3b (200, 200, 200)));
  const mid::InstanceExtent extent =
      measureLyingObject (cookies, Eigen::Matrix3d::Identity(), 0.11);
  EXPECT_NEAR (extent.size[0], 0.05f, 0.003f);
  EXPECT_NEAR (extent.size[1], 0.11f, 0.003f);
  EXPECT_NEAR (extent.size[2], 0.16f, 0.003f);
}

} // namespace
