#include "footprint_raster.h"

#include <opencv2/imgproc.hpp>
#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace mid {
namespace detail {

RasterOutcome
rasterizeFootprint (
    const std::vector<Eigen::Vector2f, Eigen::aligned_allocator<Eigen::Vector2f>>&
        points,
    float cell,
    const char* function,
    Raster& raster)
{
  if (std::any_of (points.begin(), points.end(), [] (const Eigen::Vector2f& point) {
        return !point.allFinite();
      })) {
    PCL_ERROR ("[mid::%s] A point of the footprint is not finite.\n", function);
    return RasterOutcome::refused;
  }
  if (points.empty())
    return RasterOutcome::empty;
  Eigen::Vector2f low = points.front(), high = points.front();
  for (const auto& point : points) {
    low = low.cwiseMin (point);
    high = high.cwiseMax (point);
  }
  const Eigen::Vector2f extent = (high - low) / cell;
  if (!extent.allFinite() || (static_cast<double> (extent.x()) + 3.0) *
                                     (static_cast<double> (extent.y()) + 3.0) >
                                 kMaxRasterCells) {
    PCL_ERROR ("[mid::%s] The footprint spans more than %.0f cells of %g m.\n",
               function,
               kMaxRasterCells,
               static_cast<double> (cell));
    return RasterOutcome::refused;
  }
  raster.cell = cell;
  raster.origin = low - Eigen::Vector2f::Constant (cell);
  raster.occupied = cv::Mat::zeros (
      static_cast<int> (extent.y()) + 3, static_cast<int> (extent.x()) + 3, CV_8U);
  for (const auto& point : points) {
    const Eigen::Vector2f at = (point - raster.origin) / cell;
    raster.occupied.at<std::uint8_t> (static_cast<int> (std::lround (at.y())),
                                      static_cast<int> (std::lround (at.x()))) = 1;
  }
  cv::morphologyEx (raster.occupied,
                    raster.occupied,
                    cv::MORPH_CLOSE,
                    cv::getStructuringElement (cv::MORPH_RECT, cv::Size (3, 3)));
  return RasterOutcome::rasterized;
}

} // namespace detail
} // namespace mid
