#pragma once

#include <pcl/correspondence.h>
#include <pcl/types.h>

#include <algorithm>
#include <iterator>

namespace mid {
namespace detail {

/** \brief The keypoints two sorted index lists share, sorted. */
inline pcl::Indices
sharedKeypoints (const pcl::Indices& a, const pcl::Indices& b)
{
  pcl::Indices shared;
  std::set_intersection (
      a.begin(), a.end(), b.begin(), b.end(), std::back_inserter (shared));
  return shared;
}

/** \brief The keypoints of either of two sorted index lists, sorted, each once. */
inline pcl::Indices
allKeypoints (const pcl::Indices& a, const pcl::Indices& b)
{
  pcl::Indices all;
  std::set_union (a.begin(), a.end(), b.begin(), b.end(), std::back_inserter (all));
  return all;
}

/** \brief The source of a triplet's keypoint pair as its cluster uses it (reversed or not). */
inline pcl::index_t
sourceOf (const pcl::Correspondence& c, bool reversed)
{
  return reversed ? c.index_match : c.index_query;
}

/** \brief The target of a triplet's keypoint pair as its cluster uses it. */
inline pcl::index_t
targetOf (const pcl::Correspondence& c, bool reversed)
{
  return reversed ? c.index_query : c.index_match;
}

} // namespace detail
} // namespace mid
