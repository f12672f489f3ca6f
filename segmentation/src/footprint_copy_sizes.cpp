#include "footprint_raster.h"

#include <mid/segmentation/footprint_copy_sizes.h>

#include <opencv2/imgproc.hpp>
#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace mid {

namespace {

/** How far the simplified outline may stray from the footprint's (cells). */
constexpr double kOutlineTolerance = 2.0;
/** Edges of the outline closer in length than this are one (cells). */
constexpr float kSameLength = 2.0f;
/** How far the copies' area may be from the footprint's (share of the footprint's). */
constexpr double kAreaTolerance = 0.2;
/** The copies a footprint may hold. */
constexpr int kFewestCopies = 2, kMostCopies = 3;

/** How far from a right angle the corners at both ends of a copy's edge may be (degrees). */
constexpr double kCornerTolerance = 20.0;

/** True if the outline turns by a right angle (either way, within kCornerTolerance) at
  * `corner`, between the edges from `previous` and to `next`.
  */
bool
rightAngled (const cv::Point& previous, const cv::Point& corner, const cv::Point& next)
{
  const cv::Point2d in = corner - previous, out = next - corner;
  const double lengths = std::hypot (in.x, in.y) * std::hypot (out.x, out.y);
  return lengths > 0.0 && std::abs (in.dot (out)) <=
                              lengths * std::sin (kCornerTolerance * M_PI / 180.0);
}

/** Cells a copy's rectangle of `a` x `b` cells covers with the raster's border around it. */
double
copyCells (float a, float b)
{
  return (static_cast<double> (a) + 1.0) * (static_cast<double> (b) + 1.0);
}

} // namespace

bool
footprintCopySizes (
    const std::vector<Eigen::Vector2f, Eigen::aligned_allocator<Eigen::Vector2f>>&
        points,
    float cell,
    float min_edge,
    float max_fill,
    std::vector<Eigen::Vector2f, Eigen::aligned_allocator<Eigen::Vector2f>>& sizes)
{
  sizes.clear();
  if (!(cell > 0.0f) || !std::isfinite (cell) || !(min_edge > 0.0f) ||
      !std::isfinite (min_edge) || !(max_fill > 0.0f && max_fill <= 1.0f)) {
    PCL_ERROR (
        "[mid::footprintCopySizes] The cell and the shortest edge must be finite "
        "and > 0, the fill in (0, 1].\n");
    return false;
  }
  detail::Raster raster;
  switch (detail::rasterizeFootprint (points, cell, "footprintCopySizes", raster)) {
  case detail::RasterOutcome::refused:
    return false;
  case detail::RasterOutcome::empty:
    return true;
  case detail::RasterOutcome::rasterized:
    break;
  }
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours (
      raster.occupied.clone(), contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
  std::vector<cv::Point> outline_points;
  std::vector<float> lengths; // cells
  for (const auto& contour : contours) {
    outline_points.insert (outline_points.end(), contour.begin(), contour.end());
    std::vector<cv::Point> outline;
    cv::approxPolyDP (contour, outline, kOutlineTolerance, true);
    const std::size_t n = outline.size();
    if (n < 4)
      continue;
    std::vector<bool> square (n);
    for (std::size_t i = 0; i < n; ++i)
      square[i] =
          rightAngled (outline[(i + n - 1) % n], outline[i], outline[(i + 1) % n]);
    for (std::size_t i = 0; i < n; ++i) {
      const cv::Point edge = outline[(i + 1) % n] - outline[i];
      if (const auto length = static_cast<float> (std::hypot (edge.x, edge.y));
          square[i] && square[(i + 1) % n] && length * cell >= min_edge)
        lengths.push_back (length);
    }
  }
  if (outline_points.size() < 3)
    return true;
  const double total = cv::countNonZero (raster.occupied);
  const cv::Size2f around = cv::minAreaRect (outline_points).size;
  if (total > static_cast<double> (max_fill) * copyCells (around.width, around.height))
    return true;

  std::sort (lengths.begin(), lengths.end());
  std::vector<float> distinct;
  for (const float length : lengths)
    if (distinct.empty() || length - distinct.back() >= kSameLength)
      distinct.push_back (length);
  std::vector<std::pair<double, Eigen::Vector2f>> candidates;
  for (std::size_t i = 0; i < distinct.size(); ++i)
    for (std::size_t j = i; j < distinct.size(); ++j) {
      double closest = kAreaTolerance;
      for (int copies = kFewestCopies; copies <= kMostCopies; ++copies)
        closest = std::min (
            closest,
            std::abs (copies * copyCells (distinct[i], distinct[j]) - total) / total);
      if (closest < kAreaTolerance)
        candidates.emplace_back (closest,
                                 cell * Eigen::Vector2f (distinct[i], distinct[j]));
    }
  std::stable_sort (candidates.begin(),
                    candidates.end(),
                    [] (const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& candidate : candidates)
    sizes.push_back (candidate.second);
  return true;
}

float
rectanglesFill (const FootprintRectangles& rectangles)
{
  std::vector<cv::Point2f> corners;
  double area = 0.0;
  for (const auto& r : rectangles) {
    const Eigen::Vector2f along = 0.5f * r.size.x() * r.direction;
    const Eigen::Vector2f across =
        0.5f * r.size.y() * Eigen::Vector2f (-r.direction.y(), r.direction.x());
    for (const float a : {-1.0f, 1.0f})
      for (const float b : {-1.0f, 1.0f}) {
        const Eigen::Vector2f corner = r.centre + a * along + b * across;
        corners.emplace_back (corner.x(), corner.y());
      }
    area += static_cast<double> (r.size.prod());
  }
  if (corners.empty())
    return 0.0f;
  const cv::Size2f around = cv::minAreaRect (corners).size;
  const double around_area =
      static_cast<double> (around.width) * static_cast<double> (around.height);
  return around_area > 0.0 ? static_cast<float> (area / around_area) : 0.0f;
}

} // namespace mid
