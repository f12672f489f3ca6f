#include <mid/segmentation/flat_top_parts.h>
#include <mid/segmentation/footprint_split.h>
#include <mid/segmentation/instance_extent.h>

#include <opencv2/imgproc.hpp>
#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace mid {

namespace {

/** How far (metres) a top's points may lie from its height, and a part's above it. */
constexpr float kTopBand = 0.006f;
/** Pixels to either side of a pixel whose points give its normal. */
constexpr int kNormalReach = 4;
/** Cosine of the largest angle between a level pixel's normal and the plane's (25 deg). */
constexpr float kMinLevelCosine = 0.9063f;
/** Fewest pixels of a top. */
constexpr std::size_t kMinTopPixels = 30;
/** How much longer and how much shorter (metres) a top's rectangle may be than the box's
  * edges: the rim of a top is not level.
  */
constexpr float kTopExcess = 0.006f;
constexpr float kTopShortfall = 0.02f;
/** How far beyond its top's rectangle (metres) a part reaches: the sides under the top's
  * rim, which is not level.
  */
constexpr float kPartReach = 0.008f;
/** Edges closer than this (metres) are one: a square box's top is looked for once. */
constexpr float kSameEdge = 0.001f;

/** The rectangle cv::minAreaRect() gives, in the plane's 2D coordinates. */
FootprintRectangle
rectangleOf (const cv::RotatedRect& rectangle)
{
  const float angle = rectangle.angle * static_cast<float> (M_PI) / 180.0f;
  FootprintRectangle footprint;
  footprint.centre = Eigen::Vector2f (rectangle.center.x, rectangle.center.y);
  footprint.direction = Eigen::Vector2f (std::cos (angle), std::sin (angle));
  footprint.size = Eigen::Vector2f (rectangle.size.width, rectangle.size.height);
  return footprint;
}

} // namespace

bool
flatTopParts (const pcl::PointCloud<pcl::PointXYZ>& organized,
              const Eigen::Vector4f& plane,
              const pcl::Indices& surface,
              const Eigen::Vector3f& size,
              std::vector<pcl::Indices>& parts)
{
  parts.clear();
  if (!organized.isOrganized() || organized.empty()) {
    PCL_ERROR ("[mid::flatTopParts] The cloud is not organized.\n");
    return false;
  }
  if (!size.allFinite() || !(size.array() > 0.0f).all()) {
    PCL_ERROR ("[mid::flatTopParts] The box's edges must be finite and > 0.\n");
    return false;
  }
  const auto count = static_cast<pcl::index_t> (organized.size());
  if (std::any_of (surface.begin(), surface.end(), [&] (pcl::index_t p) {
        return p < 0 || p >= count ||
               !organized[static_cast<std::size_t> (p)].getVector3fMap().allFinite();
      })) {
    PCL_ERROR ("[mid::flatTopParts] A surface pixel lies outside the cloud or has no "
               "point.\n");
    return false;
  }
  const int width = static_cast<int> (organized.width);
  const int rows = static_cast<int> (organized.height);
  const Eigen::Vector3f up = plane.head<3>();
  const Eigen::Vector3f e1 = up.unitOrthogonal(), e2 = up.cross (e1);
  const auto point = [&organized] (pcl::index_t p) {
    return organized[static_cast<std::size_t> (p)].getVector3fMap();
  };
  const auto onPlane = [&] (const Eigen::Vector3f& p) {
    return Eigen::Vector2f (e1.dot (p), e2.dot (p));
  };
  // Level pixels: the normal through the points kNormalReach pixels away.
  std::vector<std::uint8_t> level (organized.size(), 0);
  for (const auto p : surface) {
    const int row = p / width, column = p % width;
    if (row < kNormalReach || column < kNormalReach || row >= rows - kNormalReach ||
        column >= width - kNormalReach)
      continue;
    const Eigen::Vector3f normal = (point (p + kNormalReach) - point (p - kNormalReach))
                                       .cross (point (p + kNormalReach * width) -
                                               point (p - kNormalReach * width));
    if (normal.allFinite() && normal.norm() > 0.0f &&
        std::abs (normal.normalized().dot (up)) >= kMinLevelCosine)
      level[static_cast<std::size_t> (p)] = 1;
  }

  // True if a level pixel of the surface at the height `above` lies within kNormalReach
  // pixels of p: p lies on (or on the rim of) a top at that height.
  std::vector<std::uint8_t> on_surface (organized.size(), 0);
  for (const auto p : surface)
    on_surface[static_cast<std::size_t> (p)] = 1;
  const auto onLevel = [&] (pcl::index_t p, float above) {
    const int row = p / width, column = p % width;
    for (int r = std::max (0, row - kNormalReach);
         r <= std::min (rows - 1, row + kNormalReach);
         ++r)
      for (int c = std::max (0, column - kNormalReach);
           c <= std::min (width - 1, column + kNormalReach);
           ++c) {
        const pcl::index_t q = r * width + c;
        if (on_surface[static_cast<std::size_t> (q)] != 0 &&
            level[static_cast<std::size_t> (q)] != 0 &&
            std::abs (planeDistance (plane, point (q)) - above) <= kTopBand)
          return true;
      }
    return false;
  };

  for (int h = 0; h < 3; ++h) {
    if (h > 0 && std::abs (size[h] - size[h - 1]) < kSameEdge)
      continue;
    const float top = size[h];
    const float short_edge = std::min (size[(h + 1) % 3], size[(h + 2) % 3]);
    const float long_edge = std::max (size[(h + 1) % 3], size[(h + 2) % 3]);
    // Level pixels at the top's height, each taken once.
    std::vector<std::uint8_t> on_top (organized.size(), 0);
    for (const auto p : surface)
      on_top[static_cast<std::size_t> (p)] =
          level[static_cast<std::size_t> (p)] != 0 &&
          std::abs (planeDistance (plane, point (p)) - top) <= kTopBand;
    // The top's patches, each flooded from its first pixel in `surface`.
    for (const auto seed : surface) {
      if (on_top[static_cast<std::size_t> (seed)] == 0)
        continue;
      std::vector<pcl::index_t> patch, stack = {seed};
      on_top[static_cast<std::size_t> (seed)] = 0;
      while (!stack.empty()) {
        const pcl::index_t p = stack.back();
        stack.pop_back();
        patch.push_back (p);
        const int column = p % width;
        for (const pcl::index_t q : {column > 0 ? p - 1 : -1,
                                     column + 1 < width ? p + 1 : -1,
                                     p - width,
                                     p + width})
          if (q >= 0 && q < count && on_top[static_cast<std::size_t> (q)] != 0) {
            on_top[static_cast<std::size_t> (q)] = 0;
            stack.push_back (q);
          }
      }
      if (patch.size() < kMinTopPixels)
        continue;
      std::vector<cv::Point2f> footprint;
      footprint.reserve (patch.size());
      for (const auto p : patch) {
        const Eigen::Vector2f f = onPlane (point (p));
        footprint.emplace_back (f.x(), f.y());
      }
      const cv::RotatedRect rectangle = cv::minAreaRect (footprint);
      const float shorter = std::min (rectangle.size.width, rectangle.size.height);
      const float longer = std::max (rectangle.size.width, rectangle.size.height);
      if (shorter > short_edge + kTopExcess || shorter < short_edge - kTopShortfall ||
          longer > long_edge + kTopExcess || longer < long_edge - kTopShortfall)
        continue;
      const FootprintRectangle under = rectangleOf (rectangle);
      pcl::Indices part;
      for (const auto p : surface) {
        const float above = planeDistance (plane, point (p));
        if (above <= top + kTopBand && under.holds (onPlane (point (p)), kPartReach) &&
            (std::abs (above - top) <= kTopBand || !onLevel (p, above)))
          part.push_back (p);
      }
      parts.push_back (part);
    }
  }
  return true;
}

} // namespace mid
