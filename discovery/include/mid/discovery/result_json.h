#pragma once

#include <mid/discovery/discovery_result.h>

#include <string>

namespace mid {

/** \brief Version of the result JSON written by formatDiscoveryJson(); it changes whenever a
  * field changes meaning or disappears (added fields keep it). See doc/result_format.md.
  */
constexpr int DISCOVERY_JSON_VERSION = 1;

/** \brief The discovery result as JSON (doc/result_format.md):
  * {"format": "mid-discovery-result", "version": 1, "input": ..., "timing_ms": {..., "total"},
  *  "counts": {"keypoints", "matches", "triplets", "clusters", "objects", "instances"},
  *  "objects": [{"id", "landmarks", "diameter", "box" (null, or {"size" (edges ascending,
  *  metres), "copies" (how many measured copies agree on it), "pose" (4x4 row-major, box frame
  *  to model frame)}: DiscoveryResult::model_sizes), "instances": [{"group" (the
  *  instances of one group share landmarks: sharedLandmarkGroups()), "pose" (4x4 row-major,
  *  model to camera, metres), "keypoints" ([u, v] pixels), "bbox" ([u_min, v_min, u_max,
  *  v_max]), "rms_error"}]}]}.
  * \param[in] result the result
  * \param[in] input a description of the input (e.g. the file name), written as given
  * \param[in] groups whether to write each instance's "group" (default); false for results
  * whose instances are each posed on a stored model by their own matches (detection), where
  * the landmarks two instances share say nothing about what their relative pose rests on
  * \return the JSON text, ending in a newline
  */
std::string
formatDiscoveryJson (const DiscoveryResult& result,
                     const std::string& input,
                     bool groups = true);

} // namespace mid
