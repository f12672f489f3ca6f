#pragma once

#include <mid/io/camera_intrinsics.h>

#include <opencv2/core/mat.hpp>
#include <pcl/point_cloud.h>

#include <cstdint>
#include <string>
#include <vector>

namespace mid {
namespace io {

/** \brief Load an organized, colored point cloud (metres) from a PCD file.
  *
  * The file must hold the fields x, y, z and rgb or rgba, be organized (height > 1) and
  * contain at least one finite point. Values whose median |z| exceeds 100 are taken for
  * millimetres and refused, since every later threshold of the method is in metres.
  * \param[in] path the PCD file
  * \param[out] cloud the cloud; cleared when false is returned
  * \return true on success, false (with a PCL_ERROR naming the problem) otherwise
  */
template <typename PointT>
bool
loadOrganizedPCD (const std::string& path, pcl::PointCloud<PointT>& cloud);

/** \brief Build an organized, colored cloud (metres) from a color image and a registered
  * 16-bit depth image, as TUM and BOP datasets store RGB-D frames.
  *
  * A depth value of 0 means "no measurement" and gives a NaN point.
  * \param[in] color 8-bit BGR (3 channels) or gray (1 channel) image
  * \param[in] depth 16-bit single-channel depth image of the same size
  * \param[in] intrinsics the pinhole intrinsics and the depth scale
  * \param[out] cloud width x height organized cloud; cleared when false is returned
  * \return true on success, false (with a PCL_ERROR naming the problem) otherwise
  */
template <typename PointT>
bool
rgbdToCloud (const cv::Mat& color,
             const cv::Mat& depth,
             const CameraIntrinsics& intrinsics,
             pcl::PointCloud<PointT>& cloud);

/** \brief Decode a color image (PNG or JPEG) and a 16-bit depth PNG held in memory, and
  * build the organized cloud with rgbdToCloud(), as loadRGBD() does with files.
  *
  * Only PNG and JPEG are decoded (whatever else OpenCV could read), and an image whose header
  * claims more than 2^25 pixels (8K UHD fits) is refused before it is decoded.
  * \param[in] color_data the encoded color image
  * \param[in] depth_data the encoded depth image (values in units of depth_scale metres)
  * \param[in] intrinsics the pinhole intrinsics and the depth scale
  * \param[out] cloud the organized cloud; cleared when false is returned
  * \return true on success, false (with a PCL_ERROR naming the problem) otherwise
  */
template <typename PointT>
bool
decodeRGBD (const std::vector<std::uint8_t>& color_data,
            const std::vector<std::uint8_t>& depth_data,
            const CameraIntrinsics& intrinsics,
            pcl::PointCloud<PointT>& cloud);

/** \brief Read a color image (PNG/JPG) and a 16-bit depth PNG and build the organized cloud
  * with rgbdToCloud(), decoding them as decodeRGBD() does.
  * \param[in] color_path color image file
  * \param[in] depth_path depth image file (16-bit PNG, values in units of depth_scale metres)
  * \param[in] intrinsics the pinhole intrinsics and the depth scale
  * \param[out] cloud the organized cloud; cleared when false is returned
  * \return true on success, false (with a PCL_ERROR naming the problem) otherwise
  */
template <typename PointT>
bool
loadRGBD (const std::string& color_path,
          const std::string& depth_path,
          const CameraIntrinsics& intrinsics,
          pcl::PointCloud<PointT>& cloud);

/** \brief Check that a cloud can be used as one RGB-D frame: organized (height > 1,
  * width * height points), at least one finite point, and plausibly in metres.
  * \param[in] cloud the cloud to check
  * \param[out] problem what is wrong, empty when it is usable
  * \return true if usable
  */
template <typename PointT>
bool
checkOrganizedCloud (const pcl::PointCloud<PointT>& cloud, std::string& problem);

} // namespace io
} // namespace mid
