#pragma once

#include <opencv2/core/mat.hpp>

#include <cstdint>

namespace mid {
namespace simulation {

/** \brief A texture of one colour (a 1x1 image), for plain faces.
  * \param[in] color BGR colour
  * \return the CV_8UC3 texture
  */
cv::Mat
makeUniformTexture (const cv::Vec3b& color);

/** \brief A checkerboard texture, handy for tests of the texture mapping.
  * \param[in] squares_x squares across (positive)
  * \param[in] squares_y squares down (positive)
  * \param[in] square_pixels side of one square in pixels (positive)
  * \param[in] first colour of the top-left square (BGR)
  * \param[in] second colour of the other squares (BGR)
  * \return the CV_8UC3 texture, empty if a size is not positive
  */
cv::Mat
makeCheckerboardTexture (int squares_x,
                         int squares_y,
                         int square_pixels,
                         const cv::Vec3b& first,
                         const cv::Vec3b& second);

/** \brief A random, non-repeating texture (fractal value noise of four octaves, stretched to
  * the full range) blended between two colours: wood or stone-like surfaces whose features do not repeat, so that a table
  * covered by one copy gives no false repeated keypoints.
  * \param[in] width texture width in pixels (positive)
  * \param[in] height texture height in pixels (positive)
  * \param[in] feature_x size of the coarsest noise features along x, in pixels (positive);
  * make it larger than feature_y for a grain along x
  * \param[in] feature_y size of the coarsest noise features along y, in pixels (positive)
  * \param[in] dark colour where the noise is 0 (BGR)
  * \param[in] light colour where the noise is 1 (BGR)
  * \param[in] seed the seed: the same seed gives the same texture on every platform
  * \return the CV_8UC3 texture, empty if a size is not positive
  */
cv::Mat
makeNoiseTexture (int width,
                  int height,
                  double feature_x,
                  double feature_y,
                  const cv::Vec3b& dark,
                  const cv::Vec3b& light,
                  std::uint32_t seed);

} // namespace simulation
} // namespace mid
