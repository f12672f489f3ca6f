#include "two_copies_scene.h"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <limits>

namespace mid {
namespace test {

namespace {

constexpr int kWidth = 640, kHeight = 480, kPatch = 160;
constexpr float kFocal = 525.0f, kCx = 319.5f, kCy = 239.5f;
constexpr float kPatchDepth = 0.8f, kWallDepth = 1.2f;

/** Random blobs and bars of random gray levels: plenty of SIFT keypoints, none repeated. */
cv::Mat
randomTexture (unsigned seed)
{
  cv::RNG rng (seed);
  cv::Mat texture (kPatch, kPatch, CV_8UC1, cv::Scalar (128));
  for (int i = 0; i < 70; ++i) {
    const cv::Point center (rng.uniform (0, kPatch), rng.uniform (0, kPatch));
    const cv::Scalar gray (rng.uniform (0, 256));
    if (i % 2 == 0)
      cv::circle (texture, center, rng.uniform (3, 14), gray, cv::FILLED);
    else
      cv::rectangle (texture,
                     center,
                     center + cv::Point (rng.uniform (3, 25), rng.uniform (3, 25)),
                     gray,
                     cv::FILLED);
  }
  cv::GaussianBlur (texture, texture, cv::Size (0, 0), 1.0);
  return texture;
}

Eigen::Vector3f
backProject (float u, float v, float z)
{
  return {(u - kCx) * z / kFocal, (v - kCy) * z / kFocal, z};
}

void
paint (pcl::PointCloud<pcl::PointXYZRGB>& cloud,
       const cv::Mat& gray,
       const cv::Rect& rect,
       float z)
{
  for (int v = 0; v < rect.height; ++v)
    for (int u = 0; u < rect.width; ++u) {
      auto& point = cloud.at (rect.x + u, rect.y + v);
      point.r = point.g = point.b = gray.at<uchar> (v, u);
      point.getVector3fMap() = backProject (
          static_cast<float> (rect.x + u), static_cast<float> (rect.y + v), z);
    }
}

} // namespace

TwoCopiesScene
makeTwoCopiesScene (unsigned seed)
{
  TwoCopiesScene scene;
  scene.cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZRGB>> (kWidth, kHeight);
  scene.cloud->is_dense = true;
  paint (*scene.cloud,
         cv::Mat (kHeight, kWidth, CV_8UC1, cv::Scalar (90)),
         cv::Rect (0, 0, kWidth, kHeight),
         kWallDepth);

  const cv::Mat texture = randomTexture (seed);
  cv::Mat turned;
  cv::rotate (texture, turned, cv::ROTATE_90_CLOCKWISE);
  scene.rect_a = cv::Rect (80, 120, kPatch, kPatch);
  scene.rect_b = cv::Rect (380, 160, kPatch, kPatch);
  paint (*scene.cloud, texture, scene.rect_a, kPatchDepth);
  paint (*scene.cloud, turned, scene.rect_b, kPatchDepth);

  // Texture pixel (column a, row b) lands at A + (a, b) and, turned clockwise, at
  // B + (n - 1 - b, a): in the image a rotation by +90 degrees, in 3D one about the optical axis.
  scene.a_to_b.linear() =
      Eigen::AngleAxisf (static_cast<float> (M_PI / 2), Eigen::Vector3f::UnitZ())
          .toRotationMatrix();
  const Eigen::Vector3f a0 = backProject (static_cast<float> (scene.rect_a.x),
                                          static_cast<float> (scene.rect_a.y),
                                          kPatchDepth);
  const Eigen::Vector3f b0 =
      backProject (static_cast<float> (scene.rect_b.x + kPatch - 1),
                   static_cast<float> (scene.rect_b.y),
                   kPatchDepth);
  scene.a_to_b.translation() = b0 - scene.a_to_b.linear() * a0;
  return scene;
}

} // namespace test
} // namespace mid
