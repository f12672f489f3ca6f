#pragma once

#include <mid/simulation/rendered_frame.h>

#include <pcl/point_cloud.h>

#include <string>

namespace mid {
namespace simulation {

/** \brief Metres per unit of a millimetre depth PNG, the depth scale of the files written here
  * (as in BOP and the TUM-style loaders of mid::io with depth_scale 0.001).
  */
constexpr double MILLIMETRE_DEPTH_SCALE = 0.001;

/** \brief Quantize a metric depth image into 16-bit units of depth_scale metres:
  * value = round (z / depth_scale). 0, negative and non-finite depths become 0 (no
  * measurement), and so do depths beyond 65535 units (65.5 m in millimetres), which cannot be
  * stored.
  * \param[in] depth CV_32FC1 depth in metres
  * \param[in] depth_scale metres per unit (positive), e.g. MILLIMETRE_DEPTH_SCALE
  * \param[out] depth_16u CV_16UC1 depth; empty when false is returned
  * \return false (with a PCL_ERROR) if the input or the scale is invalid
  */
bool
quantizeDepth (const cv::Mat& depth, double depth_scale, cv::Mat& depth_16u);

/** \brief Organized cloud (metres, camera frame) of a frame: its depth quantized with
  * quantizeDepth(), then back-projected with mid::io::rgbdToCloud(), exactly as a loader of the
  * written PNG pair would do. Pixels without depth are NaN points; point coordinates carry the
  * quantization error (at most depth_scale / 2 along z).
  * \param[in] frame a rendered (or sensor-model) frame
  * \param[in] depth_scale metres per depth unit; a smaller scale gives finer points
  * (e.g. 1e-5 for a 0.65 m range)
  * \param[out] cloud camera.width x camera.height cloud; cleared when false is returned
  * \return false (with a PCL_ERROR) if the frame is invalid or has no valid depth
  */
template <typename PointT>
bool
frameToCloud (const RenderedFrame& frame,
              double depth_scale,
              pcl::PointCloud<PointT>& cloud);

/** \brief Write the colour image (PNG or JPG, by extension) and the 16-bit depth PNG of a frame
  * (units of depth_scale metres). Each file is written under a temporary name and renamed into
  * place only when both were written, so a failure leaves neither half-written.
  * \param[in] frame the frame
  * \param[in] color_path colour image file
  * \param[in] depth_path depth image file (must end in .png)
  * \param[in] depth_scale metres per depth unit, e.g. MILLIMETRE_DEPTH_SCALE
  * \return false (with a PCL_ERROR) on any problem
  */
bool
writeFrameImages (const RenderedFrame& frame,
                  const std::string& color_path,
                  const std::string& depth_path,
                  double depth_scale = MILLIMETRE_DEPTH_SCALE);

} // namespace simulation
} // namespace mid
