#include <mid/visualization/impl/overlay.hpp>

#include <pcl/point_types.h>

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
