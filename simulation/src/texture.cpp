#include <mid/simulation/texture.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <pcl/console/print.h>

#include <cmath>
#include <fstream>

namespace mid {
namespace simulation {

namespace {

/** Index of texel column/row i (possibly outside the image) under the wrap mode. */
inline int
wrapIndex (int index, int size, TextureWrap wrap)
{
  if (wrap == TextureWrap::REPEAT) {
    index %= size;
    return index < 0 ? index + size : index;
  }
  return index < 0 ? 0 : (index >= size ? size - 1 : index);
}

} // namespace

cv::Mat
toTexture (const cv::Mat& image)
{
  cv::Mat texture;
  if (image.empty())
    return texture;
  if (image.type() == CV_8UC1)
    cv::cvtColor (image, texture, cv::COLOR_GRAY2BGR);
  else if (image.type() == CV_8UC4)
    cv::cvtColor (image, texture, cv::COLOR_BGRA2BGR);
  else
    texture = image;
  return texture;
}

bool
checkTexture (const cv::Mat& texture, std::string& problem)
{
  problem.clear();
  if (texture.empty())
    problem = "the texture is empty";
  else if (texture.type() != CV_8UC3)
    problem = "the texture must be an 8-bit, 3-channel BGR image (CV_8UC3)";
  return problem.empty();
}

bool
loadTexture (const std::string& path, cv::Mat& texture)
{
  texture.release();
  if (!std::ifstream (path, std::ios::binary).good()) {
    PCL_ERROR (
        "[mid::simulation::loadTexture] cannot open '%s' (missing or unreadable)\n",
        path.c_str());
    return false;
  }
  texture = cv::imread (path, cv::IMREAD_COLOR);
  if (texture.empty()) {
    PCL_ERROR ("[mid::simulation::loadTexture] '%s' is not a readable image\n",
               path.c_str());
    return false;
  }
  return true;
}

cv::Vec3f
sampleBilinear (
    const cv::Mat& texture, double s, double t, TextureWrap wrap_s, TextureWrap wrap_t)
{
  const double x = s * texture.cols - 0.5;
  const double y = t * texture.rows - 0.5;
  const double x_floor = std::floor (x);
  const double y_floor = std::floor (y);
  const auto wx = static_cast<float> (x - x_floor);
  const auto wy = static_cast<float> (y - y_floor);
  // Clamp before the conversion to int: coordinates far outside must not overflow.
  const double limit = 1e8;
  const int x0 = static_cast<int> (std::fmax (-limit, std::fmin (limit, x_floor)));
  const int y0 = static_cast<int> (std::fmax (-limit, std::fmin (limit, y_floor)));
  const int c0 = wrapIndex (x0, texture.cols, wrap_s);
  const int c1 = wrapIndex (x0 + 1, texture.cols, wrap_s);
  const auto* row0 = texture.ptr<cv::Vec3b> (wrapIndex (y0, texture.rows, wrap_t));
  const auto* row1 = texture.ptr<cv::Vec3b> (wrapIndex (y0 + 1, texture.rows, wrap_t));
  const cv::Vec3f top_left (row0[c0]), top_right (row0[c1]);
  const cv::Vec3f bottom_left (row1[c0]), bottom_right (row1[c1]);
  const cv::Vec3f top = top_left + (top_right - top_left) * wx;
  const cv::Vec3f bottom = bottom_left + (bottom_right - bottom_left) * wx;
  const cv::Vec3f color = top + (bottom - top) * wy;
  return color;
}

} // namespace simulation
} // namespace mid
