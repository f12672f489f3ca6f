#pragma once

// Footprints on the support plane sampled from rectangles at known places: the tests of the
// steps that cut copies' footprints apart.
#include <mid/segmentation/footprint_split.h>

#include <cmath>
#include <vector>

namespace mid {
namespace test {

using FootprintPoints =
    std::vector<Eigen::Vector2f, Eigen::aligned_allocator<Eigen::Vector2f>>;

/** A rectangle of `size` centred at (x, y), its first edge turned by `degrees`. */
inline FootprintRectangle
footprintRectangle (float x, float y, float degrees, const Eigen::Vector2f& size)
{
  FootprintRectangle r;
  r.centre = Eigen::Vector2f (x, y);
  const float angle = degrees * static_cast<float> (M_PI) / 180.0f;
  r.direction = Eigen::Vector2f (std::cos (angle), std::sin (angle));
  r.size = size;
  return r;
}

/** Points 2 mm apart over the rectangles. */
inline FootprintPoints
sampledFootprint (const std::vector<FootprintRectangle>& rectangles)
{
  FootprintPoints points;
  for (const auto& r : rectangles) {
    const Eigen::Vector2f across (-r.direction.y(), r.direction.x());
    for (float a = -0.5f * r.size.x(); a <= 0.5f * r.size.x(); a += 0.002f)
      for (float b = -0.5f * r.size.y(); b <= 0.5f * r.size.y(); b += 0.002f)
        points.push_back (r.centre + a * r.direction + b * across);
  }
  return points;
}

/** Points 2 mm apart over a disc of `radius` centred at the origin. */
inline FootprintPoints
sampledDisc (float radius)
{
  FootprintPoints disc;
  for (float x = -radius; x <= radius; x += 0.002f)
    for (float y = -radius; y <= radius; y += 0.002f)
      if (x * x + y * y <= radius * radius)
        disc.emplace_back (x, y);
  return disc;
}

} // namespace test
} // namespace mid
