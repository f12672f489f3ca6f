#pragma once

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <vector>

namespace mid {
namespace detail {

/** \brief Union-find with path halving over 0 .. n-1; the root of a set is its smallest
  * member (DBSCAN's clusters, the touching surfaces of SizeInstanceSearch).
  */
class DisjointSets
{
public:
  explicit DisjointSets (std::size_t n) : parent_ (n)
  {
    std::iota (parent_.begin(), parent_.end(), std::size_t{0});
  }

  /** \brief The root (smallest member) of i's set. */
  std::size_t
  find (std::size_t i)
  {
    while (parent_[i] != i) {
      parent_[i] = parent_[parent_[i]];
      i = parent_[i];
    }
    return i;
  }

  /** \brief Join the sets of a and b. */
  void
  unite (std::size_t a, std::size_t b)
  {
    a = find (a);
    b = find (b);
    if (a != b)
      parent_[std::max (a, b)] = std::min (a, b);
  }

private:
  std::vector<std::size_t> parent_;
};

} // namespace detail
} // namespace mid
