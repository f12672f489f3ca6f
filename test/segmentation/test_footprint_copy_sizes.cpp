// footprintCopySizes on footprints sampled from rectangles at known places: the rectangle of
// copies of an unknown box that touch each other, read off their footprint's outline.
#include "sampled_footprints.h"

#include <mid/segmentation/footprint_copy_sizes.h>
#include <mid/segmentation/footprint_split.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using mid::test::footprintRectangle;
using mid::test::sampledFootprint;
using Points = mid::test::FootprintPoints;
using Sizes = std::vector<Eigen::Vector2f, Eigen::aligned_allocator<Eigen::Vector2f>>;

/** The copies' rectangle: 60 x 160 mm, not given to the function. */
const Eigen::Vector2f kCopy (0.06f, 0.16f);
constexpr float kCell = 0.004f;
constexpr float kMinEdge = 0.03f;
constexpr float kMaxFill = 0.85f;

Sizes
copySizes (const Points& footprint)
{
  Sizes sizes;
  EXPECT_TRUE (mid::footprintCopySizes (footprint, kCell, kMinEdge, kMaxFill, sizes));
  return sizes;
}

/** The copies' rectangle is among `sizes` (each edge within two cells), and it cuts the
  * footprint into the copies' rectangles (centres within 1 cm).
  */
void
expectCopiesRectangle (const Sizes& sizes,
                       const std::vector<mid::FootprintRectangle>& copies)
{
  const Eigen::Vector2f* found = nullptr;
  for (const auto& size : sizes)
    if ((size - kCopy).cwiseAbs().maxCoeff() < 2.0f * kCell)
      found = &size;
  ASSERT_NE (found, nullptr) << sizes.size() << " rectangles, none 60 x 160 mm";
  mid::FootprintRectangles cut;
  ASSERT_TRUE (
      mid::splitFootprint (sampledFootprint (copies), *found, kCell, 0.85f, cut));
  ASSERT_EQ (cut.size(), copies.size());
  for (const auto& copy : copies) {
    bool matched = false;
    for (const auto& part : cut)
      matched = matched || (part.centre - copy.centre).norm() < 0.01f;
    EXPECT_TRUE (matched) << "no copy at " << copy.centre.transpose();
  }
}

} // namespace

TEST (FootprintCopySizes, ReadsTheCopiesRectangleOffCopiesShiftedOrAcross)
{
  // Side by side, shifted along their length by 70 mm, turned by 25 deg.
  const float c = std::cos (25.0f * static_cast<float> (M_PI) / 180.0f);
  const float s = std::sin (25.0f * static_cast<float> (M_PI) / 180.0f);
  const Eigen::Vector2f along (-s, c), across (c, s);
  const Eigen::Vector2f shift = 0.06f * across + 0.07f * along;
  const std::vector<mid::FootprintRectangle> shifted = {
      footprintRectangle (0.1f, 0.2f, 25.0f, kCopy),
      footprintRectangle (0.1f + shift.x(), 0.2f + shift.y(), 25.0f, kCopy)};
  expectCopiesRectangle (copySizes (sampledFootprint (shifted)), shifted);

  // An L: the second across the end of the first.
  const std::vector<mid::FootprintRectangle> corner = {
      footprintRectangle (0.0f, 0.0f, 0.0f, kCopy),
      footprintRectangle (0.11f, 0.05f, 90.0f, kCopy)};
  expectCopiesRectangle (copySizes (sampledFootprint (corner)), corner);

  // Three: a pair side by side and a third across their ends.
  const std::vector<mid::FootprintRectangle> three = {
      footprintRectangle (0.0f, 0.0f, 0.0f, kCopy),
      footprintRectangle (0.06f, 0.0f, 0.0f, kCopy),
      footprintRectangle (0.11f, 0.11f, 90.0f, kCopy)};
  expectCopiesRectangle (copySizes (sampledFootprint (three)), three);
}

TEST (FootprintCopySizes, ReadsNothingOffRectanglesAndDiscs)
{
  // One copy; two copies flush side by side, whose footprint one box could make; a disc (a
  // can standing) of two copies' area.
  EXPECT_TRUE (
      copySizes (sampledFootprint ({footprintRectangle (0.0f, 0.0f, 20.0f, kCopy)}))
          .empty());
  EXPECT_TRUE (
      copySizes (sampledFootprint ({footprintRectangle (0.0f, 0.0f, 0.0f, kCopy),
                                    footprintRectangle (0.06f, 0.0f, 0.0f, kCopy)}))
          .empty());
  EXPECT_TRUE (copySizes (mid::test::sampledDisc (std::sqrt (
                              2.0f * kCopy.prod() / static_cast<float> (M_PI))))
                   .empty());
  // With any fill allowed, a disc still gives nothing: it has no right-angled corners.
  Sizes sizes;
  ASSERT_TRUE (mid::footprintCopySizes (
      mid::test::sampledDisc (0.08f), kCell, kMinEdge, 1.0f, sizes));
  EXPECT_TRUE (sizes.empty());
}

TEST (FootprintCopySizes, RefusesBadParametersAndPoints)
{
  const Points points =
      sampledFootprint ({footprintRectangle (0.0f, 0.0f, 0.0f, kCopy),
                         footprintRectangle (0.11f, 0.05f, 90.0f, kCopy)});
  const auto refuses = [] (const Points& footprint,
                           float cell,
                           float min_edge,
                           float max_fill) {
    Sizes sizes (1);
    EXPECT_FALSE (mid::footprintCopySizes (footprint, cell, min_edge, max_fill, sizes));
    EXPECT_TRUE (sizes.empty());
  };
  const float nan = std::numeric_limits<float>::quiet_NaN();
  refuses (points, 0.0f, kMinEdge, kMaxFill);
  refuses (points, nan, kMinEdge, kMaxFill);
  refuses (points, kCell, 0.0f, kMaxFill);
  refuses (points, kCell, std::numeric_limits<float>::infinity(), kMaxFill);
  refuses (points, kCell, kMinEdge, 0.0f);
  refuses (points, kCell, kMinEdge, 1.5f);
  refuses (points, 1e-5f, kMinEdge, kMaxFill); // more than 4 million cells
  Points with_nan = points;
  with_nan.front().y() = nan;
  refuses (with_nan, kCell, kMinEdge, kMaxFill);

  // The same points with good parameters give the copies' rectangle (a positive control).
  Sizes sizes;
  EXPECT_TRUE (mid::footprintCopySizes (points, kCell, kMinEdge, kMaxFill, sizes));
  EXPECT_FALSE (sizes.empty());
}

TEST (FootprintCopySizes, MeasuresHowMuchRectanglesFillTheRectangleAroundThem)
{
  // Two 60 x 160 mm rectangles, turned by 30 deg, side by side fill the 120 x 160 around
  // them; shifted by 70 mm along their length, 2 * 60 * 160 of 120 * 230.
  // One rectangle twice counts its area twice.
  EXPECT_NEAR (mid::rectanglesFill ({footprintRectangle (0.0f, 0.0f, 30.0f, kCopy),
                                     footprintRectangle (0.0f, 0.0f, 30.0f, kCopy)}),
               2.0f,
               1e-3f);
  const float c = std::cos (30.0f * static_cast<float> (M_PI) / 180.0f);
  const float s = std::sin (30.0f * static_cast<float> (M_PI) / 180.0f);
  const Eigen::Vector2f along (-s, c), across (c, s);
  const Eigen::Vector2f side = 0.06f * across, shifted = 0.06f * across + 0.07f * along;
  EXPECT_NEAR (
      mid::rectanglesFill ({footprintRectangle (0.0f, 0.0f, 30.0f, kCopy),
                            footprintRectangle (side.x(), side.y(), 30.0f, kCopy)}),
      1.0f,
      1e-3f);
  EXPECT_NEAR (mid::rectanglesFill (
                   {footprintRectangle (0.0f, 0.0f, 30.0f, kCopy),
                    footprintRectangle (shifted.x(), shifted.y(), 30.0f, kCopy)}),
               2.0f * 0.06f * 0.16f / (0.12f * 0.23f),
               1e-3f);
  EXPECT_EQ (mid::rectanglesFill ({}), 0.0f);
}
