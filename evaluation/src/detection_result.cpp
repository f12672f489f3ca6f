#include <mid/evaluation/detection_result.h>

#include <nlohmann/json.hpp>
#include <pcl/console/print.h>

#include <fstream>

namespace mid {
namespace evaluation {

bool
readDetectionResult (const std::string& path, DetectionResult& result)
{
  result = DetectionResult();
  std::ifstream file (path);
  if (!file) {
    PCL_ERROR ("[mid::evaluation::readDetectionResult] cannot open '%s'\n",
               path.c_str());
    return false;
  }
  try {
    nlohmann::json document;
    file >> document;
    if (document.value ("format", std::string()) != "mid-discovery-result")
      throw std::runtime_error ("not a mid discovery result (format)");
    if (document.value ("version", 0) != 1)
      throw std::runtime_error ("result version " +
                                std::to_string (document.value ("version", 0)) +
                                ", this build reads version 1");
    const auto& timing = document.at ("timing_ms");
    result.total_ms = timing.value ("total", -1.0);
    result.features_ms = timing.value ("features", -1.0);
    if (timing.contains ("triplets") && timing.contains ("clustering"))
      result.grouping_ms =
          timing.at ("triplets").get<double>() + timing.at ("clustering").get<double>();
    for (const auto& object : document.at ("objects")) {
      DetectedObject detected;
      if (object.contains ("box") && !object.at ("box").is_null()) {
        const auto& box = object.at ("box");
        for (int e = 0; e < 3; ++e)
          detected.box_size[e] =
              box.at ("size").at (static_cast<std::size_t> (e)).get<float>();
        detected.box_copies = box.at ("copies").get<int>();
      }
      for (const auto& instance : object.at ("instances")) {
        DetectedInstance d;
        const auto& pose = instance.at ("pose");
        for (int r = 0; r < 4; ++r)
          for (int c = 0; c < 4; ++c)
            d.pose (r, c) = pose.at (static_cast<std::size_t> (r))
                                .at (static_cast<std::size_t> (c))
                                .get<float>();
        for (const auto& uv : instance.at ("keypoints"))
          d.keypoints.emplace_back (uv.at (0).get<float>(), uv.at (1).get<float>());
        if (instance.contains ("group"))
          d.group = instance.at ("group").get<int>();
        detected.instances.push_back (d);
      }
      result.objects.push_back (detected);
    }
  }
  catch (const std::exception& error) {
    PCL_ERROR ("[mid::evaluation::readDetectionResult] '%s': %s\n",
               path.c_str(),
               error.what());
    result = DetectionResult();
    return false;
  }
  return true;
}

} // namespace evaluation
} // namespace mid
