#include <mid/discovery/result_json.h>
#include <mid/registration/json_writing.h>

#include <algorithm>
#include <cstdio>
#include <limits>
#include <sstream>

namespace mid {

namespace {

std::string
quoted (const std::string& text)
{
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\')
      out += std::string ("\\") + c;
    else if (static_cast<unsigned char> (c) < 0x20) {
      char buffer[8];
      std::snprintf (buffer, sizeof (buffer), "\\u%04x", static_cast<unsigned> (c));
      out += buffer;
    }
    else
      out += c;
  }
  return out + "\"";
}

/** One instance; its group is left out when negative. */
void
writeInstance (std::ostringstream& out,
               const ModelInstance& instance,
               int group,
               const ImageKeypoints& image)
{
  out << "        {";
  if (group >= 0)
    out << "\"group\": " << group << ", ";
  out << "\"pose\": ";
  detail::writeJsonMatrix (out, instance.pose);
  out << ",\n         \"keypoints\": [";
  float u_min = std::numeric_limits<float>::max(), v_min = u_min;
  float u_max = std::numeric_limits<float>::lowest(), v_max = u_max;
  for (std::size_t o = 0; o < instance.keypoints.size(); ++o) {
    const auto& kp = image[static_cast<std::size_t> (instance.keypoints[o])];
    out << (o > 0 ? ", " : "") << "[" << detail::jsonNumber (kp.u) << ", "
        << detail::jsonNumber (kp.v) << "]";
    u_min = std::min (u_min, kp.u);
    v_min = std::min (v_min, kp.v);
    u_max = std::max (u_max, kp.u);
    v_max = std::max (v_max, kp.v);
  }
  out << "],\n         \"bbox\": [";
  if (!instance.keypoints.empty())
    out << detail::jsonNumber (u_min) << ", " << detail::jsonNumber (v_min) << ", "
        << detail::jsonNumber (u_max) << ", " << detail::jsonNumber (v_max);
  out << "],\n         \"rms_error\": " << detail::jsonNumber (instance.rms_error)
      << "}";
}

} // namespace

std::string
formatDiscoveryJson (const DiscoveryResult& result,
                     const std::string& input,
                     bool groups)
{
  std::size_t instances = 0;
  for (const auto& model : result.models)
    instances += model.instances.size();
  std::ostringstream out;
  out << "{\n  \"format\": \"mid-discovery-result\",\n  \"version\": "
      << DISCOVERY_JSON_VERSION << ",\n  \"input\": " << quoted (input)
      << ",\n  \"timing_ms\": {";
  for (std::size_t i = 0; i < result.timing_ms.size(); ++i)
    out << (i > 0 ? ", " : "") << quoted (result.timing_ms[i].first) << ": "
        << detail::jsonNumber (result.timing_ms[i].second);
  out << "},\n  \"counts\": {\"keypoints\": "
      << (result.keypoints ? result.keypoints->size() : 0)
      << ", \"matches\": " << result.matches.size()
      << ", \"triplets\": " << result.triplets << ", \"clusters\": " << result.clusters
      << ", \"rejected_clusters\": " << result.rejected_clusters
      << ", \"objects\": " << result.models.size() << ", \"instances\": " << instances
      << "},\n  \"objects\": [";
  for (std::size_t m = 0; m < result.models.size(); ++m) {
    const auto& model = result.models[m];
    out << (m > 0 ? "," : "") << "\n    {\"id\": " << m
        << ", \"landmarks\": " << model.landmarks.size()
        << ", \"diameter\": " << detail::jsonNumber (model.diameter)
        << ",\n     \"box\": ";
    detail::writeJsonBox (out, modelBox (result, m), "\n             ");
    out << ",\n     \"instances\": [\n";
    const std::vector<int> group_of =
        groups ? sharedLandmarkGroups (model)
               : std::vector<int> (model.instances.size(), -1);
    for (std::size_t i = 0; i < model.instances.size(); ++i) {
      writeInstance (out, model.instances[i], group_of[i], result.image_keypoints);
      out << (i + 1 < model.instances.size() ? ",\n" : "\n");
    }
    out << "     ]}";
  }
  out << (result.models.empty() ? "]\n}\n" : "\n  ]\n}\n");
  return out.str();
}

} // namespace mid
