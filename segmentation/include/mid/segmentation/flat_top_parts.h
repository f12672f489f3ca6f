#pragma once

#include <Eigen/Core>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/types.h>

#include <vector>

namespace mid {

/** \brief The parts of an object's surface that a box of a known size may occupy, found by the
  * box's flat top (not in the paper).
  *
  * Two products touching each other, side faces flush, grow into one surface, and the box
  * fitted to it is neither's. A box lying on one of its faces still shows its top: a level
  * patch at one of its edges above the plane, the rectangle of the other two. For each of the
  * box's edges taken as its height, this function finds the connected patches of `surface`
  * whose points lie within 6 mm of that height and are level (the normal through the points 4
  * pixels away on either side within 25 deg of the plane's), and keeps those whose smallest
  * rectangle on the plane is at most 6 mm longer than the box's other two edges, and at most
  * 20 mm shorter (the top's rim, where the normal bends towards the sides, is not level; nor
  * is the part of it a neighbour hides). The part is the pixels of `surface` over that
  * rectangle grown by 8 mm, no higher than the top (plus 6 mm), and not within 4 pixels of a
  * level pixel of their own height unless that is the top's: the box's sides under its top,
  * not a lower neighbour's top or its rim. A neighbour of the same height joins the patch and
  * makes it too long: a join of copies of one box lying flush is no part (SizeInstanceSearch
  * cuts those by their outline or by a size seen twice). The caller measures each part
  * (fitInstanceBox()) to tell whether it is a copy.
  *
  * \param[in] organized the frame (camera frame, metres; NaN where the depth is missing)
  * \param[in] plane the support plane (fitSupportPlane())
  * \param[in] surface the object's pixels (row * width + column), each with a point
  * \param[in] size the box's edges (metres, each finite and > 0)
  * \param[out] parts the parts' pixels, edge after edge of `size` (an edge equal to the one
  * before it is skipped), patch after patch in the order of their first pixels in `surface`
  * \return false (with a PCL_ERROR, parts empty) if the cloud is not organized, a pixel lies
  * outside it or has no point, or an edge is not finite and > 0
  */
bool
flatTopParts (const pcl::PointCloud<pcl::PointXYZ>& organized,
              const Eigen::Vector4f& plane,
              const pcl::Indices& surface,
              const Eigen::Vector3f& size,
              std::vector<pcl::Indices>& parts);

/** \brief The boxes whose flat tops an object's surface shows, their sizes not known (not in
  * the paper): what flatTopParts() may be asked for.
  *
  * Two copies of one product joined into one object (one standing, one lying, or touching
  * each other end to end at right angles) show their tops at the heights of different
  * edges. Each connected patch of level pixels (as flatTopParts() finds them; neighbouring
  * pixels within 3 mm of each other's height) of at least 30 pixels suggests a box: its
  * median height above the plane and the edges of the smallest rectangle on the plane around
  * it and its rim (the pixels within 4 of it and within 3 mm of its height: where the normal
  * bends towards the sides, the top is not level; no farther, where a neighbour's side stands
  * flush). Such a size is a guess; the parts flatTopParts() finds for it, measured on their
  * own (fitInstanceBox()), say what the boxes are. Copies side by side with their tops at one
  * height make one patch, of neither's size.
  *
  * \param[in] organized the frame (camera frame, metres; NaN where the depth is missing)
  * \param[in] plane the support plane (fitSupportPlane())
  * \param[in] surface the object's pixels (row * width + column), each with a point
  * \param[out] sizes one per patch (edges ascending, metres), in the order of the patches'
  * first pixels in `surface`; patches below the plane are left out
  * \return false (with a PCL_ERROR, sizes empty) if the cloud is not organized or a pixel
  * lies outside it or has no point
  */
bool
flatTopSizes (const pcl::PointCloud<pcl::PointXYZ>& organized,
              const Eigen::Vector4f& plane,
              const pcl::Indices& surface,
              std::vector<Eigen::Vector3f>& sizes);

} // namespace mid
