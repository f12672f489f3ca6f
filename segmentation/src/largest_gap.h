#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace mid {
namespace detail {

/** \brief The phase in [0, 1) at the middle of the largest empty interval between the given
  * phases (each in [0, 1)) on the unit circle: where to cut a periodic arrangement so that no
  * group of points is cut in two.
  * \param[in] phases at least one phase, each in [0, 1)
  */
inline double
cutOfLargestGap (std::vector<double> phases)
{
  std::sort (phases.begin(), phases.end());
  double best_gap = phases.front() + 1.0 - phases.back(),
         cut = phases.back() + best_gap / 2;
  for (std::size_t i = 1; i < phases.size(); ++i)
    if (phases[i] - phases[i - 1] > best_gap) {
      best_gap = phases[i] - phases[i - 1];
      cut = phases[i - 1] + best_gap / 2;
    }
  return cut - std::floor (cut);
}

} // namespace detail
} // namespace mid
