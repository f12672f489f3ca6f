#pragma once

#include <vector>

namespace mid {

/** \brief Widen the extent across an object lying on the support plane with a round side (a
  * can lying down) to its diameter (not in the paper).
  *
  * The camera sees only the half of a lying cylinder turned towards it: its points span
  * r (1 + sin e) across it, at an elevation e of the view, where the box of a copy standing
  * up or seen from above spans 2 r. This function looks at the object's cross-section: the
  * positions of its points across it (`across`, along the plane) and their heights above the
  * plane. It finds the circle standing on the plane that the points lie on most closely
  * (median distance; centres up to 8 mm from the middle of the points within 2 mm of the
  * top, radii between 0.8 and 1 times half of `height`, by 0.5 mm; scored on at most 400
  * points, evenly taken), and the extent
  * [low, high] becomes that circle's when
  * - it spans less than the height less 5 mm,
  * - the points lie within 2.5 mm of the circle (median),
  * - on one side of the centre they reach at least 0.8 times the radius (the side seen
  *   whole), and on neither side more than the radius plus 5 mm (the circle holds them).
  * A flat top (a box, a can standing up) has corners far off any such circle, and a box seen
  * along its top edge reaches beyond it: they stay as they are.
  *
  * \param[in] across the points' positions across the object (metres)
  * \param[in] heights their heights above the plane (metres), one per position
  * \param[in] height the object's height (metres)
  * \param[in,out] low, high the extent across the object (metres; positions as `across`)
  * \return true if the extent was widened; false if not, also (with a PCL_ERROR) when the
  * positions and heights differ in number, a value is not finite or low > high
  */
bool
widenToRoundSide (const std::vector<float>& across,
                  const std::vector<float>& heights,
                  float height,
                  float& low,
                  float& high);

} // namespace mid
