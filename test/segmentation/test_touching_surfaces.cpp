// touchingSurfaces() on hand-made surfaces of a flat organized frame: which touch along a
// border, which at a point, which across a depth step.
#include <mid/segmentation/touching_surfaces.h>

#include <gtest/gtest.h>

#include <utility>
#include <vector>

namespace {

constexpr int kSide = 20;

/** A 20 x 20 frame of a plane 1 m away, 2 mm between neighbouring points; rows 9-12 of
  * columns 2-8 lie 5 cm nearer (a step no surface crosses).
  */
pcl::PointCloud<pcl::PointXYZ>
frame ()
{
  pcl::PointCloud<pcl::PointXYZ> cloud (kSide, kSide);
  for (int row = 0; row < kSide; ++row)
    for (int column = 0; column < kSide; ++column) {
      const bool step = row >= 9 && row <= 12 && column >= 2 && column <= 8;
      cloud (static_cast<std::uint32_t> (column), static_cast<std::uint32_t> (row)) =
          pcl::PointXYZ (0.002f * static_cast<float> (column),
                         0.002f * static_cast<float> (row),
                         step ? 0.95f : 1.0f);
    }
  return cloud;
}

/** The pixels of rows [r0, r1] x columns [c0, c1]. */
pcl::Indices
block (int r0, int r1, int c0, int c1)
{
  pcl::Indices pixels;
  for (int row = r0; row <= r1; ++row)
    for (int column = c0; column <= c1; ++column)
      pixels.push_back (row * kSide + column);
  return pixels;
}

using Pairs = std::vector<std::pair<std::size_t, std::size_t>>;

} // namespace

TEST (TouchingSurfaces, JoinsABorderNotAPointNorAStep)
{
  // 0 and 1 share a border of 7 pixel pairs; 2 touches 1 in one pair (its corner pixel beside
  // 1's); 3 borders 0 along 7 pairs, but 5 cm nearer.
  const pcl::PointCloud<pcl::PointXYZ> cloud = frame();
  pcl::Indices corner = block (9, 12, 16, 18);
  corner.push_back (8 * kSide + 16);
  const std::vector<pcl::Indices> surfaces = {
      block (2, 8, 2, 8), block (2, 8, 9, 15), corner, block (9, 12, 2, 8)};
  Pairs pairs;
  ASSERT_TRUE (mid::touchingSurfaces (cloud, surfaces, 0.008f, 3, pairs));
  EXPECT_EQ (pairs, (Pairs{{0, 1}}));
  ASSERT_TRUE (mid::touchingSurfaces (cloud, surfaces, 0.008f, 1, pairs));
  EXPECT_EQ (pairs, (Pairs{{0, 1}, {1, 2}}));
  // A step larger than 5 cm joins the nearer block too.
  ASSERT_TRUE (mid::touchingSurfaces (cloud, surfaces, 0.06f, 3, pairs));
  EXPECT_EQ (pairs, (Pairs{{0, 1}, {0, 3}}));
  // A border longer than asked for is none.
  ASSERT_TRUE (mid::touchingSurfaces (cloud, surfaces, 0.008f, 8, pairs));
  EXPECT_TRUE (pairs.empty());
}

TEST (TouchingSurfaces, RefusesBadInput)
{
  const pcl::PointCloud<pcl::PointXYZ> cloud = frame();
  Pairs pairs = {{0, 1}};
  EXPECT_FALSE (mid::touchingSurfaces (cloud, {block (0, 1, 0, 1)}, 0.008f, 0, pairs));
  EXPECT_TRUE (pairs.empty());
  pairs = {{0, 1}};
  EXPECT_FALSE (mid::touchingSurfaces (cloud, {{kSide * kSide}}, 0.008f, 3, pairs));
  EXPECT_TRUE (pairs.empty());
  pcl::PointCloud<pcl::PointXYZ> unorganized = cloud;
  unorganized.height = 1;
  pairs = {{0, 1}};
  EXPECT_FALSE (
      mid::touchingSurfaces (unorganized, {block (0, 1, 0, 1)}, 0.008f, 3, pairs));
  EXPECT_TRUE (pairs.empty());
}
