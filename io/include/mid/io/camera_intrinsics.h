#pragma once

#include <string>

namespace mid {
namespace io {

/** \brief Pinhole intrinsics of a registered RGB-D frame, the way TUM and BOP datasets store
  * them: a pixel (u, v) with depth value d (in file units) is the point
  * z = d * depth_scale, x = (u - cx) * z / fx, y = (v - cy) * z / fy, in metres.
  */
struct CameraIntrinsics
{
  /** \brief Focal lengths in pixels (fx along columns, fy along rows); validateIntrinsics()
    * requires them > 0.
    */
  ///@{
  double fx = 0.0;
  double fy = 0.0;
  ///@}
  /** \brief Principal point in pixels (cx column, cy row). */
  ///@{
  double cx = 0.0;
  double cy = 0.0;
  ///@}
  /** \brief Metres per depth unit: 0.001 for millimetre PNGs (BOP, TUM uses 1/5000); > 0. */
  double depth_scale = 0.001;
};

/** \brief Check that the intrinsics are usable: finite, positive focal lengths and depth scale.
  * \param[in] intrinsics the intrinsics to check
  * \param[out] problem what is wrong, empty when they are valid
  * \return true if valid
  */
bool
validateIntrinsics (const CameraIntrinsics& intrinsics, std::string& problem);

} // namespace io
} // namespace mid
