#pragma once

#include <mid/io/staged_files.h>
#include <mid/registration/object_model.h>

#include <string>

namespace mid {

/** \brief Version of the model files written by saveObjectModel(); loadObjectModel() refuses
  * any other.
  */
constexpr int OBJECT_MODEL_FILE_VERSION = 1;

/** \brief Write a model as two files: `<path>` (JSON header: format "mid-object-model",
  * version, diameter, counts, the name of the data file, and the object's box) and `<path minus
  * .json>.pcd` (binary compressed PCD, one point per descriptor: x y z normal_x normal_y
  * normal_z of its landmark in the model frame, the landmark's index, and the 128 descriptor
  * values). The instances are not stored: a model describes the object, not a frame. Both files
  * are written under temporary names and renamed only when both are complete.
  * \param[in] path the JSON file, must end in ".json"
  * \param[in] model the model
  * \param[in] box the box the object's copies occupy on the table, in the model frame: stored
  * as the result files write it (`{"size", "copies", "pose"}`), or `null` when it is not valid
  * \param[in,out] staged if given, the two files are only staged in it (written under their
  * temporary names) and the caller commits them together with its other outputs
  * \return false (with a PCL_ERROR) if a file cannot be written, or `box` is valid but no box
  * (edges not positive and ascending, no copy, the pose not rigid), which loadObjectModel()
  * would refuse
  */
bool
saveObjectModel (const std::string& path,
                 const ObjectModel& model,
                 const ModelSize& box,
                 io::StagedFiles* staged = nullptr);

/** \brief Write a model without a box (`"box": null`); see the overload above. */
bool
saveObjectModel (const std::string& path,
                 const ObjectModel& model,
                 io::StagedFiles* staged = nullptr);

/** \brief Read a model written by saveObjectModel().
  * \param[in] path the JSON file
  * \param[out] model landmarks, descriptors, their landmarks and diameter; cleared on failure
  * \param[out] box the object's box in the model frame; not valid when the file holds none
  * (`null`, or a file written before boxes were stored), and cleared on failure
  * \return false (with a PCL_ERROR naming the problem) if a file is missing, truncated, of
  * another format or version, or inconsistent, or the box is malformed
  */
bool
loadObjectModel (const std::string& path, ObjectModel& model, ModelSize& box);

/** \brief Read a model written by saveObjectModel() without returning its box; a malformed
  * box is refused all the same. See the overload above.
  */
bool
loadObjectModel (const std::string& path, ObjectModel& model);

} // namespace mid
