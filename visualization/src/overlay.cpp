#include <mid/visualization/impl/overlay.hpp>

#include <pcl/point_types.h>

#include <array>
#include <cmath>

namespace mid {
namespace visualization {
namespace detail {

void
drawInstance (const std::vector<cv::Point2f>& pixels,
              const cv::Scalar& color,
              const std::string& label,
              cv::Mat& image)
{
  if (pixels.empty())
    return;
  constexpr int kRadius = 3, kBoxWidth = 2;
  float u_min = std::numeric_limits<float>::max(), v_min = u_min;
  float u_max = std::numeric_limits<float>::lowest(), v_max = u_max;
  for (const auto& pixel : pixels) {
    cv::circle (image,
                cv::Point (cvRound (pixel.x), cvRound (pixel.y)),
                kRadius,
                color,
                2,
                cv::LINE_8);
    u_min = std::min (u_min, pixel.x);
    v_min = std::min (v_min, pixel.y);
    u_max = std::max (u_max, pixel.x);
    v_max = std::max (v_max, pixel.y);
  }
  const cv::Point top_left (cvRound (u_min), cvRound (v_min));
  const cv::Point bottom_right (cvRound (u_max), cvRound (v_max));
  cv::rectangle (image, top_left, bottom_right, color, kBoxWidth, cv::LINE_8);

  // The label: dark text on a box of the object's color, above the rectangle (inside it if the
  // rectangle touches the top of the image).
  constexpr double kScale = 0.5;
  constexpr int kThickness = 1, kMargin = 3;
  int baseline = 0;
  const cv::Size text =
      cv::getTextSize (label, cv::FONT_HERSHEY_SIMPLEX, kScale, kThickness, &baseline);
  const int height = text.height + baseline + 2 * kMargin;
  int top = top_left.y - kBoxWidth / 2 - height;
  if (top < 0)
    top = top_left.y + kBoxWidth;
  const cv::Rect box (
      top_left.x - kBoxWidth / 2, top, text.width + 2 * kMargin, height);
  cv::rectangle (image, box, color, cv::FILLED, cv::LINE_8);
  cv::putText (image,
               label,
               cv::Point (box.x + kMargin, box.y + kMargin + text.height),
               cv::FONT_HERSHEY_SIMPLEX,
               kScale,
               cv::Scalar (0, 0, 0),
               kThickness,
               cv::LINE_AA);
}

void
drawBox (const Eigen::Matrix4f& box_to_camera,
         const Eigen::Vector3f& size,
         const io::CameraIntrinsics& intrinsics,
         const cv::Scalar& color,
         cv::Mat& image)
{
  // Corner c has the sign of axis a's half edge in bit a of c.
  std::array<Eigen::Vector3f, 8> corners;
  for (int c = 0; c < 8; ++c) {
    const Eigen::Vector3f local ((c & 1) ? 0.5f * size.x() : -0.5f * size.x(),
                                 (c & 2) ? 0.5f * size.y() : -0.5f * size.y(),
                                 (c & 4) ? 0.5f * size.z() : -0.5f * size.z());
    corners[static_cast<std::size_t> (c)] =
        box_to_camera.topLeftCorner<3, 3>() * local +
        box_to_camera.topRightCorner<3, 1>();
  }
  const auto pixel = [&intrinsics] (const Eigen::Vector3f& point) {
    return cv::Point2d (intrinsics.fx * point.x() / point.z() + intrinsics.cx,
                        intrinsics.fy * point.y() / point.z() + intrinsics.cy);
  };
  for (int c = 0; c < 8; ++c)
    for (int axis = 1; axis < 8; axis <<= 1) {
      if ((c & axis) != 0)
        continue; // each edge once, from its corner on the negative side
      const Eigen::Vector3f& a = corners[static_cast<std::size_t> (c)];
      const Eigen::Vector3f& b = corners[static_cast<std::size_t> (c | axis)];
      if (!(a.z() > 0.0f) || !(b.z() > 0.0f))
        continue;
      cv::line (image, pixel (a), pixel (b), color, 1, cv::LINE_8);
    }
}

} // namespace detail

#define MID_INSTANTIATE_OVERLAY(T)                                                     \
  template bool renderOverlay<T> (                                                     \
      const pcl::PointCloud<T>&, const DiscoveryResult&, cv::Mat&);                    \
  template bool saveOverlay<T> (                                                       \
      const std::string&, const pcl::PointCloud<T>&, const DiscoveryResult&);
MID_INSTANTIATE_OVERLAY (pcl::PointXYZRGB)
MID_INSTANTIATE_OVERLAY (pcl::PointXYZRGBA)
#undef MID_INSTANTIATE_OVERLAY

} // namespace visualization
} // namespace mid
