#include <mid/simulation/pinhole_camera.h>

#include <cmath>

namespace mid {
namespace simulation {

bool
validateCamera (const PinholeCamera& camera, std::string& problem)
{
  problem.clear();
  if (camera.width <= 0 || camera.height <= 0)
    problem = "the camera size is " + std::to_string (camera.width) + "x" +
              std::to_string (camera.height) + " pixels; both must be positive";
  else if (!std::isfinite (camera.fx) || !std::isfinite (camera.fy) ||
           !std::isfinite (camera.cx) || !std::isfinite (camera.cy))
    problem = "the camera intrinsics contain a non-finite value";
  else if (camera.fx <= 0.0 || camera.fy <= 0.0)
    problem = "the camera focal lengths fx and fy must be positive";
  return problem.empty();
}

io::CameraIntrinsics
toCameraIntrinsics (const PinholeCamera& camera, double depth_scale)
{
  io::CameraIntrinsics intrinsics;
  intrinsics.fx = camera.fx;
  intrinsics.fy = camera.fy;
  intrinsics.cx = camera.cx;
  intrinsics.cy = camera.cy;
  intrinsics.depth_scale = depth_scale;
  return intrinsics;
}

bool
projectPoint (const PinholeCamera& camera,
              const Eigen::Vector3d& point,
              Eigen::Vector2d& pixel)
{
  if (!(point.z() > 0.0))
    return false;
  pixel = Eigen::Vector2d (camera.fx * point.x() / point.z() + camera.cx,
                           camera.fy * point.y() / point.z() + camera.cy);
  return true;
}

Eigen::Vector3d
pixelRay (const PinholeCamera& camera, double u, double v)
{
  return Eigen::Vector3d (
      (u - camera.cx) / camera.fx, (v - camera.cy) / camera.fy, 1.0);
}

} // namespace simulation
} // namespace mid
