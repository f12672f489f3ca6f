#pragma once

#include <opencv2/core/mat.hpp>

#include <cstdint>

namespace mid {
namespace simulation {

/** \brief A printed face of a package: a coloured band with a brand word, a subtitle, a block of
  * small text lines between rules (like a nutrition table), a round logo and a barcode, all
  * drawn with OpenCV's Hershey fonts from random letters. Gives the corners and blobs real
  * packaging shows on its sides and back, without third-party artwork; different seeds give
  * different faces.
  * \param[in] width texture width in pixels, at least 32
  * \param[in] height texture height in pixels, at least 32
  * \param[in] paper background colour (BGR)
  * \param[in] ink colour of the text, rules and barcode (BGR)
  * \param[in] accent colour of the band and the logo (BGR)
  * \param[in] seed the seed: the same seed gives the same face
  * \return the CV_8UC3 texture, empty if a size is too small
  */
cv::Mat
makePrintTexture (int width,
                  int height,
                  const cv::Vec3b& paper,
                  const cv::Vec3b& ink,
                  const cv::Vec3b& accent,
                  std::uint32_t seed);

} // namespace simulation
} // namespace mid
