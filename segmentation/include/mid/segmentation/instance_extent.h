#pragma once

#include <Eigen/Core>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/types.h>

namespace mid {

/** \brief The plane most of an organized frame lies on (a table, a bin's floor), as (unit
  * normal towards the camera, offset) with normal . x + offset = 0.
  * \param[in] organized the frame (camera frame, metres; NaN where the depth is missing)
  * \param[in] tolerance largest distance of a point on the plane (metres)
  * \param[in] min_share the share of the frame's valid points the plane must hold
  * \param[out] plane the plane; zero when none holds min_share of the points
  * \return true if a plane was found
  * Planes through three points drawn with a fixed seed: the same frame gives the same plane.
  */
bool
fitSupportPlane (const pcl::PointCloud<pcl::PointXYZ>& organized,
                 float tolerance,
                 float min_share,
                 Eigen::Vector4f& plane);

/** \brief The box an object occupies on the support plane, from the surface seen around one
  * of its copies (not in the paper).
  */
struct InstanceExtent
{
  /** \brief Box edges (metres), ascending. */
  Eigen::Vector3f size = Eigen::Vector3f::Zero();
  /** \brief Box frame -> camera: its axes along the edges in the order of `size`, its origin
    * at the box's centre.
    */
  Eigen::Matrix4f pose = Eigen::Matrix4f::Identity();
  /** \brief The pixels of the surface the box was fitted to (row * width + column). */
  pcl::Indices surface;

  EIGEN_MAKE_ALIGNED_OPERATOR_NEW
};

/** \brief Measure the box an object occupies from the surface connected to some of its pixels.
  *
  * The surface grows from the seed pixels over 4-neighbours whose points are closer than
  * max_step to each other, off the support plane and within max_radius of the seeds' centroid.
  * The box stands on the plane: its footprint is the smallest rectangle holding the surface's
  * points projected onto the plane, its height the largest height of a point above it.
  *
  * \param[in] organized the frame (camera frame, metres; NaN where the depth is missing)
  * \param[in] plane the support plane (fitSupportPlane())
  * \param[in] seeds pixels (row * width + column) on the object
  * \param[in] max_step, max_radius, plane_tolerance see above (metres)
  * \param[out] extent the box
  * \return false if fewer than 30 points were reached
  */
bool
measureInstanceExtent (const pcl::PointCloud<pcl::PointXYZ>& organized,
                       const Eigen::Vector4f& plane,
                       const pcl::Indices& seeds,
                       float max_step,
                       float max_radius,
                       float plane_tolerance,
                       InstanceExtent& extent);

} // namespace mid
