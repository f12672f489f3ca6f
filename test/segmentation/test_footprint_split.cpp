// splitFootprint on footprints sampled from rectangles at known places: the copies of one box
// that touch flush, cut into their rectangles.
#include "sampled_footprints.h"

#include <mid/segmentation/footprint_split.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using Points = mid::test::FootprintPoints;

/** The copies' rectangle: 60 x 160 mm. */
const Eigen::Vector2f kCopy (0.06f, 0.16f);
constexpr float kCell = 0.005f;
constexpr float kCoverage = 0.85f;

mid::FootprintRectangle
rectangle (float x, float y, float degrees, const Eigen::Vector2f& size = kCopy)
{
  return mid::test::footprintRectangle (x, y, degrees, size);
}

Points
sampled (const std::vector<mid::FootprintRectangle>& rectangles)
{
  return mid::test::sampledFootprint (rectangles);
}

/** Angle (degrees) between two rectangles' directions, modulo a half turn. */
double
angleBetween (const mid::FootprintRectangle& a, const mid::FootprintRectangle& b)
{
  const double c = std::abs (static_cast<double> (a.direction.dot (b.direction)));
  return std::acos (std::min (1.0, c)) * 180.0 / M_PI;
}

/** Each true rectangle has one found rectangle of the copies' size at its place (centre within
  * 8 mm, a cell and a half, turned by 4 deg at most, modulo the edges' order).
  */
void
expectRectangles (const mid::FootprintRectangles& found,
                  const std::vector<mid::FootprintRectangle>& truth)
{
  ASSERT_EQ (found.size(), truth.size());
  for (const auto& t : truth) {
    bool matched = false;
    for (const auto& f : found) {
      if ((f.centre - t.centre).norm() > 0.008f)
        continue;
      const bool same_order = std::abs (f.size.x() - t.size.x()) < 1e-6f;
      const double turn = angleBetween (f, t);
      matched = matched || (same_order ? turn < 4.0 : std::abs (turn - 90.0) < 4.0);
    }
    EXPECT_TRUE (matched) << "no rectangle at " << t.centre.transpose();
  }
}

} // namespace

TEST (FootprintSplit, CutsCopiesSideBySideAndEndToEnd)
{
  // Two copies side by side, turned by 30 deg; three end to end along a line at -70 deg.
  const float c = std::cos (30.0f * static_cast<float> (M_PI) / 180.0f);
  const float s = std::sin (30.0f * static_cast<float> (M_PI) / 180.0f);
  const std::vector<mid::FootprintRectangle> side_by_side = {
      rectangle (0.1f, 0.2f, 30.0f),
      rectangle (0.1f - 0.06f * c, 0.2f - 0.06f * s, 30.0f)};
  mid::FootprintRectangles found;
  ASSERT_TRUE (
      mid::splitFootprint (sampled (side_by_side), kCopy, kCell, kCoverage, found));
  expectRectangles (found, side_by_side);

  const Eigen::Vector2f along (std::cos (-70.0f * static_cast<float> (M_PI) / 180.0f),
                               std::sin (-70.0f * static_cast<float> (M_PI) / 180.0f));
  const Eigen::Vector2f start (-0.3f, 0.1f);
  std::vector<mid::FootprintRectangle> end_to_end;
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector2f centre = start + static_cast<float> (i) * 0.16f * along;
    end_to_end.push_back (rectangle (centre.x(), centre.y(), -70.0f + 90.0f));
  }
  ASSERT_TRUE (
      mid::splitFootprint (sampled (end_to_end), kCopy, kCell, kCoverage, found));
  expectRectangles (found, end_to_end);
}

TEST (FootprintSplit, CutsTwoCopiesMeetingAtARightAngle)
{
  // An L: the second copy across the end of the first.
  const std::vector<mid::FootprintRectangle> corner = {rectangle (0.0f, 0.0f, 0.0f),
                                                       rectangle (0.11f, 0.05f, 90.0f)};
  mid::FootprintRectangles found;
  ASSERT_TRUE (mid::splitFootprint (sampled (corner), kCopy, kCell, kCoverage, found));
  expectRectangles (found, corner);
}

TEST (FootprintSplit, LeavesOneCopyAndOtherShapesWhole)
{
  mid::FootprintRectangles found;
  // One copy is no group.
  ASSERT_TRUE (mid::splitFootprint (
      sampled ({rectangle (0.0f, 0.0f, 20.0f)}), kCopy, kCell, kCoverage, found));
  EXPECT_TRUE (found.empty());
  // A copy against a box of another size in which no copy fits: the copies' rectangles cover
  // too little of the whole.
  ASSERT_TRUE (
      mid::splitFootprint (sampled ({rectangle (0.0f, 0.0f, 0.0f),
                                     rectangle (0.08f, 0.0f, 0.0f, {0.1f, 0.1f})}),
                           kCopy,
                           kCell,
                           kCoverage,
                           found));
  EXPECT_TRUE (found.empty());
  // A disc of the same area as two copies.
  const Points disc = mid::test::sampledDisc (
      std::sqrt (2.0f * kCopy.prod() / static_cast<float> (M_PI)));
  ASSERT_TRUE (mid::splitFootprint (disc, kCopy, kCell, kCoverage, found));
  EXPECT_TRUE (found.empty());
}

TEST (FootprintSplit, RefusesBadParametersAndPoints)
{
  const Points points =
      sampled ({rectangle (0.0f, 0.0f, 0.0f), rectangle (0.06f, 0.0f, 0.0f)});
  const auto refuses = [] (const Points& footprint,
                           const Eigen::Vector2f& size,
                           float cell,
                           float coverage) {
    mid::FootprintRectangles found (1);
    EXPECT_FALSE (mid::splitFootprint (footprint, size, cell, coverage, found));
    EXPECT_TRUE (found.empty());
  };
  refuses (points, {0.0f, 0.16f}, kCell, kCoverage);
  refuses (points, kCopy, -kCell, kCoverage);
  refuses (points, kCopy, kCell, 1.5f);
  refuses (points, kCopy, std::numeric_limits<float>::quiet_NaN(), kCoverage);
  refuses (points, kCopy, 0.01f, kCoverage); // coarser than a tenth of 0.06 m
  refuses (points, kCopy, 1e-5f, kCoverage); // more than 4 million cells
  Points with_nan = points;
  with_nan.front().x() = std::numeric_limits<float>::quiet_NaN();
  refuses (with_nan, kCopy, kCell, kCoverage);
  Points with_infinity = points;
  with_infinity.back().y() = std::numeric_limits<float>::infinity();
  refuses (with_infinity, kCopy, kCell, kCoverage);

  // The same points with good parameters are cut (a positive control).
  mid::FootprintRectangles found;
  EXPECT_TRUE (mid::splitFootprint (points, kCopy, kCell, kCoverage, found));
  EXPECT_EQ (found.size(), 2u);
}
