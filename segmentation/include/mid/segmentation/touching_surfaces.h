#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/types.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace mid {

/** \brief Which surfaces of an organized frame touch along a border, not at a point (not in the
  * paper).
  *
  * Two surfaces touch where a pixel of one and a 4-neighbouring pixel of the other hold points
  * closer than `max_step`; they touch along a border when at least `min_contact` such pairs of
  * pixels do. The surfaces grown from neighbouring keypoints of one face meet along a border
  * of many pixels; two objects that merely touch at a point (the corner of a standing carton
  * against a lying one) meet in one or two pairs, and joining them would measure one box for
  * both. Used by SizeInstanceSearch to join the surfaces of one object (on the benchmark, 3
  * pairs kept every object of one face together and separated such objects, while 15 cut
  * faces into fragments: doc/benchmark.md, session 35).
  *
  * \param[in] organized the frame (camera frame, metres; NaN where the depth is missing)
  * \param[in] surfaces pixel sets of `organized` (row * width + column), disjoint (a pixel in
  * several counts for the last), e.g. from growInstanceSurfaces()
  * \param[in] max_step largest distance between the points of touching pixels (metres)
  * \param[in] min_contact pairs of touching pixels a border needs (>= 1)
  * \param[out] pairs the touching surfaces (a < b, indices into `surfaces`), sorted
  * \return false (with a PCL_ERROR, `pairs` empty) if the cloud is not organized, a pixel lies
  * outside it or min_contact < 1
  */
bool
touchingSurfaces (const pcl::PointCloud<pcl::PointXYZ>& organized,
                  const std::vector<pcl::Indices>& surfaces,
                  float max_step,
                  int min_contact,
                  std::vector<std::pair<std::size_t, std::size_t>>& pairs);

} // namespace mid
