#include <mid/simulation/ground_truth_json.h>

#include <cmath>
#include <cstdio>
#include <sstream>

namespace mid {
namespace simulation {

namespace {

/** A number as JSON: 12 significant digits (sub-picometre for poses in metres), rounding
  * errors of exact zeros (below 1e-14) written as 0, null if not finite.
  */
std::string
number (double value)
{
  if (!std::isfinite (value))
    return "null";
  if (std::abs (value) < 1e-14)
    return "0";
  char buffer[32];
  std::snprintf (buffer, sizeof (buffer), "%.12g", value);
  return buffer;
}

std::string
quoted (const std::string& text)
{
  std::string out = "\"";
  for (const char c : text) {
    switch (c) {
    case '"':
      out += "\\\"";
      break;
    case '\\':
      out += "\\\\";
      break;
    case '\n':
      out += "\\n";
      break;
    case '\t':
      out += "\\t";
      break;
    default:
      if (static_cast<unsigned char> (c) < 0x20) {
        char escaped[8];
        std::snprintf (escaped, sizeof (escaped), "\\u%04x", static_cast<unsigned> (c));
        out += escaped;
      }
      else
        out += c;
    }
  }
  return out + "\"";
}

std::string
poseJSON (const Eigen::Isometry3d& pose)
{
  const Eigen::Matrix4d& matrix = pose.matrix();
  std::string out = "[";
  for (int row = 0; row < 4; ++row) {
    out += row == 0 ? "[" : ", [";
    for (int col = 0; col < 4; ++col)
      out += (col == 0 ? "" : ", ") + number (matrix (row, col));
    out += "]";
  }
  return out + "]";
}

/** "object", "type", "dimensions" and "pose" of a scene object (without braces). */
std::string
objectFieldsJSON (const SceneObject& object)
{
  std::string out;
  if (!object.shape)
    return R"("object": null, "pose": )" + poseJSON (object.pose);
  const std::string& name = object.shape->getName();
  out += "\"object\": " + quoted (name.empty() ? object.shape->getTypeName() : name);
  out += ", \"type\": " + quoted (object.shape->getTypeName()) + ", \"dimensions\": {";
  bool first = true;
  for (const auto& dimension : object.shape->getDimensions()) {
    out += (first ? "" : ", ") + quoted (dimension.first) + ": " +
           number (dimension.second);
    first = false;
  }
  return out + "}, \"pose\": " + poseJSON (object.pose);
}

} // namespace

std::string
formatGroundTruthJSON (const Scene& scene,
                       const RenderedFrame& frame,
                       double depth_scale,
                       const std::vector<std::pair<std::string, double>>& extra)
{
  const PinholeCamera& camera = frame.camera;
  std::ostringstream out;
  out << "{\n  \"camera\": {\"width\": " << camera.width
      << ", \"height\": " << camera.height << ", \"fx\": " << number (camera.fx)
      << ", \"fy\": " << number (camera.fy) << ", \"cx\": " << number (camera.cx)
      << ", \"cy\": " << number (camera.cy) << "},\n";
  out << "  \"depth_scale\": " << number (depth_scale) << ",\n";
  for (const auto& entry : extra)
    out << "  " << quoted (entry.first) << ": " << number (entry.second) << ",\n";

  out << "  \"instances\": [";
  const auto& objects = scene.getObjects();
  for (std::size_t id = 0; id < objects.size(); ++id) {
    const InstanceStats stats =
        id < frame.instance_stats.size() ? frame.instance_stats[id] : InstanceStats();
    out << (id == 0 ? "\n" : ",\n") << "    {\"id\": " << id << ", "
        << objectFieldsJSON (objects[id]) << ",\n     \"bbox\": [" << stats.bbox.x
        << ", " << stats.bbox.y << ", " << stats.bbox.width << ", " << stats.bbox.height
        << "], \"visible_pixels\": " << stats.visible_pixels << "}";
  }
  out << (objects.empty() ? "],\n" : "\n  ],\n");

  out << "  \"background\": [";
  const auto& background = scene.getBackgroundObjects();
  for (std::size_t i = 0; i < background.size(); ++i)
    out << (i == 0 ? "\n" : ",\n") << "    {" << objectFieldsJSON (background[i])
        << "}";
  out << (background.empty() ? "]\n" : "\n  ]\n") << "}\n";
  return out.str();
}

} // namespace simulation
} // namespace mid
