#include <mid/simulation/deterministic_random.h>
#include <mid/simulation/procedural_texture.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace mid {
namespace simulation {

namespace {

constexpr int kNoiseOctaves = 4;

/** One octave of value noise: random values on a grid with the given spacing, smoothly
  * interpolated; added with the given weight into noise (width x height, row-major).
  */
void
addValueNoiseOctave (int width,
                     int height,
                     double spacing_x,
                     double spacing_y,
                     double weight,
                     DeterministicRandom& random,
                     std::vector<double>& noise)
{
  const int grid_x = static_cast<int> (std::ceil (width / spacing_x)) + 2;
  const int grid_y = static_cast<int> (std::ceil (height / spacing_y)) + 2;
  std::vector<double> grid (static_cast<std::size_t> (grid_x) * grid_y);
  for (double& value : grid)
    value = random.uniform();
  const auto smooth = [] (double w) { return w * w * (3.0 - 2.0 * w); };
  for (int y = 0; y < height; ++y) {
    const double gy = y / spacing_y;
    const int iy = static_cast<int> (gy);
    const double wy = smooth (gy - iy);
    for (int x = 0; x < width; ++x) {
      const double gx = x / spacing_x;
      const int ix = static_cast<int> (gx);
      const double wx = smooth (gx - ix);
      const double* top = &grid[static_cast<std::size_t> (iy) * grid_x + ix];
      const double* bottom = top + grid_x;
      const double upper = top[0] + wx * (top[1] - top[0]);
      const double lower = bottom[0] + wx * (bottom[1] - bottom[0]);
      noise[static_cast<std::size_t> (y) * width + x] +=
          weight * (upper + wy * (lower - upper));
    }
  }
}

} // namespace

cv::Mat
makeUniformTexture (const cv::Vec3b& color)
{
  return cv::Mat (1, 1, CV_8UC3, cv::Scalar (color[0], color[1], color[2]));
}

cv::Mat
makeCheckerboardTexture (int squares_x,
                         int squares_y,
                         int square_pixels,
                         const cv::Vec3b& first,
                         const cv::Vec3b& second)
{
  if (squares_x <= 0 || squares_y <= 0 || square_pixels <= 0)
    return cv::Mat();
  cv::Mat texture (squares_y * square_pixels, squares_x * square_pixels, CV_8UC3);
  for (int y = 0; y < texture.rows; ++y) {
    auto* row = texture.ptr<cv::Vec3b> (y);
    for (int x = 0; x < texture.cols; ++x)
      row[x] = ((x / square_pixels + y / square_pixels) % 2 == 0) ? first : second;
  }
  return texture;
}

cv::Mat
makeNoiseTexture (int width,
                  int height,
                  double feature_x,
                  double feature_y,
                  const cv::Vec3b& dark,
                  const cv::Vec3b& light,
                  std::uint32_t seed)
{
  if (width <= 0 || height <= 0 || !(feature_x > 0.0) || !(feature_y > 0.0))
    return cv::Mat();
  DeterministicRandom random (seed);
  std::vector<double> noise (static_cast<std::size_t> (width) * height, 0.0);
  double weight = 1.0;
  for (int octave = 0; octave < kNoiseOctaves; ++octave) {
    const double divisor = std::pow (2.0, octave);
    addValueNoiseOctave (width,
                         height,
                         std::max (1.0, feature_x / divisor),
                         std::max (1.0, feature_y / divisor),
                         weight,
                         random,
                         noise);
    weight *= 0.5;
  }
  // Stretch to the full [0, 1] range: a sum of octaves clusters around its mean.
  const auto range = std::minmax_element (noise.begin(), noise.end());
  const double low = *range.first;
  const double span = std::max (*range.second - low, 1e-12);
  cv::Mat texture (height, width, CV_8UC3);
  for (int y = 0; y < height; ++y) {
    auto* row = texture.ptr<cv::Vec3b> (y);
    for (int x = 0; x < width; ++x) {
      const double value =
          (noise[static_cast<std::size_t> (y) * width + x] - low) / span;
      for (int channel = 0; channel < 3; ++channel)
        row[x][channel] = cv::saturate_cast<std::uint8_t> (
            dark[channel] + value * (light[channel] - dark[channel]));
    }
  }
  return texture;
}

} // namespace simulation
} // namespace mid
