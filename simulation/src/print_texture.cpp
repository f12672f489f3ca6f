#include <mid/simulation/deterministic_random.h>
#include <mid/simulation/print_texture.h>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <string>
#include <vector>

namespace mid {
namespace simulation {

namespace {

cv::Scalar
scalar (const cv::Vec3b& color)
{
  return cv::Scalar (color[0], color[1], color[2]);
}

/** A random word of the given length range, upper or lower case. */
std::string
randomWord (int shortest, int longest, bool upper, DeterministicRandom& random)
{
  const int length = shortest + random.uniformInt (longest - shortest + 1);
  std::string word;
  for (int i = 0; i < length; ++i)
    word += static_cast<char> ((upper ? 'A' : 'a') + random.uniformInt (26));
  return word;
}

/** Draw text that fits the given box (left, baseline at the bottom), scaled to its height or
  * narrowed to its width.
  */
void
drawText (cv::Mat& image,
          const std::string& text,
          const cv::Rect& box,
          int font,
          const cv::Vec3b& color)
{
  int baseline = 0;
  const cv::Size unit = cv::getTextSize (text, font, 1.0, 1, &baseline);
  const double scale =
      std::min (box.height / static_cast<double> (unit.height + baseline),
                box.width / static_cast<double> (std::max (unit.width, 1)));
  const int thickness = std::max (1, static_cast<int> (scale * 1.5));
  cv::putText (
      image,
      text,
      cv::Point (box.x, box.y + box.height - static_cast<int> (baseline * scale)),
      font,
      scale,
      scalar (color),
      thickness,
      cv::LINE_AA);
}

void
drawBarcode (cv::Mat& image,
             const cv::Rect& box,
             const cv::Vec3b& ink,
             DeterministicRandom& random)
{
  int x = box.x;
  const int unit = std::max (1, box.width / 60);
  while (x < box.x + box.width) {
    const int bar = unit * (1 + random.uniformInt (3));
    const int space = unit * (1 + random.uniformInt (2));
    cv::rectangle (
        image,
        cv::Rect (x, box.y, std::min (bar, box.x + box.width - x), box.height),
        scalar (ink),
        cv::FILLED);
    x += bar + space;
  }
}

/** A logo centred at center: a ringed disc, a framed square or a triangle, as drawn. */
void
drawLogo (cv::Mat& image,
          const cv::Point& center,
          int radius,
          const cv::Vec3b& ink,
          const cv::Vec3b& accent,
          DeterministicRandom& random)
{
  const int stroke = std::max (1, radius / 5);
  switch (random.uniformInt (3)) {
  case 0:
    cv::circle (image, center, radius, scalar (accent), cv::FILLED, cv::LINE_AA);
    cv::circle (image, center, radius * 2 / 3, scalar (ink), stroke, cv::LINE_AA);
    break;
  case 1: {
    const cv::Point corner (radius, radius), inner (radius / 2, radius / 2);
    cv::rectangle (image, center - corner, center + corner, scalar (ink), cv::FILLED);
    cv::rectangle (image, center - inner, center + inner, scalar (accent), stroke);
    break;
  }
  default: {
    const std::vector<cv::Point> triangle = {center + cv::Point (0, -radius),
                                             center + cv::Point (radius, radius),
                                             center + cv::Point (-radius, radius)};
    cv::fillConvexPoly (image, triangle, scalar (accent), cv::LINE_AA);
    cv::circle (image,
                center + cv::Point (0, radius / 3),
                radius / 3,
                scalar (ink),
                cv::FILLED);
  }
  }
}

} // namespace

cv::Mat
makePrintTexture (int width,
                  int height,
                  const cv::Vec3b& paper,
                  const cv::Vec3b& ink,
                  const cv::Vec3b& accent,
                  std::uint32_t seed)
{
  if (width < 32 || height < 32)
    return cv::Mat();
  DeterministicRandom random (seed);
  cv::Mat image (height, width, CV_8UC3, scalar (paper));
  const int margin = std::max (2, width / 16);
  const int inner = width - 2 * margin;

  // Band with the brand word, then a subtitle.
  const int band_top = static_cast<int> (height * random.uniform (0.04, 0.2));
  const int band_height = std::max (8, height / 7);
  cv::rectangle (
      image, cv::Rect (0, band_top, width, band_height), scalar (accent), cv::FILLED);
  drawText (image,
            randomWord (4, 8, true, random),
            cv::Rect (margin, band_top + band_height / 8, inner, band_height * 3 / 4),
            cv::FONT_HERSHEY_DUPLEX,
            paper);
  int y = band_top + band_height + height / 40;
  const int subtitle = std::max (6, height / 22);
  drawText (image,
            randomWord (5, 10, false, random),
            cv::Rect (margin, y, inner * 3 / 4, subtitle),
            cv::FONT_HERSHEY_SIMPLEX,
            ink);
  y += subtitle + height / 30;

  // A table of small text lines between rules, above a logo and, on some faces, a barcode.
  const int line = std::max (5, height / 32);
  const int bottom = height - height / 4;
  const int rule_every = 2 + random.uniformInt (3);
  for (int row = 0; y + line < bottom; ++row) {
    if (row % rule_every == 0)
      cv::line (image,
                cv::Point (margin, y),
                cv::Point (width - margin, y),
                scalar (ink),
                std::max (1, line / 6));
    y += line / 4;
    const std::string text =
        randomWord (2, 7, false, random) + " " + randomWord (2, 6, false, random);
    const int length = inner * (2 + random.uniformInt (3)) / 4;
    drawText (
        image, text, cv::Rect (margin, y, length, line), cv::FONT_HERSHEY_PLAIN, ink);
    y += line + line / 4;
  }
  const int radius = std::max (
      4, static_cast<int> (std::min (width, height) * random.uniform (0.07, 0.12)));
  const cv::Point logo (margin + radius +
                            random.uniformInt (std::max (1, inner - 2 * radius)),
                        bottom + radius / 2 + height / 80);
  drawLogo (image, logo, radius, ink, accent, random);
  if (random.uniform() < 0.5)
    drawBarcode (
        image,
        cv::Rect (width / 2, height - height / 9, width / 2 - margin, height / 14),
        ink,
        random);
  return image;
}

} // namespace simulation
} // namespace mid
