#pragma once

#include <Eigen/Core>
#include <Eigen/StdVector>
#include <opencv2/core.hpp>

#include <vector>

namespace mid {
namespace detail {

/** \brief Largest footprint raster, in cells. */
constexpr double kMaxRasterCells = 4.0e6;

/** \brief A footprint on the support plane on a grid: cell (column, row) has its centre at
  * origin + (column, row) * cell (splitFootprint(), footprintCopySizes()).
  */
struct Raster
{
  Eigen::Vector2f origin = Eigen::Vector2f::Zero();
  float cell = 0.0f;
  cv::Mat occupied; ///< CV_8U, non-zero where a point falls

  Eigen::Vector2f
  centreOf (int column, int row) const
  {
    return origin + cell * Eigen::Vector2f (static_cast<float> (column),
                                            static_cast<float> (row));
  }
};

/** \brief What rasterizeFootprint() made of the points. */
enum class RasterOutcome {
  empty,      ///< no point: nothing to rasterize
  rasterized, ///< the raster holds the points
  refused     ///< a point not finite, or too many cells (PCL_ERROR printed)
};

/** \brief Rasterize `points` into cells of `cell` (> 0), with a free cell around them, the
  * gaps between the points' cells closed (3 x 3). A point that is not finite, or a raster of
  * more than kMaxRasterCells cells, is refused with a PCL_ERROR that names `function` (the
  * caller, e.g. "splitFootprint"); the raster is then untouched.
  */
RasterOutcome
rasterizeFootprint (
    const std::vector<Eigen::Vector2f, Eigen::aligned_allocator<Eigen::Vector2f>>&
        points,
    float cell,
    const char* function,
    Raster& raster);

} // namespace detail
} // namespace mid
