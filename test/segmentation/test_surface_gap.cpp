#include "plate_surface.h"

#include <mid/segmentation/surface_gap.h>

#include <gtest/gtest.h>

#include <cmath>

namespace {

using mid::test::Plate;
using mid::test::plateSurfacePixel;
using mid::test::renderPlates;

constexpr float kTop = 0.1f, kFloor = 0.13f;

/** Two keypoints on top of plates at height kTop, 6 cm apart at 0.9 m. */
const Eigen::Vector3f kLeft (-0.03f, kTop, 0.9f), kRight (0.03f, kTop, 0.9f);

/** The surface of `cloud` with the keypoints kLeft (0) and kRight (1). */
mid::KeypointSurface
surfaceOf (const pcl::PointCloud<pcl::PointXYZ>::Ptr& cloud)
{
  return {cloud, {plateSurfacePixel (kLeft), plateSurfacePixel (kRight)}};
}

} // namespace

TEST (SurfaceGap, FindsTheFloorBetweenTwoObjects)
{
  // Two plates 4 cm apart, 3 cm above the floor: a ray through the middle of the segment
  // (0, kTop, 0.9) goes on to the floor, kFloor / kTop times as far. The drop is measured
  // along the ray: in depth (z) alone it would be 0.6 % smaller, outside the 0.5 % band
  // (the keypoints' pixel row, 0.3 % off the segment, is inside it).
  const auto surface = surfaceOf (renderPlates (
      {{-0.08f, -0.02f, 0.8f, 1.0f, kTop}, {0.02f, 0.08f, 0.8f, 1.0f, kTop}}, kFloor));
  const float drop = (kFloor / kTop - 1.0f) * Eigen::Vector3f (0.0f, kTop, 0.9f).norm();
  EXPECT_TRUE (mid::surfaceDropsBetween (surface, 0, 1, 0.01f));
  EXPECT_TRUE (mid::surfaceDropsBetween (surface, 1, 0, 0.995f * drop));
  EXPECT_FALSE (mid::surfaceDropsBetween (surface, 0, 1, 1.005f * drop));
}

TEST (SurfaceGap, OneObjectsSurfaceDoesNotDrop)
{
  // One plate under both keypoints: flat between them.
  const auto flat =
      surfaceOf (renderPlates ({{-0.08f, 0.08f, 0.8f, 1.0f, kTop}}, kFloor));
  EXPECT_FALSE (mid::surfaceDropsBetween (flat, 0, 1, 0.001f));

  // A ball (radius 5 cm at 0.9 m): its visible surface lies in front of every chord.
  const Eigen::Vector3f centre (0.0f, 0.0f, 0.9f);
  const float radius = 0.05f;
  auto ball = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>> (
      mid::test::kPlateWidth, mid::test::kPlateHeight);
  for (int v = 0; v < mid::test::kPlateHeight; ++v)
    for (int u = 0; u < mid::test::kPlateWidth; ++u) {
      const Eigen::Vector3f ray =
          Eigen::Vector3f (
              (static_cast<float> (u) - mid::test::kPlateCx) / mid::test::kPlateFocal,
              (static_cast<float> (v) - mid::test::kPlateCy) / mid::test::kPlateFocal,
              1.0f)
              .normalized();
      const float along = ray.dot (centre),
                  discriminant = along * along - centre.squaredNorm() + radius * radius;
      pcl::PointXYZ& point =
          (*ball) (static_cast<std::size_t> (u), static_cast<std::size_t> (v));
      if (discriminant >= 0.0f)
        point.getVector3fMap() = (along - std::sqrt (discriminant)) * ray;
      else
        point.x = point.y = point.z = NAN;
    }
  const Eigen::Vector3f a = centre +
                            radius * Eigen::Vector3f (-0.8f, 0.3f, -0.52f).normalized(),
                        b = centre +
                            radius * Eigen::Vector3f (0.7f, -0.2f, -0.68f).normalized();
  const mid::KeypointSurface on_ball{ball,
                                     {plateSurfacePixel (a), plateSurfacePixel (b)}};
  ASSERT_TRUE (mid::isValidKeypointSurface (on_ball, 2));
  EXPECT_FALSE (mid::surfaceDropsBetween (on_ball, 0, 1, 0.001f));
}

TEST (SurfaceGap, IgnoresMissingDepth)
{
  auto cloud = renderPlates ({{-0.08f, 0.08f, 0.8f, 1.0f, kTop}}, kFloor);
  const auto surface = surfaceOf (cloud);
  const int width = mid::test::kPlateWidth;
  const pcl::index_t left = surface.keypoint_pixels[0],
                     right = surface.keypoint_pixels[1];
  ASSERT_EQ (left / width, right / width); // the row between them (same v)
  ASSERT_GT (right - left, 10);
  for (pcl::index_t p = left + 1; p < right; ++p)
    (*cloud)[static_cast<std::size_t> (p)].z = NAN;
  EXPECT_FALSE (mid::surfaceDropsBetween (surface, 0, 1, 0.001f, 1));
  // An end without depth gives no answer either.
  (*cloud)[static_cast<std::size_t> (right)].z = NAN;
  EXPECT_FALSE (mid::surfaceDropsBetween (surface, 0, 1, 0.001f, 1));
}

TEST (SurfaceGap, MissingDepthDoesNotBreakARunOfFloor)
{
  // Two plates 4 cm apart; every second pixel of the floor between them has no depth. The
  // floor pixels left still make a run: a gap seen through a noisy sensor.
  auto cloud = renderPlates (
      {{-0.08f, -0.02f, 0.8f, 1.0f, kTop}, {0.02f, 0.08f, 0.8f, 1.0f, kTop}}, kFloor);
  const auto surface = surfaceOf (cloud);
  const pcl::index_t left = surface.keypoint_pixels[0],
                     right = surface.keypoint_pixels[1];
  int floor_pixels = 0;
  for (pcl::index_t p = left + 1; p < right; ++p) {
    pcl::PointXYZ& point = (*cloud)[static_cast<std::size_t> (p)];
    if (point.y > kTop + 0.01f && ++floor_pixels % 2 == 0)
      point.z = NAN;
  }
  ASSERT_GT (floor_pixels, 10);
  EXPECT_TRUE (mid::surfaceDropsBetween (surface, 0, 1, 0.01f, floor_pixels / 2));
  EXPECT_FALSE (mid::surfaceDropsBetween (surface, 0, 1, 0.01f, floor_pixels / 2 + 2));
}

TEST (SurfaceGap, ALonePixelBehindIsNotAGap)
{
  // One plate under both keypoints, with one or three pixels between them reading the
  // floor's depth (a flying pixel, then a narrow slit).
  auto cloud = renderPlates ({{-0.08f, 0.08f, 0.8f, 1.0f, kTop}}, kFloor);
  const auto surface = surfaceOf (cloud);
  const int width = mid::test::kPlateWidth;
  // On one row, middle - 1 .. middle + 1 lie on the line between the keypoints.
  ASSERT_EQ (surface.keypoint_pixels[0] / width, surface.keypoint_pixels[1] / width);
  ASSERT_GT (surface.keypoint_pixels[1] - surface.keypoint_pixels[0], 10);
  const auto middle = static_cast<std::size_t> (
      (surface.keypoint_pixels[0] + surface.keypoint_pixels[1]) / 2);
  const auto seeFloor = [&cloud] (std::size_t p) {
    (*cloud)[p].getVector3fMap() *= kFloor / kTop;
  };
  seeFloor (middle);
  EXPECT_FALSE (mid::surfaceDropsBetween (surface, 0, 1, 0.01f));
  EXPECT_TRUE (mid::surfaceDropsBetween (surface, 0, 1, 0.01f, 1));
  seeFloor (middle + 1);
  EXPECT_FALSE (mid::surfaceDropsBetween (surface, 0, 1, 0.01f));
  seeFloor (middle - 1);
  EXPECT_TRUE (mid::surfaceDropsBetween (surface, 0, 1, 0.01f));
}

TEST (SurfaceGap, ChecksTheSurface)
{
  const auto cloud = renderPlates ({}, kFloor);
  EXPECT_TRUE (mid::isValidKeypointSurface ({cloud, {0, 1, 640 * 480 - 1}}, 3));
  EXPECT_FALSE (mid::isValidKeypointSurface ({nullptr, {0}}, 1));
  EXPECT_FALSE (mid::isValidKeypointSurface ({cloud, {0, 1}}, 3));         // one short
  EXPECT_FALSE (mid::isValidKeypointSurface ({cloud, {0, 640 * 480}}, 2)); // outside
  EXPECT_FALSE (mid::isValidKeypointSurface ({cloud, {-1, 0}}, 2));
  auto unorganized = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  unorganized->resize (10);
  EXPECT_FALSE (mid::isValidKeypointSurface ({unorganized, {0}}, 1));
}
