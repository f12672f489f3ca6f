#pragma once

#include <mid/features/keypoint_types.h>
#include <mid/registration/triplet_cluster.h>
#include <mid/registration/triplet_match.h>
#include <mid/segmentation/surface_gap.h>

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace mid {

/** \brief Split a cluster whose relative pose links a whole row of copies into one part per
  * pair of neighbouring copies.
  *
  * Copies placed in a regular row (a shelf, a pallet layer) share one relative pose between
  * neighbours: copy 1 -> 2, 2 -> 3, ... all fall into one cluster whose two point sets each
  * span several copies. Abbeloos et al. (3DV 2017, Sec. 5) name this as a limitation of the
  * method; the model built from such a cluster covers several copies. Such a cluster shows
  * itself by a keypoint that is both a target (on copy k + 1) and a source (towards copy k + 2),
  * or by sources spanning more than 1.05 steps along the row; a cluster showing neither (a
  * single pair of copies) is never split. For a chain whose pose is nearly a translation d
  * (rotation below `max_rotation`), every point x gets the chain
  * coordinate s(x) = (x - c) . d / |d|^2 (c: centroid of the source points); copies k and k + 1
  * are one unit apart. Copies cannot interpenetrate, so the keypoints of one copy fill less
  * than a unit of s. A cut c numbers the copies (point x lies on copy floor(s(x) - c)); a cut
  * through the objects puts the sources, and the targets moved back by the stride, on more
  * copies than a cut between copies, so the cut is the middle of the empty interval of s
  * modulo 1 that puts them on the fewest copies (the largest empty interval alone may lie
  * inside the print of every copy when copies touch). Of such intervals, when the surface is
  * given, the one with the most places where the surface shows a gap between the cluster's
  * keypoints next to the cut on either side (each within half a step of it;
  * surfaceDropsBetween(): the floor or the background seen between copies) goes first, then
  * the largest (a print with an empty band wider
  * than the gap between the copies would otherwise be cut).
  * When the span of the sources is the only evidence, they must lie on consecutive copies;
  * otherwise (two pairs of touching copies far apart, or a row whose middle link is missing)
  * the cluster is left whole, for the compound splitting. A triplet whose three source points
  * lie on copy k and whose targets lie on copy k + 1 goes to part k; triplets that straddle
  * copies are dropped.
  * \param[in] cluster the cluster (its triplets, reversed flags and transformation)
  * \param[in] triplets the triplet matches the cluster indexes
  * \param[in] keypoints the frame's keypoints (source and target are one cloud)
  * \param[in] max_rotation clusters whose rotation exceeds this (radians) are not split
  * \param[in] row_step zero, or the step of a row found before of which this cluster's step is
  * a multiple n (|n| >= 2: copies k -> k + n forming a chain of their own): copies are then
  * numbered along row_step, the test for chain evidence is skipped, and a triplet goes to part
  * k when its sources lie on copy k and its targets on copy k + n
  * \param[in] surface the organized frame and the keypoints' pixels (a valid KeypointSurface,
  * not checked), or null: the cut is then chosen without looking at the surface
  * \return per part, positions in cluster.triplets of its member triplets, parts in copy order;
  * a single part holding every triplet when the cluster is not a chain (with row_step: a
  * single part may also be the triplets that link one pair of copies, the others dropped)
  */
std::vector<std::vector<std::size_t>>
splitChainCluster (const TripletCluster& cluster,
                   const TripletMatches& triplets,
                   const KeypointCloud& keypoints,
                   float max_rotation,
                   const Eigen::Vector3f& row_step = Eigen::Vector3f::Zero(),
                   const KeypointSurface* surface = nullptr);

/** \brief The step of a cluster along a row: the displacement its pose gives the centroid of
  * its source keypoints (for a pure translation, the translation).
  * \param[in] cluster the cluster (its transformation and source indices)
  * \param[in] keypoints the frame's keypoints
  * \return the displacement (metres); zero if the cluster has no source keypoint
  */
Eigen::Vector3f
chainStep (const TripletCluster& cluster, const KeypointCloud& keypoints);

} // namespace mid
