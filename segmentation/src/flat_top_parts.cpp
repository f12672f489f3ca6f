#include <mid/segmentation/flat_top_parts.h>
#include <mid/segmentation/footprint_split.h>
#include <mid/segmentation/instance_extent.h>

#include <opencv2/imgproc.hpp>
#include <pcl/console/print.h>

#include <algorithm>
#include <array>
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
/** Largest step in height (metres) between neighbouring pixels of one top, when its height is
  * not known (flatTopSizes()).
  */
constexpr float kLevelStep = 0.003f;
/** How far (metres) from a top's height the points of its rim lie (withRim()). */
constexpr float kRimBand = 0.003f;
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

/** By pixel of `organized`: 1 where `surface` holds a level point (the normal through the
  * points kNormalReach pixels away on either side within 25 deg of the plane's).
  */
std::vector<std::uint8_t>
levelPixels (const pcl::PointCloud<pcl::PointXYZ>& organized,
             const Eigen::Vector3f& up,
             const pcl::Indices& surface)
{
  const int width = static_cast<int> (organized.width);
  const int rows = static_cast<int> (organized.height);
  const auto point = [&organized] (pcl::index_t p) {
    return organized[static_cast<std::size_t> (p)].getVector3fMap();
  };
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
  return level;
}

/** The 4-neighbours of pixel p in an image `width` pixels wide of `count` pixels, -1 for those
  * outside it.
  */
std::array<pcl::index_t, 4>
fourNeighbours (pcl::index_t p, int width, pcl::index_t count)
{
  const int column = p % width;
  return {column > 0 ? p - 1 : -1,
          column + 1 < width ? p + 1 : -1,
          p - width,
          p + width < count ? p + width : -1};
}

/** The 4-connected patches of the pixels marked in `mask` (cleared on the way), each flooded
  * from its first pixel in `surface`, of kMinTopPixels at least; `joins (p, q)` tells whether
  * two neighbouring marked pixels are of one patch.
  */
template <typename Joins>
std::vector<pcl::Indices>
patchesOf (const pcl::PointCloud<pcl::PointXYZ>& organized,
           const pcl::Indices& surface,
           std::vector<std::uint8_t>& mask,
           const Joins& joins)
{
  const int width = static_cast<int> (organized.width);
  const auto count = static_cast<pcl::index_t> (organized.size());
  std::vector<pcl::Indices> patches;
  for (const auto seed : surface) {
    if (mask[static_cast<std::size_t> (seed)] == 0)
      continue;
    pcl::Indices patch;
    std::vector<pcl::index_t> stack = {seed};
    mask[static_cast<std::size_t> (seed)] = 0;
    while (!stack.empty()) {
      const pcl::index_t p = stack.back();
      stack.pop_back();
      patch.push_back (p);
      for (const pcl::index_t q : fourNeighbours (p, width, count))
        if (q >= 0 && mask[static_cast<std::size_t> (q)] != 0 && joins (p, q)) {
          mask[static_cast<std::size_t> (q)] = 0;
          stack.push_back (q);
        }
    }
    if (patch.size() >= kMinTopPixels)
      patches.push_back (std::move (patch));
  }
  return patches;
}

/** `patch` grown by up to kNormalReach pixels (4-neighbours) over the pixels of `surface`
  * (marked in `on_surface`) whose points lie within kRimBand of `height` above the plane: the
  * top's rim, where the normal through points kNormalReach pixels away bends towards the
  * sides, so that the rectangle around the grown patch is the top's own. No farther: beyond
  * the rim lies a neighbour's side, at the top's height where it stands flush.
  */
pcl::Indices
withRim (const pcl::PointCloud<pcl::PointXYZ>& organized,
         const Eigen::Vector4f& plane,
         const std::vector<std::uint8_t>& on_surface,
         const pcl::Indices& patch,
         float height)
{
  const int width = static_cast<int> (organized.width);
  const auto count = static_cast<pcl::index_t> (organized.size());
  std::vector<std::uint8_t> reached (organized.size(), 0);
  for (const auto p : patch)
    reached[static_cast<std::size_t> (p)] = 1;
  pcl::Indices grown = patch;
  std::size_t ring_begin = 0;
  for (int ring = 0; ring < kNormalReach; ++ring) {
    const std::size_t ring_end = grown.size();
    for (std::size_t i = ring_begin; i < ring_end; ++i) {
      const pcl::index_t p = grown[i];
      for (const pcl::index_t q : fourNeighbours (p, width, count))
        if (q >= 0 && reached[static_cast<std::size_t> (q)] == 0 &&
            on_surface[static_cast<std::size_t> (q)] != 0 &&
            std::abs (
                planeDistance (
                    plane, organized[static_cast<std::size_t> (q)].getVector3fMap()) -
                height) <= kRimBand) {
          reached[static_cast<std::size_t> (q)] = 1;
          grown.push_back (q);
        }
    }
    ring_begin = ring_end;
  }
  return grown;
}

/** The smallest rectangle around the patch's points on the plane (e1, e2 its axes). */
cv::RotatedRect
patchRectangle (const pcl::PointCloud<pcl::PointXYZ>& organized,
                const Eigen::Vector3f& e1,
                const Eigen::Vector3f& e2,
                const pcl::Indices& patch)
{
  std::vector<cv::Point2f> footprint;
  footprint.reserve (patch.size());
  for (const auto p : patch) {
    const Eigen::Vector3f point =
        organized[static_cast<std::size_t> (p)].getVector3fMap();
    footprint.emplace_back (e1.dot (point), e2.dot (point));
  }
  return cv::minAreaRect (footprint);
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
  if (const char* problem = surfacePixelsProblem (organized, surface)) {
    PCL_ERROR ("[mid::flatTopParts] %s.\n", problem);
    return false;
  }
  if (!size.allFinite() || !(size.array() > 0.0f).all()) {
    PCL_ERROR ("[mid::flatTopParts] The box's edges must be finite and > 0.\n");
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
  const std::vector<std::uint8_t> level = levelPixels (organized, up, surface);

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
    for (const pcl::Indices& patch :
         patchesOf (organized, surface, on_top, [] (pcl::index_t, pcl::index_t) {
           return true;
         })) {
      const cv::RotatedRect rectangle = patchRectangle (organized, e1, e2, patch);
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

bool
flatTopSizes (const pcl::PointCloud<pcl::PointXYZ>& organized,
              const Eigen::Vector4f& plane,
              const pcl::Indices& surface,
              std::vector<Eigen::Vector3f>& sizes)
{
  sizes.clear();
  if (const char* problem = surfacePixelsProblem (organized, surface)) {
    PCL_ERROR ("[mid::flatTopSizes] %s.\n", problem);
    return false;
  }
  const Eigen::Vector3f up = plane.head<3>();
  const Eigen::Vector3f e1 = up.unitOrthogonal(), e2 = up.cross (e1);
  const auto above = [&] (pcl::index_t p) {
    return planeDistance (plane,
                          organized[static_cast<std::size_t> (p)].getVector3fMap());
  };
  std::vector<std::uint8_t> level = levelPixels (organized, up, surface);
  std::vector<std::uint8_t> on_surface (organized.size(), 0);
  for (const auto p : surface)
    on_surface[static_cast<std::size_t> (p)] = 1;
  for (pcl::Indices& patch :
       patchesOf (organized, surface, level, [&] (pcl::index_t p, pcl::index_t q) {
         return std::abs (above (p) - above (q)) <= kLevelStep;
       })) {
    const auto middle = patch.begin() + static_cast<std::ptrdiff_t> (patch.size() / 2);
    std::nth_element (
        patch.begin(), middle, patch.end(), [&] (pcl::index_t a, pcl::index_t b) {
          return above (a) < above (b);
        });
    const cv::RotatedRect rectangle =
        patchRectangle (organized,
                        e1,
                        e2,
                        withRim (organized, plane, on_surface, patch, above (*middle)));
    Eigen::Vector3f size (above (*middle), rectangle.size.width, rectangle.size.height);
    std::sort (size.data(), size.data() + 3);
    if (size[0] > 0.0f)
      sizes.push_back (size);
  }
  return true;
}

} // namespace mid
