#include <mid/registration/json_writing.h>

#include <cstdio>

namespace mid {
namespace detail {

std::string
jsonNumber (double value)
{
  if (value == 0.0)
    value = 0.0; // no "-0"
  char buffer[32];
  std::snprintf (buffer, sizeof (buffer), "%.9g", value);
  return buffer;
}

void
writeJsonMatrix (std::ostream& out, const Eigen::Matrix4f& matrix)
{
  out << "[";
  for (int r = 0; r < 4; ++r) {
    out << (r > 0 ? ", [" : "[");
    for (int c = 0; c < 4; ++c)
      out << (c > 0 ? ", " : "") << jsonNumber (matrix (r, c));
    out << "]";
  }
  out << "]";
}

void
writeJsonBox (std::ostream& out, const ModelSize* size, const std::string& before_pose)
{
  if (!size || !size->valid) {
    out << "null";
    return;
  }
  out << "{\"size\": [" << jsonNumber (size->size.x()) << ", "
      << jsonNumber (size->size.y()) << ", " << jsonNumber (size->size.z())
      << "], \"copies\": " << size->agreeing << "," << before_pose << "\"pose\": ";
  writeJsonMatrix (out, size->box_in_model);
  out << "}";
}

} // namespace detail
} // namespace mid
