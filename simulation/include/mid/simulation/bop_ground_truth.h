#pragma once

#include <mid/simulation/rendered_frame.h>
#include <mid/simulation/scene.h>

#include <opencv2/core/types.hpp>

#include <vector>

namespace mid {
namespace simulation {

/** \brief What the BOP format (scene_gt_info.json) says about one object in one frame. Boxes
  * are (x, y, width, height) in pixels, (-1, -1, -1, -1) when there is no pixel.
  */
struct BopInstanceInfo
{
  /** \brief Box of the object's whole silhouette in the image (as if nothing occluded it). */
  cv::Rect bbox_obj = cv::Rect (-1, -1, -1, -1);
  /** \brief Box of its visible pixels. */
  cv::Rect bbox_visib = cv::Rect (-1, -1, -1, -1);
  /** \brief Pixels of the silhouette; of those, pixels with a depth measurement in the frame;
    * pixels where the object is the first surface seen.
    */
  int px_count_all = 0;
  int px_count_valid = 0;
  int px_count_visib = 0;
  /** \brief px_count_visib / px_count_all (0 if the silhouette is empty). */
  double visib_fract = 0.0;
};

/** \brief The BOP statistics of every object of a rendered frame. The silhouette of each object
  * is ray-cast alone with the frame's camera; the visible pixels are those of frame.instances.
  * \param[in] scene the scene the frame was rendered from
  * \param[in] frame the frame (after applySensorModel(), px_count_valid counts the measured
  * depth)
  * \param[out] info one entry per scene object; cleared when false is returned
  * \return false (with a PCL_ERROR) if the frame does not belong to the scene or an object
  * cannot be rendered
  */
bool
computeBopInstanceInfo (const Scene& scene,
                        const RenderedFrame& frame,
                        std::vector<BopInstanceInfo>& info);

} // namespace simulation
} // namespace mid
