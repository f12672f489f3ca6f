#include "json_file.h"

#include <mid/evaluation/ground_truth.h>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <pcl/console/print.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace mid {
namespace evaluation {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr const char* kCaller = "mid::evaluation::loadBopScene";

std::string
maskName (int image, std::size_t instance)
{
  char name[32];
  std::snprintf (name, sizeof (name), "%06d_%06zu.png", image, instance);
  return name;
}

} // namespace

bool
GroundTruthFrame::contains (std::size_t k, float u, float v) const
{
  const GroundTruthInstance& instance = instances[k];
  const int x = static_cast<int> (std::lround (u)),
            y = static_cast<int> (std::lround (v));
  if (!instance.mask_visible.empty())
    return x >= 0 && y >= 0 && x < instance.mask_visible.cols &&
           y < instance.mask_visible.rows &&
           instance.mask_visible.at<unsigned char> (y, x) != 0;
  return instance.bbox_visible.contains (cv::Point (x, y));
}

bool
loadBopScene (const std::string& folder, GroundTruthScene& scene)
{
  scene.clear();
  const fs::path root (folder);
  json gt, info;
  if (!detail::readJsonFile (root / "scene_gt.json", kCaller, gt))
    return false;
  const bool has_info = fs::exists (root / "scene_gt_info.json");
  if (has_info && !detail::readJsonFile (root / "scene_gt_info.json", kCaller, info))
    return false;
  try {
    for (const auto& [key, entries] : gt.items()) {
      GroundTruthFrame frame;
      frame.image_id = std::stoi (key);
      for (std::size_t k = 0; k < entries.size(); ++k) {
        const auto& entry = entries.at (k);
        GroundTruthInstance instance;
        instance.object_id = entry.at ("obj_id").get<int>();
        const auto rotation = entry.at ("cam_R_m2c").get<std::vector<double>>();
        const auto translation = entry.at ("cam_t_m2c").get<std::vector<double>>();
        if (rotation.size() != 9 || translation.size() != 3)
          throw std::runtime_error ("cam_R_m2c needs 9 and cam_t_m2c 3 values");
        // BOP stores the rotation row by row, the translation in millimetres.
        instance.pose.topLeftCorner<3, 3>() =
            Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> (
                rotation.data())
                .cast<float>();
        instance.pose.topRightCorner<3, 1>() =
            (Eigen::Map<const Eigen::Vector3d> (translation.data()) / 1000.0)
                .cast<float>();
        if (has_info && info.contains (key)) {
          const auto& i = info.at (key).at (k);
          const auto box = i.at ("bbox_visib").get<std::vector<int>>();
          if (box.size() == 4)
            instance.bbox_visible = cv::Rect (box[0], box[1], box[2], box[3]);
          instance.visible_pixels = i.value ("px_count_visib", 0);
        }
        const fs::path mask = root / "mask_visib" / maskName (frame.image_id, k);
        if (fs::exists (mask)) {
          instance.mask_visible = cv::imread (mask.string(), cv::IMREAD_GRAYSCALE);
          if (instance.mask_visible.empty())
            throw std::runtime_error ("cannot read mask " + mask.string());
        }
        frame.instances.push_back (instance);
      }
      scene[frame.image_id] = frame;
    }
  }
  catch (const std::exception& error) {
    PCL_ERROR (
        "[mid::evaluation::loadBopScene] '%s': %s\n", folder.c_str(), error.what());
    scene.clear();
    return false;
  }
  return true;
}

} // namespace evaluation
} // namespace mid
