#include "app_support.h"

#include <mid/discovery/result_json.h>
#include <mid/io/organized_cloud_io.h>
#include <mid/registration/object_model_io.h>

#include <pcl/console/parse.h>
#include <pcl/console/print.h>

#include <cstring>
#include <fstream>
#include <vector>

namespace mid {
namespace apps {

using pcl::console::print_error;
using pcl::console::print_info;
using pcl::console::print_value;

void
printSceneInputHelp ()
{
  print_info ("Scene:\n");
  print_info ("  SCENE.pcd           organized PCD with x y z rgb(a), metres\n");
  print_info ("  -rgb FILE           color image (PNG/JPG), with -depth\n");
  print_info ("  -depth FILE         16-bit depth PNG registered to the color image\n");
  print_info (
      "  -fx -fy -cx -cy     pinhole intrinsics in pixels (required with -rgb)\n");
  print_info ("  -depth_scale S      metres per depth unit (default 0.001)\n");
}

OptionSpecs
sceneInputOptions ()
{
  return {{"-rgb", 1},
          {"-depth", 1},
          {"-fx", 1},
          {"-fy", 1},
          {"-cx", 1},
          {"-cy", 1},
          {"-depth_scale", 1}};
}

bool
parseSceneInput (int argc, char** argv, SceneInput& input)
{
  using pcl::console::parse_argument;
  // A .pcd argument that is not the value of an output option (-models, -json).
  std::vector<int> pcd_indices;
  for (const int i : pcl::console::parse_file_extension_argument (argc, argv, ".pcd"))
    if (i == 0 || (std::strcmp (argv[i - 1], "-models") != 0 &&
                   std::strcmp (argv[i - 1], "-json") != 0))
      pcd_indices.push_back (i);
  parse_argument (argc, argv, "-rgb", input.color_path);
  parse_argument (argc, argv, "-depth", input.depth_path);
  const bool rgbd = !input.color_path.empty() || !input.depth_path.empty();
  if (pcd_indices.size() + (rgbd ? 1 : 0) != 1) {
    print_error ("Give exactly one input: one SCENE.pcd, or -rgb and -depth.\n");
    return false;
  }
  if (!rgbd) {
    input.pcd_path = argv[pcd_indices.front()];
    return true;
  }
  if (input.color_path.empty() || input.depth_path.empty()) {
    print_error ("-rgb and -depth must be given together.\n");
    return false;
  }
  io::CameraIntrinsics& k = input.intrinsics;
  for (const char* name : {"-fx", "-fy", "-cx", "-cy"})
    if (pcl::console::find_argument (argc, argv, name) < 0) {
      print_error ("-rgb/-depth input needs the intrinsics -fx -fy -cx -cy.\n");
      return false;
    }
  return parseNumber (argc, argv, "-fx", k.fx) &&
         parseNumber (argc, argv, "-fy", k.fy) &&
         parseNumber (argc, argv, "-cx", k.cx) &&
         parseNumber (argc, argv, "-cy", k.cy) &&
         parseNumber (argc, argv, "-depth_scale", k.depth_scale);
}

bool
loadScene (const SceneInput& input, pcl::PointCloud<PointT>& cloud)
{
  if (!input.pcd_path.empty())
    return io::loadOrganizedPCD (input.pcd_path, cloud);
  return io::loadRGBD (input.color_path, input.depth_path, input.intrinsics, cloud);
}

bool
ResultFiles::stage (const std::string& json_path, const std::string& model_prefix)
{
  json_path_ = json_path;
  model_prefix_ = model_prefix;
  if (!json_path.empty() && (json_temporary_ = files_.stage (json_path)).empty())
    return false;
  // The model files are staged when written; check their folder now.
  return model_prefix.empty() || canStage (model_prefix + "0.json");
}

bool
ResultFiles::write (const DiscoveryResult& result, const std::string& input_name)
{
  for (std::size_t m = 0; !model_prefix_.empty() && m < result.models.size(); ++m)
    if (!saveObjectModel (model_prefix_ + std::to_string (m) + ".json",
                          result.models[m],
                          modelBox (result, m) ? *modelBox (result, m) : ModelSize(),
                          &files_))
      return false;
  if (!json_path_.empty()) {
    std::ofstream json (json_temporary_);
    json << formatDiscoveryJson (result, input_name, groups_);
    json.close();
    if (!json) {
      print_error ("Could not write '%s'.\n", json_path_.c_str());
      return false;
    }
  }
  return files_.commit();
}

void
printResult (const pcl::PointCloud<PointT>& cloud,
             const DiscoveryResult& result,
             double load_ms)
{
  pcl::console::print_highlight ("Scene: ");
  print_value ("%u x %u", cloud.width, cloud.height);
  print_info (" points\nkeypoints: ");
  print_value ("%zu", result.keypoints ? result.keypoints->size() : 0);
  print_info (" (valid depth and normal)\nmatches:   ");
  print_value ("%zu", result.matches.size());
  print_info ("\ntriplets:  ");
  print_value ("%zu", result.triplets);
  print_info ("\nclusters:  ");
  print_value ("%zu", result.clusters);
  if (result.rejected_clusters > 0)
    print_info (" (%zu rejected by the photometric verification)",
                result.rejected_clusters);
  print_info ("\nobjects:   ");
  print_value ("%zu", result.models.size());
  print_info ("\n");
  for (std::size_t m = 0; m < result.models.size(); ++m) {
    print_info ("  object %zu: ", m);
    print_value ("%zu", result.models[m].instances.size());
    print_info (" instances, %zu landmarks, diameter %.3f m",
                result.models[m].landmarks.size(),
                static_cast<double> (result.models[m].diameter));
    if (modelBox (result, m) && modelBox (result, m)->valid) {
      const ModelSize& box = *modelBox (result, m);
      print_info (", box %.1f x %.1f x %.1f mm (agreed by %d cop%s)",
                  1000.0 * static_cast<double> (box.size.x()),
                  1000.0 * static_cast<double> (box.size.y()),
                  1000.0 * static_cast<double> (box.size.z()),
                  box.agreeing,
                  box.agreeing == 1 ? "y" : "ies");
    }
    print_info ("\n");
  }
  print_info ("timing_ms: load ");
  print_value ("%.1f", load_ms);
  for (const auto& [stage, ms] : result.timing_ms) {
    print_info (", %s ", stage.c_str());
    print_value ("%.1f", ms);
  }
  print_info ("\n");
}

} // namespace apps
} // namespace mid
