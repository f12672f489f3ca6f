#pragma once

#include <mid/simulation/rendered_frame.h>

#include <opencv2/core/mat.hpp>

#include <vector>

namespace mid {
namespace simulation {

/** \brief A picture of a frame for people: colour, depth and instance masks side by side
  * (BGR, 3 width x height, times scale).
  *
  * Depth is colour-mapped from near (red) to far (blue) over the range of the frame's measured
  * depth, black where there is none; each instance of the instance map gets its own colour
  * (hues spread by the golden angle), the background is black.
  * \param[in] frame the frame (colour CV_8UC3, depth CV_32FC1, instances CV_32SC1, one size)
  * \param[in] scale size of the picture relative to the frame, in (0, 1]
  * \return the picture; empty if the frame or the scale is invalid
  */
cv::Mat
makeFramePreview (const RenderedFrame& frame, double scale = 1.0);

/** \brief Previews stacked top to bottom, e.g. of several frames; empty if they differ in
  * width or type or one is empty.
  */
cv::Mat
stackPreviews (const std::vector<cv::Mat>& previews);

} // namespace simulation
} // namespace mid
