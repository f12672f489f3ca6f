#include <mid/visualization/object_colors.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace mid {
namespace visualization {

namespace {

/** Sky blue, magenta, green, yellow, red, violet, aquamarine, orange, lime, rose. */
constexpr std::array<ObjectColor, OBJECT_PALETTE_SIZE> kPalette{{{0, 190, 255},
                                                                 {255, 40, 200},
                                                                 {40, 220, 40},
                                                                 {255, 230, 0},
                                                                 {255, 40, 40},
                                                                 {150, 90, 255},
                                                                 {0, 230, 170},
                                                                 {255, 120, 0},
                                                                 {180, 255, 60},
                                                                 {255, 120, 150}}};

/** A fully saturated, bright color of the given hue (degrees). */
ObjectColor
hueColor (double hue)
{
  const double sector = hue / 60.0;
  const auto channel = [sector] (double offset) {
    // HSV with S = V = 1: 255 near the hue, 0 opposite, a linear ramp in between.
    const double k = std::fmod (offset + sector, 6.0);
    const double value = 1.0 - std::max (0.0, std::min ({k, 4.0 - k, 1.0}));
    return static_cast<std::uint8_t> (std::lround (255.0 * value));
  };
  return {channel (5.0), channel (3.0), channel (1.0)};
}

} // namespace

ObjectColor
objectColor (std::size_t id)
{
  if (id < kPalette.size())
    return kPalette[id];
  constexpr double kGoldenAngle = 137.50776405003785;
  return hueColor (
      std::fmod (static_cast<double> (id - kPalette.size()) * kGoldenAngle, 360.0));
}

} // namespace visualization
} // namespace mid
