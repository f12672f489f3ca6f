#pragma once

#include <mid/registration/object_model.h>

#include <Eigen/Core>

#include <ostream>
#include <string>

namespace mid {
/** \brief Internals shared by the library's JSON writers (the model files, the result files);
  * not an API: their layout may change with the files'.
  */
namespace detail {

/** \brief A number as JSON text: nine significant digits (enough for a float to read back
  * exactly), never "-0".
  */
std::string
jsonNumber (double value);

/** \brief Write a 4x4 matrix as a row-major nested JSON list. */
void
writeJsonMatrix (std::ostream& out, const Eigen::Matrix4f& matrix);

/** \brief Write an object's box as JSON, the same in the result files and the model files:
  * `{"size": [a, b, c], "copies": n, "pose": [[...], ...]}` (edges ascending in metres, how
  * many copies agree on them, box frame -> model frame), or `null` when `size` is null or
  * not valid.
  * \param[in,out] out the stream
  * \param[in] size the box, or nullptr
  * \param[in] before_pose the text between the copies and the pose (a line break and an
  * indent that suit the file)
  */
void
writeJsonBox (std::ostream& out, const ModelSize* size, const std::string& before_pose);

} // namespace detail
} // namespace mid
