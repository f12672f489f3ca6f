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
  * version, diameter, counts, and the name of the data file) and `<path minus .json>.pcd`
  * (binary compressed PCD, one point per descriptor: x y z normal_x normal_y normal_z of its
  * landmark in the model frame, the landmark's index, and the 128 descriptor values). The
  * instances are not stored: a model describes the object, not a frame. Both files are written
  * under temporary names and renamed only when both are complete.
  * \param[in] path the JSON file, must end in ".json"
  * \param[in] model the model
  * \param[in,out] staged if given, the two files are only staged in it (written under their
  * temporary names) and the caller commits them together with its other outputs
  * \return false (with a PCL_ERROR) if a file cannot be written
  */
bool
saveObjectModel (const std::string& path,
                 const ObjectModel& model,
                 io::StagedFiles* staged = nullptr);

/** \brief Read a model written by saveObjectModel().
  * \param[in] path the JSON file
  * \param[out] model landmarks, descriptors, their landmarks and diameter; cleared on failure
  * \return false (with a PCL_ERROR naming the problem) if a file is missing, truncated, of
  * another format or version, or inconsistent
  */
bool
loadObjectModel (const std::string& path, ObjectModel& model);

} // namespace mid
