#pragma once

#include <Eigen/Core>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

namespace mid {

/** \brief The pinhole projection of an organized frame: pixel column u = fx * x / z + cx and
  * row v = fy * y / z + cy. Every organized frame made from a depth image has one, and
  * fitFramePinhole() recovers it from the points alone, so that a step that moves surface points
  * can look up where they land without being given the camera. A frame turned by a half turn
  * about the x axis (negative z, as in some of PCL's sample clouds) gets a negative fx.
  */
struct FramePinhole
{
  /** \brief Focal lengths and principal point, in pixels. */
  ///@{
  double fx = 0.0, fy = 0.0, cx = 0.0, cy = 0.0;
  ///@}

  /** \brief True if the focal lengths are finite and non-zero and the principal point is
    * finite: a projection project() can use.
    */
  bool
  isValid () const;

  /** \brief The pixel (column u, row v) of a camera-frame point.
    * \return false if the point lies on the camera plane or projects outside a width x
    * height image
    */
  bool
  project (const Eigen::Vector3f& point, int width, int height, int& u, int& v) const;
};

/** \brief Fit the pinhole projection of an organized frame: least squares over its valid
  * points, each image axis on its own.
  * \param[in] organized the frame
  * \param[out] pinhole the projection (zeros on failure)
  * \return false if the frame is not organized, its valid points do not span two columns and
  * two rows, or they do not project back onto their own pixels within a pixel (root mean
  * square): no pinhole camera made that frame
  */
bool
fitFramePinhole (const pcl::PointCloud<pcl::PointXYZ>& organized,
                 FramePinhole& pinhole);

} // namespace mid
