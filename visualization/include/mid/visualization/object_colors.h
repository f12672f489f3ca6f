#pragma once

#include <cstddef>
#include <cstdint>

namespace mid {
namespace visualization {

/** \brief An 8-bit RGB color. */
struct ObjectColor
{
  /** \brief Red, green and blue, 0..255. */
  ///@{
  std::uint8_t r = 0;
  std::uint8_t g = 0;
  std::uint8_t b = 0;
  ///@}
};

/** \brief Number of hand-picked colors in the palette of objectColor(). */
constexpr std::size_t OBJECT_PALETTE_SIZE = 10;

/** \brief The color of object `id` (its index in DiscoveryResult::models) in every picture of a
  * result: the overlay, the scene viewer and its model panel.
  *
  * Deterministic: the same id always gets the same color. The first OBJECT_PALETTE_SIZE ids get
  * ten saturated, mutually distinct colors chosen to stand out on warm (wood, cardboard) scenes
  * and on the viewer's dark background: sky blue, magenta, green, yellow, red, violet,
  * aquamarine, orange, lime, rose. Further ids get fully saturated hues spaced by the golden
  * angle (137.5 degrees), so that neighbouring ids are always far apart on the color wheel.
  * \param[in] id the object's index
  * \return its color
  */
ObjectColor
objectColor (std::size_t id);

} // namespace visualization
} // namespace mid
