#pragma once

namespace mid {
namespace detail {

/** Running sums of paired samples (x, y): their count, sums, sums of squares and sum of
  * products, which is all a least-squares line or a correlation of the pairs needs.
  */
struct PairedSums
{
  double n = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, syy = 0.0, sxy = 0.0;

  void
  add (double x, double y)
  {
    n += 1.0;
    sx += x;
    sy += y;
    sxx += x * x;
    syy += y * y;
    sxy += x * y;
  }
};

} // namespace detail
} // namespace mid
