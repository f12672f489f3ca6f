#include "footprint_raster.h"

#include <mid/segmentation/footprint_split.h>

#include <opencv2/imgproc.hpp>
#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace mid {

bool
FootprintRectangle::holds (const Eigen::Vector2f& point, float margin) const
{
  const Eigen::Vector2f offset = point - centre;
  const Eigen::Vector2f across (-direction.y(), direction.x());
  return std::abs (offset.dot (direction)) <= 0.5f * size.x() + margin &&
         std::abs (offset.dot (across)) <= 0.5f * size.y() + margin;
}

float
FootprintRectangle::distance (const Eigen::Vector2f& point) const
{
  const Eigen::Vector2f offset = point - centre;
  const Eigen::Vector2f across (-direction.y(), direction.x());
  const Eigen::Vector2f outside (
      std::max (0.0f, std::abs (offset.dot (direction)) - 0.5f * size.x()),
      std::max (0.0f, std::abs (offset.dot (across)) - 0.5f * size.y()));
  return outside.norm();
}

namespace {

using detail::Raster;
using detail::rasterizeFootprint;
using detail::RasterOutcome;

/** A footprint of fewer rectangles' area than this is one copy, not a group. */
constexpr double kMinCopies = 1.6;
/** A footprint of more copies' area than this is left whole (a wall of boxes, not a group). */
constexpr std::size_t kMaxCopies = 32;
/** Cells the rectangle's shortest edge must span at least. */
constexpr float kCellsPerEdge = 10.0f;
/** Share of the footprint the rectangles placed must cover. */
constexpr double kMinExplained = 0.8;
/** How far from a right angle a corner of the outline may be (degrees). */
constexpr double kCornerTolerance = 20.0;
/** How far the simplified outline may stray from the hull (cells). */
constexpr double kOutlineTolerance = 2.0;
/** Width (cells) below which what a placed rectangle leaves is a sliver, not a copy. */
constexpr int kSliverCells = 5;

/** Visit the cells whose centres lie in `rectangle`, as visit(column, row). */
template <typename Visit>
void
forCellsIn (const Raster& raster, const FootprintRectangle& rectangle, Visit visit)
{
  const float reach = 0.5f * rectangle.size.norm();
  const Eigen::Vector2f low =
      (rectangle.centre - raster.origin).array() / raster.cell - reach / raster.cell;
  const Eigen::Vector2f high =
      (rectangle.centre - raster.origin).array() / raster.cell + reach / raster.cell;
  const int first_column = std::max (0, static_cast<int> (std::floor (low.x())));
  const int first_row = std::max (0, static_cast<int> (std::floor (low.y())));
  const int last_column =
      std::min (raster.occupied.cols - 1, static_cast<int> (std::ceil (high.x())));
  const int last_row =
      std::min (raster.occupied.rows - 1, static_cast<int> (std::ceil (high.y())));
  for (int row = first_row; row <= last_row; ++row)
    for (int column = first_column; column <= last_column; ++column)
      if (rectangle.holds (raster.centreOf (column, row), 0.0f))
        visit (column, row);
}

/** Share of the cells of `rectangle` that `occupied` holds (0 if it has none). */
double
coverage (const Raster& raster,
          const cv::Mat& occupied,
          const FootprintRectangle& rectangle)
{
  std::size_t cells = 0, covered = 0;
  forCellsIn (raster, rectangle, [&] (int column, int row) {
    ++cells;
    if (occupied.at<std::uint8_t> (row, column) != 0)
      ++covered;
  });
  return cells == 0 ? 0.0 : static_cast<double> (covered) / static_cast<double> (cells);
}

/** The rectangles of `size` placed at the right-angled corners of the outline of what
  * `occupied` holds: along either edge of the corner, either way round.
  */
FootprintRectangles
cornerPlacements (const Raster& raster,
                  const cv::Mat& occupied,
                  const Eigen::Vector2f& size)
{
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours (
      occupied.clone(), contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE);
  FootprintRectangles placements;
  // Two edges meet at a right angle within the tolerance when the cosine of their angle is
  // at most the sine of the tolerance.
  const double max_cosine = std::sin (kCornerTolerance * M_PI / 180.0);
  for (const auto& contour : contours) {
    std::vector<cv::Point> hull, outline;
    cv::convexHull (contour, hull);
    cv::approxPolyDP (hull, outline, kOutlineTolerance, true);
    const std::size_t n = outline.size();
    if (n < 3)
      continue;
    for (std::size_t i = 0; i < n; ++i) {
      const cv::Point& corner = outline[i];
      const cv::Point& next = outline[(i + 1) % n];
      const cv::Point& previous = outline[(i + n - 1) % n];
      const Eigen::Vector2f to_next (static_cast<float> (next.x - corner.x),
                                     static_cast<float> (next.y - corner.y));
      const Eigen::Vector2f to_previous (static_cast<float> (previous.x - corner.x),
                                         static_cast<float> (previous.y - corner.y));
      if (to_next.norm() == 0.0f || to_previous.norm() == 0.0f ||
          std::abs (to_next.normalized().dot (to_previous.normalized())) > max_cosine)
        continue;
      const Eigen::Vector2f at = raster.centreOf (corner.x, corner.y);
      for (const auto& [along, other] :
           {std::pair{to_next, to_previous}, std::pair{to_previous, to_next}}) {
        const Eigen::Vector2f u = along.normalized();
        Eigen::Vector2f v (-u.y(), u.x());
        if (v.dot (other) < 0.0f)
          v = -v;
        for (const Eigen::Vector2f& edges :
             {size, Eigen::Vector2f (size.y(), size.x())}) {
          FootprintRectangle placement;
          placement.centre = at + 0.5f * edges.x() * u + 0.5f * edges.y() * v;
          placement.direction = u;
          placement.size = edges;
          placements.push_back (placement);
        }
      }
    }
  }
  return placements;
}

/** Take the cells of `rectangle` out of `left`, then the slivers that a rectangle a cell off
  * leaves along its edges, which are no corner of another; returns how many held footprint.
  */
double
takeAway (const Raster& raster, const FootprintRectangle& rectangle, cv::Mat& left)
{
  double taken = 0.0;
  forCellsIn (raster, rectangle, [&] (int column, int row) {
    if (left.at<std::uint8_t> (row, column) != 0)
      ++taken;
    left.at<std::uint8_t> (row, column) = 0;
  });
  cv::morphologyEx (left,
                    left,
                    cv::MORPH_OPEN,
                    cv::getStructuringElement (cv::MORPH_RECT,
                                               cv::Size (kSliverCells, kSliverCells)));
  return taken;
}

/** Place rectangles of `size` in what `left` holds, the best covered corner placement first,
  * while one covers `min_coverage` and fewer than `most` are placed; returns the footprint
  * cells they hold.
  */
double
placeGreedily (const Raster& raster,
               const Eigen::Vector2f& size,
               float min_coverage,
               std::size_t most,
               cv::Mat& left,
               FootprintRectangles& placed)
{
  const double rectangle_cells = static_cast<double> (size.prod()) /
                                 (static_cast<double> (raster.cell) * raster.cell);
  double taken = 0.0;
  while (placed.size() < most && cv::countNonZero (left) >= 0.5 * rectangle_cells) {
    double best = 0.0;
    FootprintRectangle chosen;
    for (const auto& placement : cornerPlacements (raster, left, size))
      if (const double covered = coverage (raster, left, placement); covered > best) {
        best = covered;
        chosen = placement;
      }
    if (best < static_cast<double> (min_coverage))
      break;
    taken += takeAway (raster, chosen, left);
    placed.push_back (chosen);
  }
  return taken;
}

} // namespace

bool
splitFootprint (const std::vector<Eigen::Vector2f,
                                  Eigen::aligned_allocator<Eigen::Vector2f>>& points,
                const Eigen::Vector2f& size,
                float cell,
                float min_coverage,
                FootprintRectangles& rectangles)
{
  rectangles.clear();
  if (!(size.minCoeff() > 0.0f) || !size.allFinite() || !(cell > 0.0f) ||
      !std::isfinite (cell) || !(min_coverage > 0.0f && min_coverage <= 1.0f)) {
    PCL_ERROR (
        "[mid::splitFootprint] The rectangle's edges and the cell must be finite and "
        "> 0, the coverage in (0, 1].\n");
    return false;
  }
  if (kCellsPerEdge * cell > size.minCoeff()) {
    PCL_ERROR (
        "[mid::splitFootprint] The cell (%g m) must be a tenth of the rectangle's "
        "shortest edge (%g m) or less.\n",
        static_cast<double> (cell),
        static_cast<double> (size.minCoeff()));
    return false;
  }
  Raster raster;
  switch (rasterizeFootprint (points, cell, "splitFootprint", raster)) {
  case RasterOutcome::refused:
    return false;
  case RasterOutcome::empty:
    return true;
  case RasterOutcome::rasterized:
    break;
  }
  const double total = cv::countNonZero (raster.occupied);
  // A copy alone covers its rectangle's cells and the border the raster adds around it.
  const double copy_cells = (static_cast<double> (size.x() / cell) + 1.0) *
                            (static_cast<double> (size.y() / cell) + 1.0);
  const auto copies = static_cast<std::size_t> (std::lround (total / copy_cells));
  if (total < kMinCopies * copy_cells || copies > kMaxCopies)
    return true;

  // The first rectangle may fit a corner either way round; each way is followed through, and
  // the one whose rectangles, as many as the footprint's area holds copies, cover most of it
  // is kept.
  double explained = 0.0;
  for (const auto& first : cornerPlacements (raster, raster.occupied, size)) {
    if (coverage (raster, raster.occupied, first) < static_cast<double> (min_coverage))
      continue;
    cv::Mat left = raster.occupied.clone();
    FootprintRectangles placed = {first};
    double covered = takeAway (raster, first, left);
    covered += placeGreedily (raster, size, min_coverage, copies + 1, left, placed);
    if (placed.size() == copies && covered > explained) {
      explained = covered;
      rectangles = placed;
    }
  }
  if (explained < kMinExplained * total)
    rectangles.clear();
  return true;
}

} // namespace mid
