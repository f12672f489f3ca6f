#pragma once

#include <mid/features/keypoint_types.h>
#include <mid/registration/triplet_cluster.h>
#include <mid/registration/triplet_match.h>
#include <mid/segmentation/surface_gap.h>

#include <cstddef>
#include <vector>

namespace mid {

/** \brief What becomes of one triplet of a cluster whose point sets span two touching copies
  * (see orientHalfTurnCluster()).
  */
enum class TripletOrientation {
  keep,    ///< stays as it is
  reverse, ///< used in the other direction (its targets become its sources)
  drop     ///< straddles the two copies: removed from the cluster
};

/** \brief Orient a cluster whose pose is a half turn swapping two touching copies.
  *
  * Two copies placed head to tail (one turned by 180 degrees about an axis between them, as a
  * box turned around next to its twin) are related by a half turn M, and M is its own inverse:
  * the matches copy A -> copy B and copy B -> copy A fall into one cluster, each of whose point
  * sets spans both copies. The model built from it would cover both copies as one instance.
  * Abbeloos et al. (3DV 2017, Sec. 5) list such pairs sharing one relative pose as a
  * limitation. The cluster shows itself by a pose rotating more than 150 degrees and point sets
  * that share at least a quarter of the smaller one's keypoints (a keypoint is on one copy, so
  * a shared one is both a source and a target).
  *
  * The copies lie on either side of a plane through the axis of M (the rotation's axis,
  * through a point c with (I - R) c = t minus t's part along the axis), and M maps each side
  * onto the other: every such plane agrees with M, so M alone cannot tell the copies apart (a
  * plane across two cartons lying side by side agrees with it as well as the plane between
  * them). The plane kept, among 180 through the axis, cuts the fewest links between keypoints
  * that lie on one copy: keypoints closer than 20 mm (one surface, weight 1), and keypoints
  * within 5 mm of one anchor set (a point set of another cluster, which lies on a single copy
  * and so tells where a copy ends; weight 4); among planes cutting as few, the one farthest
  * from every keypoint (for copies lying apart: through the middle of the gap, not through an
  * unprinted band of both). The cluster is oriented only if the plane is
  * confirmed: when anchor links exist, it cuts at most 10 % of them; when none exist (no third
  * copy matched to one of the two), it must cut no link at all (20 mm free of keypoints
  * between the copies) and the surface must show a gap there: between the two closest
  * keypoints across the plane it falls more than 10 mm behind the segment joining them
  * (surfaceDropsBetween(): the floor or the background seen between two objects; one object's
  * own surface does not fall behind its chords). Else (touching copies without an anchor, no
  * surface given, or the two "copies" are the halves of one object that looks the same after
  * a half turn, which every anchor spans and whose surface shows no gap) it is left as it is.
  * Triplets whose sources lie on one side and targets on the other stay or are reversed so
  * that all go from the same side to the other; those straddling the plane, or with a keypoint
  * within 1 mm of it, or with a keypoint missing from the cluster's point sets, are dropped.
  * \param[in] cluster the cluster (its triplets, reversed flags, point sets and transformation)
  * \param[in] anchors point sets that each lie on one copy (the point sets of the other
  * clusters); may be empty
  * \param[in] triplets the triplet matches the cluster indexes
  * \param[in] keypoints the frame's keypoints (source and target are one cloud)
  * \param[in] surface the organized frame and the keypoints' pixels in it (a valid
  * KeypointSurface, isValidKeypointSurface()), or nullptr: then only anchors confirm a plane
  * \return one entry per member triplet; empty when the cluster is not such a half turn or
  * nothing confirms the plane
  */
std::vector<TripletOrientation>
orientHalfTurnCluster (const TripletCluster& cluster,
                       const std::vector<pcl::Indices>& anchors,
                       const TripletMatches& triplets,
                       const KeypointCloud& keypoints,
                       const KeypointSurface* surface = nullptr);

/** \brief Split a cluster one of whose point sets straddles the two copies of another
  * cluster.
  *
  * The two point sets of a cluster lie on two different copies. If at least three keypoints of
  * a point set of `cluster`, and a fifth of them, lie within 15 mm of each of `other`'s point
  * sets, that set covers two copies: two touching copies that share their relative pose with
  * two other ones (copies 1, 2 -> 3, 4: every second copy of a row, or a pair of pairs on a
  * table). Each keypoint of that point set takes the side of its nearest keypoint of `other`'s
  * sets (3D); a triplet whose three keypoints on that set take one side goes to that side's
  * part; a triplet across both, or with a keypoint missing from that point set, is dropped.
  * When every triplet spans both copies (two lying cans matched to the next two), nothing of
  * the cluster is left: its model would cover two copies. When only one side gets triplets,
  * the cluster is left whole: its set may be one object whose print repeats (its two
  * patterns then are `other`'s two sets). The parts may hold fewer triplets than the
  * clusterer's minimum cluster size.
  * \param[in] cluster the cluster to split (its triplets, reversed flags and point sets)
  * \param[in] other a cluster whose point sets lie on two different copies (not `cluster`)
  * \param[in] triplets the triplet matches both clusters index
  * \param[in] keypoints the frame's keypoints (source and target are one cloud)
  * \return positions in cluster.triplets of the two parts' members; none when no triplet lies
  * whole on one side (every triplet spans both copies, or has a keypoint missing from the
  * straddling set); a single part holding every triplet when neither of `cluster`'s point
  * sets straddles `other`, or only one side gets triplets
  */
std::vector<std::vector<std::size_t>>
splitStraddlingCluster (const TripletCluster& cluster,
                        const TripletCluster& other,
                        const TripletMatches& triplets,
                        const KeypointCloud& keypoints);

/** \brief Split a cluster whose point sets lie on objects with a gap between them, as the
  * surface shows (not in the paper).
  *
  * splitStraddlingCluster() needs another cluster whose keypoints lie near those of the
  * straddling set; in a row of copies standing apart, the triplets linking every second copy
  * (copies 0, 1 -> 2, 3) often lie on other parts of the print than those of the neighbour
  * pairs. The surface tells the copies apart without them: two keypoints lie on one object
  * unless the surface between them falls behind the segment joining them
  * (surfaceDropsBetween() by kMinSurfaceGapDrop: the floor or the background seen between two
  * objects; the visible surface of one convex object lies in front of its chords).
  *
  * Each point set falls into groups of keypoints joined by such links (single linkage): each
  * keypoint is linked to its 8 nearest (3D), then the pieces still apart are joined where the
  * surface does not fall behind their closest pair across. Keypoints without depth at their
  * pixel, and groups of fewer than three keypoints, are left out; a set with no group left, or
  * falling into more than 16 pieces, is not judged. When both sets are judged and one holds
  * two groups or more, each triplet whose three sources lie in one group and whose three
  * targets lie in one group goes to the part of that pair of groups; the others (across a gap,
  * or on a keypoint left out or missing from the point sets) are dropped, and so are parts of
  * fewer than three triplets, which may leave nothing. Copies that touch without a gap stay
  * joined (splitStraddlingCluster() and the chain splitting see those). An object whose own
  * surface drops behind a chord (a bowl, a U-shaped part) may be split, or its cluster dropped.
  * \param[in] cluster the cluster (its triplets, reversed flags and point sets)
  * \param[in] triplets the triplet matches the cluster indexes
  * \param[in] surface the organized frame and the keypoints' pixels in it (a valid
  * KeypointSurface, isValidKeypointSurface(); not checked)
  * \return positions in cluster.triplets of each part's members, in the order of their first
  * triplet; a single part holding every triplet (none for a cluster without triplets) when
  * neither set holds two groups or a set is not judged; no part when no part keeps three
  * triplets (nothing of the cluster lies on one pair of objects: its model would span two)
  */
std::vector<std::vector<std::size_t>>
splitClusterAtSurfaceGaps (const TripletCluster& cluster,
                           const TripletMatches& triplets,
                           const KeypointSurface& surface);

} // namespace mid
