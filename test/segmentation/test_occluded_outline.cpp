// occludedOutlineShare() and occludedOutline() on hand-made organized frames: a square
// surface with something in front of one of its sides, behind it, or nothing around it.
#include <mid/segmentation/occluded_outline.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace {

constexpr int kSide = 30;
constexpr int kRing = 4;
constexpr float kStep = 0.01f;

/** A 30 x 30 frame of a plane 1 m away, 2 mm between neighbouring points, the pixels of
  * columns [c0, c1] (all rows) at depth `z`.
  */
pcl::PointCloud<pcl::PointXYZ>
frame (int c0 = 0, int c1 = -1, float z = 1.0f)
{
  pcl::PointCloud<pcl::PointXYZ> cloud (kSide, kSide);
  for (int row = 0; row < kSide; ++row)
    for (int column = 0; column < kSide; ++column)
      cloud (static_cast<std::uint32_t> (column), static_cast<std::uint32_t> (row)) =
          pcl::PointXYZ (0.002f * static_cast<float> (column),
                         0.002f * static_cast<float> (row),
                         column >= c0 && column <= c1 ? z : 1.0f);
  return cloud;
}

/** The 10 x 10 square of rows and columns 10-19: 36 pixels of outline, 10 on each side with
  * the corners shared.
  */
pcl::Indices
square ()
{
  pcl::Indices pixels;
  for (int row = 10; row < 20; ++row)
    for (int column = 10; column < 20; ++column)
      pixels.push_back (row * kSide + column);
  return pixels;
}

float
shareOf (const pcl::PointCloud<pcl::PointXYZ>& cloud, int ring = kRing)
{
  float share = -1.0f;
  EXPECT_TRUE (mid::occludedOutlineShare (cloud, square(), ring, kStep, share));
  return share;
}

} // namespace

TEST (OccludedOutline, CountsTheOutlineBesideSomethingInFront)
{
  // Nothing around: nothing hidden.
  EXPECT_EQ (shareOf (frame()), 0.0f);
  // Columns 22-29, 5 cm nearer, 3 pixels right of the square: its right side (10 of 36
  // outline pixels) and the top and bottom pixels of column 18 (4 pixels away) are hidden,
  // seen through the ring of 4 pixels, not through a ring of 2.
  EXPECT_NEAR (shareOf (frame (22, 29, 0.95f)), 12.0f / 36.0f, 1e-6f);
  EXPECT_EQ (shareOf (frame (22, 29, 0.95f), 2), 0.0f);
  // The same columns behind the square, or nearer by less than the step: nothing hidden.
  EXPECT_EQ (shareOf (frame (22, 29, 1.05f)), 0.0f);
  EXPECT_EQ (shareOf (frame (22, 29, 0.995f)), 0.0f);
  // Columns 0-7 nearer: the left side, 3 pixels away, and column 11's top and bottom.
  EXPECT_NEAR (shareOf (frame (0, 7, 0.9f)), 12.0f / 36.0f, 1e-6f);
  // Missing depth beside the square hides nothing.
  EXPECT_EQ (shareOf (frame (22, 29, std::numeric_limits<float>::quiet_NaN())), 0.0f);
}

TEST (OccludedOutline, RefusesBadInput)
{
  const auto refuses = [] (const pcl::PointCloud<pcl::PointXYZ>& cloud,
                           const pcl::Indices& pixels,
                           int ring,
                           float step) {
    float share = 0.5f;
    EXPECT_FALSE (mid::occludedOutlineShare (cloud, pixels, ring, step, share));
    EXPECT_EQ (share, 0.0f);
  };
  const auto cloud = frame();
  refuses (cloud, square(), 0, kStep);
  refuses (cloud, square(), kRing, 0.0f);
  refuses (cloud, square(), kRing, std::numeric_limits<float>::quiet_NaN());
  refuses (cloud, {kSide * kSide}, kRing, kStep);
  refuses (cloud, {-1}, kRing, kStep);
  pcl::PointCloud<pcl::PointXYZ> unorganized;
  unorganized.push_back (pcl::PointXYZ (0.0f, 0.0f, 1.0f));
  refuses (unorganized, {0}, kRing, kStep);
}

TEST (OccludedOutline, ListsTheOutlineAndTheHiddenPixels)
{
  // Columns 22-29 nearer, 3 pixels right of the square: the hidden pixels are its right
  // column (19) and the top and bottom pixels of column 18, each listed once.
  pcl::Indices outline, hidden;
  ASSERT_TRUE (mid::occludedOutline (
      frame (22, 29, 0.95f), square(), kRing, kStep, outline, hidden));
  EXPECT_EQ (outline.size(), 36u);
  EXPECT_TRUE (std::is_sorted (outline.begin(), outline.end())); // in the frame's order
  pcl::Indices expected = {10 * kSide + 18, 10 * kSide + 19};
  for (int row = 11; row < 19; ++row)
    expected.push_back (row * kSide + 19);
  expected.push_back (19 * kSide + 18);
  expected.push_back (19 * kSide + 19);
  EXPECT_EQ (hidden, expected);
  for (const auto p : hidden)
    EXPECT_NE (std::find (outline.begin(), outline.end(), p), outline.end());

  // Bad input empties both lists.
  EXPECT_FALSE (mid::occludedOutline (frame(), square(), 0, kStep, outline, hidden));
  EXPECT_TRUE (outline.empty());
  EXPECT_TRUE (hidden.empty());
}
