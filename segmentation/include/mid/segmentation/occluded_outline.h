#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/types.h>

namespace mid {

/** \brief Share of a surface's outline that something in front of it hides (not in the paper).
  *
  * Where an object lies partly behind another, its surface ends at the occluder's edge, and
  * the outline there is the occluder's, not the object's own: a box fitted to it, or edges
  * read off it, measure the occluder. A pixel of the outline (a pixel of `pixels` with a
  * 4-neighbour off it) counts as hidden when a pixel off the surface within `ring` pixels of
  * it holds a point nearer the camera (smaller z) by at least `step`; the ring reaches past
  * the few pixels where a surface grown up to a crease stops short of the occluder. Missing
  * depth hides nothing. Used by SizeInstanceSearch before it reads copies' edges off an
  * object's outline.
  *
  * \param[in] organized the frame (camera frame, metres; NaN where the depth is missing)
  * \param[in] pixels the surface: pixels of `organized` (row * width + column)
  * \param[in] ring how far from an outline pixel to look (pixels, >= 1)
  * \param[in] step how much nearer a point must lie to hide the surface (metres, > 0)
  * \param[out] share hidden outline pixels over all outline pixels; 0 for a surface without
  * an outline (none, or the whole frame)
  * \return false (with a PCL_ERROR, `share` 0) if the cloud is not organized, a pixel lies
  * outside it, `ring` < 1 or `step` is not finite and > 0
  */
bool
occludedOutlineShare (const pcl::PointCloud<pcl::PointXYZ>& organized,
                      const pcl::Indices& pixels,
                      int ring,
                      float step,
                      float& share);

/** \brief The outline of a surface and the part of it that something in front hides, pixel by
  * pixel (see occludedOutlineShare(), which counts them).
  *
  * \param[in] organized, pixels, ring, step see occludedOutlineShare()
  * \param[out] outline the outline's pixels (each once, in the order of the frame)
  * \param[out] hidden those of them that something in front hides (in the order of the
  * frame)
  * \return false (with a PCL_ERROR, both outputs empty) as occludedOutlineShare()
  */
bool
occludedOutline (const pcl::PointCloud<pcl::PointXYZ>& organized,
                 const pcl::Indices& pixels,
                 int ring,
                 float step,
                 pcl::Indices& outline,
                 pcl::Indices& hidden);

} // namespace mid
