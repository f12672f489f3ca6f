#pragma once

#include <mid/simulation/rendered_frame.h>
#include <mid/simulation/scene.h>

#include <string>
#include <utility>
#include <vector>

namespace mid {
namespace simulation {

/** \brief The ground truth of a rendered scene as a JSON document:
  *
  * \verbatim
  * {
  *   "camera": {"width": 640, "height": 480, "fx": 538, "fy": 538, "cx": 319.5, "cy": 239.5},
  *   "depth_scale": 0.001,
  *   <extra numbers, e.g. "seed": 1>,
  *   "instances": [
  *     {"id": 0, "object": "juice_carton", "type": "box",
  *      "dimensions": {"size_x": 0.07, "size_y": 0.07, "size_z": 0.2},
  *      "pose": [[r00, r01, r02, tx], [r10, r11, r12, ty], [r20, r21, r22, tz], [0, 0, 0, 1]],
  *      "bbox": [x, y, width, height], "visible_pixels": 1234}, ...],
  *   "background": [{"object": "table", "type": "table_plane", "dimensions": {...},
  *                   "pose": [[...]]}, ...]
  * }
  * \endverbatim
  *
  * Poses are model-to-camera in metres (camera: x right, y down, z forward); ids are the
  * values of the instance map; "object" is Shape::getName(), or the type name if empty.
  * \param[in] scene the rendered scene
  * \param[in] frame the frame rendered from it (camera and instance statistics)
  * \param[in] depth_scale metres per unit of the depth image written with the frame
  * \param[in] extra additional top-level numbers, in order
  * \return the JSON text, ending with a newline
  */
std::string
formatGroundTruthJSON (const Scene& scene,
                       const RenderedFrame& frame,
                       double depth_scale,
                       const std::vector<std::pair<std::string, double>>& extra = {});

} // namespace simulation
} // namespace mid
