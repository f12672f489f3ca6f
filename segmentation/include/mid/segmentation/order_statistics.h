#pragma once

// Order statistics of a list of values, for the steps that read a robust level or extent off
// noisy points (a median height, the 99.5 % quantile of an extent).

#include <algorithm>
#include <cstddef>
#include <vector>

namespace mid {

/** \brief The value below which a share q of `values` lies: the one at position
  * q * (size - 1), rounded down, of the sorted values.
  * \param[in,out] values the values (reordered; not empty)
  * \param[in] q the share (in [0, 1])
  * \return that value
  */
inline float
quantile (std::vector<float>& values, float q)
{
  const auto at = values.begin() + static_cast<std::ptrdiff_t> (
                                       q * static_cast<float> (values.size() - 1));
  std::nth_element (values.begin(), at, values.end());
  return *at;
}

/** \brief The median of `values`: the one at position size / 2 of the sorted values (the upper
  * of the two middle ones for an even count).
  * \param[in,out] values the values (reordered; not empty)
  * \return that value
  */
inline float
median (std::vector<float>& values)
{
  const auto middle = values.begin() + static_cast<std::ptrdiff_t> (values.size() / 2);
  std::nth_element (values.begin(), middle, values.end());
  return *middle;
}

} // namespace mid
