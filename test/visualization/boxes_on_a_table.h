#pragma once

// Shared by the overlay test and the rendering test: three copies of a box lying apart on a
// table, their discovery, and how much of each true box's outline a picture draws.

#include "rendered_objects_scene.h"

#include <mid/discovery/multi_instance_discovery.h>
#include <mid/visualization/intrinsics_estimation.h>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include <cstdlib>
#include <vector>

namespace mid {
namespace test {

/** \brief Three cookie boxes (0.12 x 0.09 x 0.04 m) lying apart on a table, and the result of
  * discovery on them: one object, whose box two or more copies agree on (asserted: call with
  * ASSERT_NO_FATAL_FAILURE).
  */
inline void
discoverBoxesOnATable (RenderedObjectsScene& scene, DiscoveryResult& result)
{
  const char* print = "bastoncini_cookie_box.png";
  scene = boxesLyingOnATable ({print, print, print});
  MultiInstanceDiscovery<pcl::PointXYZRGBA> discovery;
  discovery.setInputCloud (scene.cloud);
  ASSERT_TRUE (discovery.discover (result));
  ASSERT_EQ (result.models.size(), 1u);
  ASSERT_EQ (result.model_sizes.size(), 1u);
  ASSERT_TRUE (result.model_sizes[0].valid);
  ASSERT_GE (result.model_sizes[0].agreeing, 2);
}

/** \brief Per true box of the scene, the share of the points along its projected edges that lie
  * within 3 pixels of a pixel of `color` in `image` (BGR; a pixel whose channels differ from it
  * by `tolerance` or less in sum counts), the picture drawn through the scene's camera at the
  * image's size. Expects each box's edges to lie in the image (200 points or more).
  */
inline std::vector<double>
boxOutlinesShown (const cv::Mat& image,
                  const cv::Vec3b& color,
                  int tolerance,
                  const RenderedObjectsScene& scene)
{
  io::CameraIntrinsics camera;
  EXPECT_TRUE (visualization::estimateIntrinsics (*scene.cloud, camera));
  cv::Mat colored (image.size(), CV_8UC1, cv::Scalar (0));
  for (int v = 0; v < image.rows; ++v)
    for (int u = 0; u < image.cols; ++u) {
      const auto& pixel = image.at<cv::Vec3b> (v, u);
      const int difference = std::abs (pixel[0] - color[0]) +
                             std::abs (pixel[1] - color[1]) +
                             std::abs (pixel[2] - color[2]);
      colored.at<uchar> (v, u) = difference <= tolerance ? 255 : 0;
    }
  cv::dilate (colored, colored, cv::Mat::ones (7, 7, CV_8UC1));
  std::vector<double> shares;
  for (const auto& box : scene.boxes) {
    std::size_t samples = 0;
    shares.push_back (shareOfBoxEdgesOn (
        colored, box, camera.fx, camera.fy, camera.cx, camera.cy, &samples));
    EXPECT_GT (samples, 200u); // the box is in the picture, whatever it shows
  }
  return shares;
}

} // namespace test
} // namespace mid
