#pragma once

#include <opencv2/core/mat.hpp>

#include <string>

namespace mid {
namespace simulation {

/** \brief What a texture lookup outside [0, 1] does. */
enum class TextureWrap {
  /** \brief Repeat the border texel (a texture stretched once over a face). */
  CLAMP,
  /** \brief Repeat the texture (tiled surfaces such as a table top). */
  REPEAT
};

/** \brief Convert an image to the texture format of this module, 8-bit BGR (CV_8UC3): gray
  * and BGRA 8-bit images are converted, any other image is returned unchanged (and then
  * refused by checkTexture()).
  * \param[in] image the image
  * \return the texture (sharing data with image when no conversion was needed)
  */
cv::Mat
toTexture (const cv::Mat& image);

/** \brief Check that an image is a usable texture: non-empty 8-bit BGR (CV_8UC3).
  * \param[in] texture the texture to check
  * \param[out] problem what is wrong, empty when it is usable
  * \return true if usable
  */
bool
checkTexture (const cv::Mat& texture, std::string& problem);

/** \brief Read a texture (PNG, JPG, ...) as 8-bit BGR.
  * \param[in] path the image file
  * \param[out] texture the texture; empty when false is returned
  * \return true on success, false (with a PCL_ERROR naming the problem) otherwise
  */
bool
loadTexture (const std::string& path, cv::Mat& texture);

/** \brief Bilinear lookup of a texture at texture coordinates (s, t).
  *
  * (0, 0) is the top-left corner of the image and (1, 1) its bottom-right corner, so that the
  * texel (i, j) covers [i / width, (i + 1) / width] x [j / height, (j + 1) / height] and its
  * colour is returned exactly at its centre.
  * \param[in] texture a texture that passed checkTexture()
  * \param[in] s horizontal coordinate (1 = image width)
  * \param[in] t vertical coordinate (1 = image height)
  * \param[in] wrap_s what s outside [0, 1] does
  * \param[in] wrap_t what t outside [0, 1] does
  * \return the BGR colour, channels in [0, 255]
  */
cv::Vec3f
sampleBilinear (const cv::Mat& texture,
                double s,
                double t,
                TextureWrap wrap_s = TextureWrap::CLAMP,
                TextureWrap wrap_t = TextureWrap::CLAMP);

} // namespace simulation
} // namespace mid
