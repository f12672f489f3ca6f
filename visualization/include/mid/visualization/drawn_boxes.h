#pragma once

#include <mid/registration/object_model.h>

namespace mid {
namespace visualization {

/** \brief Copies that must agree on an object's box for the pictures (the overlay and the 3D
  * view) to draw it: a box that one copy alone gives is often that copy measured joined with a
  * neighbour.
  */
constexpr int kMinDrawnBoxCopies = 2;

/** \brief Whether the pictures draw an object's box (ModelSize) at its instances. */
inline bool
isBoxDrawn (const ModelSize& size)
{
  return size.valid && size.agreeing >= kMinDrawnBoxCopies;
}

} // namespace visualization
} // namespace mid
