#include <mid/simulation/frame_preview.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <cmath>

namespace mid {
namespace simulation {

namespace {

/** Depth colour-mapped near red to far blue over its range; no depth is black. */
cv::Mat
depthPicture (const cv::Mat& depth)
{
  const cv::Mat valid = depth > 0.0f;
  double near = 0.0, far = 0.0;
  cv::minMaxLoc (depth, &near, &far, nullptr, nullptr, valid);
  cv::Mat scaled;
  const double range = std::max (far - near, 1e-6);
  // 255 for the nearest, 0 for the farthest: JET shows near red, far blue.
  depth.convertTo (scaled, CV_8U, -255.0 / range, 255.0 * far / range);
  cv::Mat picture;
  cv::applyColorMap (scaled, picture, cv::COLORMAP_JET);
  picture.setTo (cv::Scalar::all (0), ~valid);
  return picture;
}

/** A distinct colour per instance id: hues spread by the golden angle. */
cv::Vec3b
instanceColor (int id)
{
  const double hue = std::fmod (id * 137.508, 360.0);
  cv::Mat hsv (1, 1, CV_8UC3, cv::Scalar (hue / 2.0, 200, 255));
  cv::Mat bgr;
  cv::cvtColor (hsv, bgr, cv::COLOR_HSV2BGR);
  return bgr.at<cv::Vec3b> (0, 0);
}

cv::Mat
maskPicture (const cv::Mat& instances)
{
  cv::Mat picture = cv::Mat::zeros (instances.size(), CV_8UC3);
  double highest = -1.0;
  cv::minMaxLoc (instances, nullptr, &highest);
  for (int id = 0; id <= static_cast<int> (highest); ++id)
    picture.setTo (instanceColor (id), instances == id);
  return picture;
}

} // namespace

cv::Mat
makeFramePreview (const RenderedFrame& frame, double scale)
{
  const cv::Size size = frame.color.size();
  if (!(scale > 0.0 && scale <= 1.0) || frame.color.empty() ||
      frame.color.type() != CV_8UC3 || frame.depth.size() != size ||
      frame.depth.type() != CV_32FC1 || frame.instances.size() != size ||
      frame.instances.type() != CV_32SC1)
    return cv::Mat();
  cv::Mat picture;
  cv::hconcat (std::vector<cv::Mat>{frame.color.clone(),
                                    depthPicture (frame.depth),
                                    maskPicture (frame.instances)},
               picture);
  if (scale < 1.0)
    cv::resize (picture, picture, cv::Size(), scale, scale, cv::INTER_AREA);
  return picture;
}

cv::Mat
stackPreviews (const std::vector<cv::Mat>& previews)
{
  cv::Mat picture;
  for (const cv::Mat& preview : previews)
    if (preview.empty() || preview.type() != previews.front().type() ||
        preview.cols != previews.front().cols)
      return picture;
  if (!previews.empty())
    cv::vconcat (previews, picture);
  return picture;
}

} // namespace simulation
} // namespace mid
