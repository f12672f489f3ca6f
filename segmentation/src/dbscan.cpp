#include "disjoint_sets.h"

#include <mid/segmentation/dbscan.h>

#include <algorithm>
#include <limits>

namespace mid {

std::size_t
DBSCAN::cluster (std::size_t n,
                 const RegionQuery& query,
                 std::vector<int>& labels,
                 std::vector<bool>* core) const
{
  labels.assign (n, -1);
  std::vector<bool> is_core (n, false);
  if (min_samples_ == 0) {
    labels.clear();
    return 0;
  }
  std::vector<Neighbor> neighbors;
  for (std::size_t i = 0; i < n; ++i) {
    query (i, neighbors);
    is_core[i] = neighbors.size() + 1 >= min_samples_;
  }

  detail::DisjointSets sets (n);
  std::vector<std::size_t> nearest_core (n, n);
  std::vector<double> nearest_distance (n, std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < n; ++i) {
    query (i, neighbors);
    for (const auto& [j, distance] : neighbors) {
      if (is_core[i] && is_core[j])
        sets.unite (i, j);
      else if (!is_core[i] && is_core[j] &&
               (distance < nearest_distance[i] ||
                (distance == nearest_distance[i] && j < nearest_core[i]))) {
        nearest_distance[i] = distance;
        nearest_core[i] = j;
      }
    }
  }

  std::vector<int> label_of_root (n, -1);
  int clusters = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!is_core[i])
      continue;
    const std::size_t root = sets.find (i);
    if (label_of_root[root] < 0)
      label_of_root[root] = clusters++;
    labels[i] = label_of_root[root];
  }
  for (std::size_t i = 0; i < n; ++i)
    if (!is_core[i] && nearest_core[i] < n)
      labels[i] = labels[nearest_core[i]];
  if (core != nullptr)
    *core = is_core;
  return static_cast<std::size_t> (clusters);
}

DBSCAN::RegionQuery
makeAllPairsRegionQuery (std::size_t n,
                         double eps,
                         std::function<double (std::size_t, std::size_t)> distance)
{
  return [n, eps, distance = std::move (distance)] (
             std::size_t i, std::vector<DBSCAN::Neighbor>& out) {
    out.clear();
    for (std::size_t j = 0; j < n; ++j) {
      if (j == i)
        continue;
      const double d = distance (i, j);
      if (d <= eps)
        out.emplace_back (j, d);
    }
  };
}

} // namespace mid
