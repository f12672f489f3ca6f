#pragma once

#include <mid/features/keypoint_types.h>
#include <mid/registration/triplet_cluster.h>
#include <mid/registration/triplet_match.h>

#include <cstddef>
#include <vector>

namespace mid {

/** \brief Split a cluster whose relative pose links a whole row of copies into one part per
  * pair of neighbouring copies.
  *
  * Copies placed in a regular row (a shelf, a pallet layer) share one relative pose between
  * neighbours: copy 1 -> 2, 2 -> 3, ... all fall into one cluster whose two point sets each
  * span several copies. Abbeloos et al. (3DV 2017, Sec. 5) name this as a limitation of the
  * method; the model built from such a cluster covers several copies. For a cluster whose pose
  * is nearly a translation d (rotation below `max_rotation`), every point x gets the chain
  * coordinate s(x) = (x - c) . d / |d|^2 (c: centroid of the source points); copies k and k + 1
  * are one unit apart. Copies cannot interpenetrate, so the keypoints of one copy fill less
  * than a unit of s, and the largest empty interval of s modulo 1 separates neighbouring
  * copies: it gives every point its copy number. A triplet whose three source points lie on
  * copy k and whose targets lie on copy k + 1 goes to part k; triplets that straddle copies are
  * dropped. A cluster whose sources all lie on one copy (the usual pair of instances) is one
  * part.
  * \param[in] cluster the cluster (its triplets, reversed flags and transformation)
  * \param[in] triplets the triplet matches the cluster indexes
  * \param[in] keypoints the frame's keypoints (source and target are one cloud)
  * \param[in] max_rotation clusters whose rotation exceeds this (radians) are not split
  * \return per part, positions in cluster.triplets of its member triplets, parts in copy order;
  * a single part holding every triplet when the cluster is not a chain
  */
std::vector<std::vector<std::size_t>>
splitChainCluster (const TripletCluster& cluster,
                   const TripletMatches& triplets,
                   const KeypointCloud& keypoints,
                   float max_rotation);

} // namespace mid
