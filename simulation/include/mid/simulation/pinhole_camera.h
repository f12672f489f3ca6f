#pragma once

#include <mid/io/camera_intrinsics.h>

#include <Eigen/Core>

#include <string>

namespace mid {
namespace simulation {

/** \brief An ideal pinhole camera in the OpenCV convention: x right, y down, z forward (metres).
  *
  * Pixel (u, v) has its centre at integer coordinates, so the point (x, y, z) projects to
  * u = fx * x / z + cx, v = fy * y / z + cy, exactly the inverse of mid::io::rgbdToCloud().
  * The defaults are those of a VGA Kinect-like RGB-D sensor.
  */
struct PinholeCamera
{
  /** \brief Image size in pixels. */
  int width = 640;
  int height = 480;
  /** \brief Focal lengths in pixels. */
  double fx = 538.0;
  double fy = 538.0;
  /** \brief Principal point in pixels. */
  double cx = 319.5;
  double cy = 239.5;
};

/** \brief Check that a camera is usable: positive size, finite positive focal lengths and a
  * finite principal point.
  * \param[in] camera the camera to check
  * \param[out] problem what is wrong, empty when it is valid
  * \return true if valid
  */
bool
validateCamera (const PinholeCamera& camera, std::string& problem);

/** \brief The intrinsics of the camera for mid::io, with the given depth scale.
  * \param[in] camera the camera
  * \param[in] depth_scale metres per 16-bit depth unit (0.001 for millimetres)
  * \return the intrinsics
  */
io::CameraIntrinsics
toCameraIntrinsics (const PinholeCamera& camera, double depth_scale);

/** \brief Project a point given in the camera frame.
  * \param[in] camera the camera
  * \param[in] point the point (metres, camera frame)
  * \param[out] pixel continuous pixel coordinates (u, v), pixel centres at integers
  * \return false if the point is not in front of the camera (z <= 0); pixel is then unchanged
  */
bool
projectPoint (const PinholeCamera& camera,
              const Eigen::Vector3d& point,
              Eigen::Vector2d& pixel);

/** \brief The ray through a pixel, scaled so that its z component is 1: a point at depth z
  * on it is z * ray, which makes the ray parameter of a hit equal to its depth.
  * \param[in] camera the camera
  * \param[in] u column (pixel centres at integers; fractions allowed)
  * \param[in] v row
  * \return ((u - cx) / fx, (v - cy) / fy, 1)
  */
Eigen::Vector3d
pixelRay (const PinholeCamera& camera, double u, double v);

} // namespace simulation
} // namespace mid
