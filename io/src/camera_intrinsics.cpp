#include <mid/io/camera_intrinsics.h>

#include <cmath>

namespace mid {
namespace io {

bool
validateIntrinsics (const CameraIntrinsics& intrinsics, std::string& problem)
{
  problem.clear();
  const double values[] = {intrinsics.fx,
                           intrinsics.fy,
                           intrinsics.cx,
                           intrinsics.cy,
                           intrinsics.depth_scale};
  for (const double value : values)
    if (!std::isfinite (value))
      problem = "intrinsics contain a non-finite value";
  if (problem.empty() && (intrinsics.fx <= 0.0 || intrinsics.fy <= 0.0))
    problem = "focal lengths fx and fy must be positive";
  if (problem.empty() && intrinsics.depth_scale <= 0.0)
    problem = "depth scale must be positive (metres per depth unit, e.g. 0.001 for "
              "millimetres)";
  return problem.empty();
}

} // namespace io
} // namespace mid
