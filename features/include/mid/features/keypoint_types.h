#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstdint>
#include <vector>

namespace mid {

/** \brief A 128-D SIFT descriptor (OpenCV's layout: L2 norm about 512, values 0..255). */
using SIFTDescriptor = pcl::Histogram<128>;
/** \brief One SIFTDescriptor per keypoint, in the order of the KeypointCloud it belongs to. */
using SIFTDescriptorCloud = pcl::PointCloud<SIFTDescriptor>;

/** \brief Keypoints in 3D: position (metres, camera frame), unit surface normal oriented towards
  * the camera, and the surface variation of the neighbourhood in `curvature`.
  */
using KeypointCloud = pcl::PointCloud<pcl::PointNormal>;

/** \brief Where a keypoint was found in the image (OpenCV's cv::KeyPoint, without OpenCV). */
struct ImageKeypoint
{
  /** \brief Sub-pixel position: column u and row v, in pixels (0 is the first pixel's
    * centre).
    */
  ///@{
  float u = 0.0f;
  float v = 0.0f;
  ///@}
  /** \brief Diameter of the meaningful neighbourhood, in pixels. */
  float size = 0.0f;
  /** \brief Orientation in degrees [0, 360). */
  float angle = 0.0f;
  /** \brief Detector response (larger is stronger). */
  float response = 0.0f;
  /** \brief Pyramid octave the keypoint was detected in (OpenCV's packed value). */
  std::int32_t octave = 0;
  /** \brief Index of the pixel (row * width + column) in the organized input cloud. */
  pcl::index_t pixel_index = 0;
};

/** \brief Image positions of keypoints, in the order of their KeypointCloud. */
using ImageKeypoints = std::vector<ImageKeypoint>;

/** \brief The pixel (ImageKeypoint::pixel_index) of each keypoint, in their order: the
  * keypoint pixels of the steps that read the organized frame around the keypoints.
  */
inline pcl::Indices
pixelIndices (const ImageKeypoints& keypoints)
{
  pcl::Indices pixels;
  pixels.reserve (keypoints.size());
  for (const auto& k : keypoints)
    pixels.push_back (k.pixel_index);
  return pixels;
}

} // namespace mid
