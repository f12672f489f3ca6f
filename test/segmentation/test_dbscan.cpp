#include <mid/segmentation/dbscan.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace {

/** Cluster points on a line with |x_i - x_j| as the distance. */
std::vector<int>
clusterLine (const std::vector<double>& x,
             double eps,
             std::size_t min_samples,
             std::vector<bool>* core = nullptr,
             bool reverse_listing = false)
{
  mid::DBSCAN dbscan;
  dbscan.setMinSamples (min_samples);
  auto all_pairs =
      mid::makeAllPairsRegionQuery (x.size(), eps, [&x] (std::size_t i, std::size_t j) {
        return std::abs (x[i] - x[j]);
      });
  const mid::DBSCAN::RegionQuery query = [&] (std::size_t i,
                                              std::vector<mid::DBSCAN::Neighbor>& out) {
    all_pairs (i, out);
    if (reverse_listing)
      std::reverse (out.begin(), out.end());
  };
  std::vector<int> labels;
  dbscan.cluster (x.size(), query, labels, core);
  return labels;
}

} // namespace

TEST (DBSCAN, CoreBorderAndNoise)
{
  // 0..4 spaced by 1 with eps 1.5 and min samples 3: the ends have one neighbour (border).
  const std::vector<double> x{0, 1, 2, 3, 4, 100};
  std::vector<bool> core;
  const auto labels = clusterLine (x, 1.5, 3, &core);
  EXPECT_EQ (labels, (std::vector<int>{0, 0, 0, 0, 0, -1}));
  EXPECT_EQ (core, (std::vector<bool>{false, true, true, true, false, false}));
}

TEST (DBSCAN, ChainsConnectAndGapsSeparate)
{
  std::vector<double> x;
  for (int i = 0; i <= 10; ++i)
    x.push_back (i); // one chain, 11 items
  for (int i = 0; i < 4; ++i)
    x.push_back (20.0 + 0.5 * i); // a second group past a gap
  const auto labels = clusterLine (x, 1.0, 3);
  for (int i = 0; i <= 10; ++i)
    EXPECT_EQ (labels[static_cast<std::size_t> (i)], 0);
  for (std::size_t i = 11; i < x.size(); ++i)
    EXPECT_EQ (labels[i], 1);
  // Too sparse for min samples 4 in the chain: the chain is noise, the dense group stays.
  const auto sparse = clusterLine (x, 1.0, 4);
  for (int i = 0; i <= 10; ++i)
    EXPECT_EQ (sparse[static_cast<std::size_t> (i)], -1);
  EXPECT_EQ (sparse[11], 0);
}

TEST (DBSCAN, ABorderBetweenTwoClustersJoinsTheNearestCoreWithTiesToTheSmallerIndex)
{
  // Item 0 at 2.0 is 1.0 from the core at 1.0 (index 6) and from the core at 3.0 (index 1).
  const std::vector<double> x{
      2.0, 3.0, 3.25, 3.5, 3.75, 4.0, 1.0, 0.75, 0.5, 0.25, 0.0};
  std::vector<bool> core;
  auto labels = clusterLine (x, 1.0, 4, &core);
  EXPECT_FALSE (core[0]);
  EXPECT_TRUE (core[1]);
  EXPECT_TRUE (core[6]);
  EXPECT_EQ (labels[0], labels[1]);
  EXPECT_NE (labels[1], labels[6]);
  // Move the border closer to the left cluster: nearest wins.
  auto moved = x;
  moved[0] = 1.9;
  labels = clusterLine (moved, 1.0, 4);
  EXPECT_EQ (labels[0], labels[6]);
}

TEST (DBSCAN, DoesNotDependOnTheOrderNeighboursAreListed)
{
  const std::vector<double> x{0, 0.4, 0.8, 5, 5.3, 2.5, 9, 9.1, 9.2, 9.3};
  EXPECT_EQ (clusterLine (x, 0.5, 2), clusterLine (x, 0.5, 2, nullptr, true));
}

TEST (DBSCAN, MinSamplesOneMakesEveryItemACluster)
{
  const std::vector<double> x{0, 10, 20};
  EXPECT_EQ (clusterLine (x, 1.0, 1), (std::vector<int>{0, 1, 2}));
  EXPECT_TRUE (clusterLine ({}, 1.0, 3).empty());
}
