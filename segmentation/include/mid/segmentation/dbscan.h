#pragma once

#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

namespace mid {

/** \brief Density-based clustering (DBSCAN, Ester et al., KDD 1996) over an abstract distance.
  *
  * The items are 0 .. n-1; a region query lists, for one item, every OTHER item within eps with
  * its distance. An item is a core item if it has at least min_samples items within eps,
  * itself included (scikit-learn's convention). Core items within eps of each other share a
  * cluster; a non-core item within eps of a core item is a border item and joins the cluster of
  * its nearest core item (ties: the smaller index); every other item is noise (label -1).
  * Clusters are numbered 0, 1, ... in the order of their smallest core item. The result depends only
  * on the distances, not on the order in which the query lists neighbours.
  *
  * Each item is queried twice (once to find the core items, once to connect them), so memory
  * stays O(n) whatever the density.
  */
class DBSCAN
{
public:
  /** \brief One neighbour: item index and its distance (<= eps) to the queried item. */
  using Neighbor = std::pair<std::size_t, double>;
  /** \brief query (i, neighbors): fill `neighbors` with every j != i within eps of i. */
  using RegionQuery = std::function<void (std::size_t, std::vector<Neighbor>&)>;

  /** \brief Items (itself included) within eps that make an item a core item. Default 14
    * (Abbeloos et al.: a cluster needs 14 triplet matches). 0 gives no clusters at all (see
    * cluster()).
    */
  ///@{
  void
  setMinSamples (std::size_t min_samples)
  {
    min_samples_ = min_samples;
  }
  std::size_t
  getMinSamples () const
  {
    return min_samples_;
  }
  ///@}

  /** \brief Cluster n items.
    * \param[in] n number of items
    * \param[in] query the region query (its eps is the clustering distance)
    * \param[out] labels cluster of each item, -1 for noise; empty if min_samples is 0
    * \param[out] core whether each item is a core item (optional)
    * \return the number of clusters
    */
  std::size_t
  cluster (std::size_t n,
           const RegionQuery& query,
           std::vector<int>& labels,
           std::vector<bool>* core = nullptr) const;

private:
  std::size_t min_samples_ = 14;
};

/** \brief A region query that compares an item with all others: for tests and small n.
  * \param[in] n number of items; the query must only be called with items below n
  * \param[in] eps the clustering distance: neighbours are the items j != i with
  *            distance (i, j) <= eps (in the distance's unit)
  * \param[in] distance the distance between two items (symmetric); a NaN distance never
  *            makes a neighbour
  * \return the query, which keeps a copy of distance
  */
DBSCAN::RegionQuery
makeAllPairsRegionQuery (std::size_t n,
                         double eps,
                         std::function<double (std::size_t, std::size_t)> distance);

} // namespace mid
