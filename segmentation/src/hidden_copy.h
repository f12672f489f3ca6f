#pragma once

#include "free_objects.h"

#include <mid/segmentation/instance_extent.h>
#include <mid/segmentation/model_size.h>

#include <Eigen/Core>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

namespace mid {
namespace detail {

/** \brief The box of a copy of a box of size `whole` that something in front hides in part
  * (SizeInstanceSearch; not in the paper).
  *
  * Where a box lies partly behind something nearer the camera, its surface ends at the
  * occluder's edge and its fitted box is too short along one edge of its footprint: the
  * object measures shorter than its copies, and no size joins them. `hidden` is taken for such
  * a copy of `whole` when:
  * - their boxes agree on two edges (either way round) and `hidden`'s third, a footprint edge
  *   (not the one that stands up), is shorter than `whole`'s beyond the tolerance, but shows
  *   60 % of it at least;
  * - at one end of `hidden`'s box along that edge, half of its outline's pixels at least
  *   (within 10 mm of the end, 5 pixels at least) are hidden by something in front
  *   (occludedOutline(): a point nearer by kOccluderStep within 8 pixels).
  *
  * \param[in] organized the frame (camera frame, metres)
  * \param[in] plane the support plane
  * \param[in] whole the edges of the box (ascending), as a copy seen whole measures them
  * \param[in] hidden the object that may be a copy hidden in part (its pixels and box)
  * \param[in] agree when two edges are one
  * \param[out] completed `hidden`'s box lengthened to `whole`'s edge beyond the hidden end (its
  * visible end stays), its edges ascending as fitInstanceBox() gives them and its frame's axes
  * along them
  * \return true if `hidden` is such a copy; else false, `completed` untouched
  */
bool
completeHiddenCopy (const pcl::PointCloud<pcl::PointXYZ>& organized,
                    const Eigen::Vector4f& plane,
                    const Eigen::Vector3f& whole,
                    const FreeObject& hidden,
                    const SizeAgreement& agree,
                    InstanceExtent& completed);

/** \brief True if `a` and `b` may be the two ends of one box that something in front hides
  * in the middle (SizeInstanceSearch; not in the paper): a box lying behind a narrower
  * object shows on both sides of it, and its two visible parts, of one cross-section, measure
  * alike and look alike, as two copies would. They are such ends when:
  * - their heights (the edges that stand up) and their other cross-section edges agree, and
  *   the footprint axes along which they lie are parallel (10 deg);
  * - b's centre lies on a's axis (less than a quarter of the shorter cross-section edge off
  *   it), and their boxes lie 2 cm apart at least (room for what hides the middle);
  * - something in front hides the middle: half of the pixels at least on the image line
  *   between the tips of the ends that face each other hold a point nearer the camera than
  *   the line between the tips (by 10 mm, kOccluderStep) and outside the box the two would
  *   make whole (grown by 10 mm): a copy standing between them in a row lies on that box, not
  *   in front of it.
  * Two copies lying in a row with one object in front of the space between them are taken
  * for one box too.
  *
  * \param[in] organized the frame (camera frame, metres)
  * \param[in] plane the support plane
  * \param[in] a, b the objects (their pixels and boxes)
  * \param[in] agree when two edges are one
  */
bool
endsOfOneHiddenBox (const pcl::PointCloud<pcl::PointXYZ>& organized,
                    const Eigen::Vector4f& plane,
                    const FreeObject& a,
                    const FreeObject& b,
                    const SizeAgreement& agree);

} // namespace detail
} // namespace mid
