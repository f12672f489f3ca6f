#pragma once

#include <mid/simulation/shape.h>

#include <Eigen/Core>

#include <cmath>
#include <limits>
#include <vector>

namespace mid {
namespace simulation {
namespace test {

/** Points on a shape's surface (model frame): hits of rays cast at its centre from a sphere of
  * directions around it.
  */
inline std::vector<Eigen::Vector3d>
sampleSurface (const Shape& shape)
{
  std::vector<Eigen::Vector3d> points;
  const double radius = 2.0 * shape.getBoundingRadius();
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 80; ++j) {
      const double polar = M_PI * (i + 0.5) / 40.0, azimuth = 2.0 * M_PI * j / 80.0;
      const Eigen::Vector3d origin =
          radius * Eigen::Vector3d (std::sin (polar) * std::cos (azimuth),
                                    std::sin (polar) * std::sin (azimuth),
                                    std::cos (polar));
      // Aim near the centre, varied so that edges and faces are all sampled.
      const Eigen::Vector3d target = 0.2 * radius *
                                     Eigen::Vector3d (std::sin (3.1 * j),
                                                      std::cos (1.7 * i),
                                                      std::sin (2.3 * (i + j)));
      const Eigen::Vector3d direction = target - origin;
      SurfaceHit hit;
      if (shape.intersect (
              origin, direction, std::numeric_limits<double>::infinity(), hit))
        points.emplace_back (origin + hit.t * direction);
    }
  return points;
}

} // namespace test
} // namespace simulation
} // namespace mid
