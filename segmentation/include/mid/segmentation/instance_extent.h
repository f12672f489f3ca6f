#pragma once

#include <Eigen/Core>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/types.h>

#include <vector>

namespace mid {

/** \brief Signed distance (metres) of point p from the plane (unit normal n, offset d),
  * n . p + d: positive on the side the normal points to (towards the camera for the planes of
  * fitSupportPlane()).
  */
float
planeDistance (const Eigen::Vector4f& plane, const Eigen::Vector3f& p);

/** \brief The plane most of an organized frame lies on (a table, a bin's floor), as (unit
  * normal towards the camera, offset) with normal . x + offset = 0.
  * \param[in] organized the frame (camera frame, metres; NaN where the depth is missing)
  * \param[in] tolerance largest distance of a point on the plane (metres)
  * \param[in] min_share the share of the frame's valid points the plane must hold
  * \param[out] plane the plane; zero when none holds min_share of the points
  * \return true if a plane was found; false when none holds min_share of the points, or (with
  * a PCL_ERROR) when width x height is not the cloud's size
  * Planes through three points drawn with a fixed seed (the same frame gives the same plane on
  * every platform), the best one then refitted by least squares to the points within
  * tolerance of it: a plane through three points is tilted by up to the tolerance, which
  * every height above it would carry.
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

/** \brief Grow the surfaces of several objects at once, each from some of its pixels.
  *
  * A surface grows from its seed pixels over 4-neighbours whose points are closer than
  * max_step to each other, lie off the support plane (farther than plane_tolerance from it),
  * within max_radius of the centroid of its seeds' points, and not in a crease: a pixel
  * behind the chord between its neighbours 6 pixels away (in any of four directions) by more
  * than 6 mm, where one object leans on or stands beside another; the visible surface of a
  * convex object has none. All objects grow together, breadth first, and a pixel belongs to
  * the object that reaches it first: where the surfaces of touching objects still join, the
  * join is split between them instead of being measured as one object.
  *
  * \param[in] organized the frame (camera frame, metres; NaN where the depth is missing)
  * \param[in] plane the support plane (fitSupportPlane())
  * \param[in] seeds for each object, pixels (row * width + column) on it; a pixel seeded by
  * several objects belongs to the first
  * \param[in] max_step, max_radius, plane_tolerance see above (metres)
  * \param[out] surfaces for each object, the pixels of its surface in the order reached
  * \return false (with a PCL_ERROR, every surface empty) if the cloud is not organized or a
  * seed lies outside the frame
  */
bool
growInstanceSurfaces (const pcl::PointCloud<pcl::PointXYZ>& organized,
                      const Eigen::Vector4f& plane,
                      const std::vector<pcl::Indices>& seeds,
                      float max_step,
                      float max_radius,
                      float plane_tolerance,
                      std::vector<pcl::Indices>& surfaces);

/** \brief What is wrong with an organized frame and a surface's pixels in it: the frame not
  * organized, or a pixel outside it or without a point; nullptr if nothing.
  */
const char*
surfacePixelsProblem (const pcl::PointCloud<pcl::PointXYZ>& organized,
                      const pcl::Indices& surface);

/** \brief Fit the box an object occupies on the support plane to its surface.
  *
  * The box stands on the plane: its footprint is the rectangle holding the surface's points
  * projected onto the plane (directions from the smallest such rectangle, extents from the
  * 0.5 % and 99.5 % quantiles along them, so that a few noisy points do not widen it), its
  * height the 99.5 % quantile of the points' heights above the plane. An object lying with a
  * round side up (a can lying down) shows the camera only half of it: its shorter footprint
  * edge is widened to the diameter of the circle its cross-section (the points of the middle
  * 80 % of its length) lies on (widenToRoundSide()), as a copy standing up measures it.
  *
  * \param[in] organized the frame (camera frame, metres)
  * \param[in] plane the support plane (fitSupportPlane())
  * \param[in] surface pixels (row * width + column) of the object's surface
  * (growInstanceSurfaces()), each with a point
  * \param[out] extent the box, holding `surface`
  * \return false if the surface has fewer than 30 pixels, or (with a PCL_ERROR) a pixel
  * without a point
  */
bool
fitInstanceBox (const pcl::PointCloud<pcl::PointXYZ>& organized,
                const Eigen::Vector4f& plane,
                const pcl::Indices& surface,
                InstanceExtent& extent);

/** \brief Measure the box one object occupies: growInstanceSurfaces() from its seeds alone,
  * then fitInstanceBox().
  * \return false if either fails
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
