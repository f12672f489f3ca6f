#pragma once

#include <mid/features/keypoint_types.h>

#include <pcl/correspondence.h>

#include <cstdint>
#include <vector>

namespace mid {
namespace detail {

/** \brief A match used in one direction: P side keypoint p (source), Q side keypoint q
  * (target), its descriptor distance, and which unique match it came from.
  */
struct UniqueMatch
{
  pcl::index_t p = 0;
  pcl::index_t q = 0;
  float distance = 0.0f;
};

/** \brief Thresholds of the pair test (see CorrespondenceRejectorPPFTriplet). */
struct PairCriteria
{
  float max_distance_difference = 0.0f;
  float max_angle_difference = 0.0f;
  float min_edge_length = 0.0f;
  float max_edge_length = 0.0f;
};

/** \brief The graph of compatible pairs of matches: nodes are unique matches ranked by
  * descriptor distance, an edge (a, b, r) with a < b says that match b used in direction r
  * (0 = as given, 1 = reversed) is compatible with match a used as given.
  */
class CompatibleMatchGraph
{
public:
  /** \brief Build the graph. With allow_reversal, match b is also tried as q -> p, and the four
    * keypoints of a pair must all differ (both triangles live in one frame). Candidates are
    * found with a radius search of the maximum edge length around each match's P side, so the
    * cost grows with M times the number of matches nearby rather than with M^2.
    */
  CompatibleMatchGraph (const std::vector<UniqueMatch>& matches,
                        const KeypointCloud::ConstPtr& source,
                        const KeypointCloud& target,
                        const PairCriteria& criteria,
                        bool allow_reversal);

  /** \brief Neighbours of a with a larger rank, encoded 2 b + r, sorted ascending. */
  const std::vector<std::uint32_t>&
  successors (std::size_t a) const
  {
    return successors_[a];
  }

  /** \brief True if (b, r) is a successor of a. */
  bool
  hasEdge (std::size_t a, std::uint32_t encoded_b) const;

  /** \brief Number of edges (compatible oriented pairs). */
  std::size_t
  size () const;

private:
  std::vector<std::vector<std::uint32_t>> successors_;
};

} // namespace detail
} // namespace mid
