// pcl_multi_instance_bench_synth: write a synthetic multi-instance RGB-D benchmark in the BOP
// format: one scene folder per scenario (S-ez, S-d, M-ez, M-d, rows, none), a number of random
// frames in each, with exact ground truth, plus an organized PCD per frame for
// pcl_multi_instance_discovery. Deterministic for a seed; written all or nothing.

#include "strict_options.h"

#include <mid/io/staged_files.h>
#include <mid/simulation/benchmark_frame.h>
#include <mid/simulation/bop_scene_writer.h>
#include <mid/simulation/deterministic_random.h>
#include <mid/simulation/frame_preview.h>
#include <mid/simulation/product_catalog.h>
#include <mid/simulation/scene_renderer.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <pcl/common/time.h>
#include <pcl/console/parse.h>
#include <pcl/console/print.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

using pcl::console::print_error;
using pcl::console::print_highlight;
using pcl::console::print_info;
using pcl::console::print_value;

namespace {

namespace fs = std::filesystem;
using mid::simulation::BenchmarkScenario;

/** Everything the command line sets. */
struct Options
{
  std::string out_dir;
  std::string texture_dir = "data/textures";
  std::string scenarios = "S-ez,S-d,M-ez,M-d,rows,none";
  std::string sensor = "kinect";
  std::string preview;
  std::uint32_t seed = 1;
  int frames = 10;
  int supersampling = 3;
  int instances_per_type = 0;
  double preview_scale = 0.5;
  /** The scenarios of -scenarios, in order: scene folder i holds the i-th. */
  std::vector<BenchmarkScenario> scenario_list;
};

const mid::apps::OptionSpecs kOptions{{"-h", 0},
                                      {"--help", 0},
                                      {"-out_dir", 1},
                                      {"-texture_dir", 1},
                                      {"-scenarios", 1},
                                      {"-sensor", 1},
                                      {"-preview", 1},
                                      {"-preview_scale", 1},
                                      {"-seed", 1},
                                      {"-frames", 1},
                                      {"-supersampling", 1},
                                      {"-instances_per_type", 1}};

void
printHelp (const char* program)
{
  const Options defaults;
  print_info (
      "Write a synthetic multi-instance RGB-D benchmark (BOP format) with exact "
      "ground truth.\n\n");
  print_info ("Usage: %s -out_dir DATASET_DIR [options]\n\n", program);
  print_info (
      "  -out_dir DIR        dataset folder, created; must be missing or empty\n");
  print_info ("  -frames N           frames per scenario, 1 to 1000 (default ");
  print_value ("%d", defaults.frames);
  print_info (")\n  -seed S             seed of the whole dataset (default ");
  print_value ("%u", defaults.seed);
  print_info (
      ")\n  -scenarios LIST     comma-separated, of S-ez S-d M-ez M-d rows none "
      "(default ");
  print_value ("%s", defaults.scenarios.c_str());
  print_info (
      ")\n  -instances_per_type N  copies of each repeated product in S-ez, S-d, M-ez, "
      "M-d:\n                      0 = drawn (2 to 9), 2 = the paper's pair "
      "subset, up to 9 (default ");
  print_value ("%d", defaults.instances_per_type);
  print_info (")\n  -texture_dir DIR    folder with the product photographs (default ");
  print_value ("%s", defaults.texture_dir.c_str());
  print_info (")\n  -sensor NAME        kinect (Kinect v1-like noise, holes) or exact "
              "(default ");
  print_value ("%s", defaults.sensor.c_str());
  print_info (")\n  -supersampling N    colour rays per pixel along each axis, 1 to %d "
              "(default ",
              mid::simulation::SceneRenderer::kMaxSupersampling);
  print_value ("%d", defaults.supersampling);
  print_info (
      ")\n  -preview FILE       also write a PNG of the first frame of each scenario: "
      "colour,\n                      depth, masks side by side\n");
  print_info ("  -preview_scale F    size of the preview, in (0, 1] (default ");
  print_value ("%g", defaults.preview_scale);
  print_info (
      ")\n\nOutput: DIR/<scene>/ (000000 for the first scenario, ...) with "
      "scene_camera.json,\n"
      "scene_gt.json, scene_gt_info.json, rgb/, depth/ (16-bit, 0.1 mm), mask_visib/, "
      "pcd/\n"
      "(organized XYZRGB for pcl_multi_instance_discovery); DIR/scenarios.json (scene "
      "-> "
      "scenario),\nDIR/models_info.json (obj_id -> product), DIR/camera.json.\n");
}

bool
parseScenarios (Options& options)
{
  std::stringstream list (options.scenarios);
  std::string name;
  while (std::getline (list, name, ',')) {
    BenchmarkScenario scenario;
    if (!mid::simulation::parseScenarioName (name, scenario) ||
        std::find (options.scenario_list.begin(),
                   options.scenario_list.end(),
                   scenario) != options.scenario_list.end()) {
      print_error (
          "-scenarios: '%s' is not one of S-ez S-d M-ez M-d rows none, or comes "
          "twice.\n",
          name.c_str());
      return false;
    }
    options.scenario_list.push_back (scenario);
  }
  if (options.scenario_list.empty()) {
    print_error ("-scenarios names no scenario.\n");
    return false;
  }
  return true;
}

/** Parse the command line; false (after a one-line error) if it is unusable. */
bool
parseOptions (int argc, char** argv, Options& options)
{
  if (!mid::apps::onlyKnownArguments (argc, argv, kOptions))
    return false;
  using pcl::console::parse_argument;
  long seed = options.seed, frames = options.frames,
       supersampling = options.supersampling,
       instances_per_type = options.instances_per_type;
  if (!mid::apps::parseIntegerOption (argc, argv, "-seed", 0, 4294967295L, seed) ||
      !mid::apps::parseIntegerOption (argc, argv, "-frames", 1, 1000, frames) ||
      !mid::apps::parseIntegerOption (argc,
                                      argv,
                                      "-supersampling",
                                      1,
                                      mid::simulation::SceneRenderer::kMaxSupersampling,
                                      supersampling) ||
      !mid::apps::parseIntegerOption (
          argc, argv, "-instances_per_type", 0, 9, instances_per_type))
    return false;
  if (instances_per_type == 1) {
    print_error ("-instances_per_type must be 0 (drawn) or 2 to 9: one copy does not "
                 "repeat.\n");
    return false;
  }
  options.instances_per_type = static_cast<int> (instances_per_type);
  options.seed = static_cast<std::uint32_t> (seed);
  options.frames = static_cast<int> (frames);
  options.supersampling = static_cast<int> (supersampling);
  parse_argument (argc, argv, "-out_dir", options.out_dir);
  parse_argument (argc, argv, "-texture_dir", options.texture_dir);
  parse_argument (argc, argv, "-scenarios", options.scenarios);
  parse_argument (argc, argv, "-sensor", options.sensor);
  parse_argument (argc, argv, "-preview", options.preview);
  std::string scale;
  if (parse_argument (argc, argv, "-preview_scale", scale) >= 0) {
    char* end = nullptr;
    options.preview_scale = std::strtod (scale.c_str(), &end);
    if (scale.empty() || *end != '\0' ||
        !(options.preview_scale > 0.0 && options.preview_scale <= 1.0)) {
      print_error ("-preview_scale must be a number in (0, 1], got '%s'.\n",
                   scale.c_str());
      return false;
    }
  }
  if (options.sensor != "kinect" && options.sensor != "exact") {
    print_error ("-sensor must be 'kinect' or 'exact', got '%s'.\n",
                 options.sensor.c_str());
    return false;
  }
  if (options.out_dir.empty()) {
    print_error ("-out_dir is required (see -h).\n");
    return false;
  }
  std::error_code error;
  if (!fs::is_directory (options.texture_dir, error)) {
    print_error ("The texture folder '%s' does not exist (see -texture_dir).\n",
                 options.texture_dir.c_str());
    return false;
  }
  if (fs::exists (options.out_dir, error) &&
      (!fs::is_directory (options.out_dir, error) ||
       !fs::is_empty (options.out_dir, error))) {
    print_error ("The output folder '%s' is not an empty folder; remove it first.\n",
                 options.out_dir.c_str());
    return false;
  }
  if (!options.preview.empty()) {
    const fs::path folder = fs::path (options.preview).parent_path();
    if (!folder.empty() &&
        folder.lexically_normal() != fs::path (options.out_dir).lexically_normal() &&
        !fs::is_directory (folder, error)) {
      print_error ("The folder of the preview '%s' does not exist.\n",
                   options.preview.c_str());
      return false;
    }
  }
  return parseScenarios (options);
}

std::string
sceneFolderName (std::size_t index)
{
  char name[32];
  std::snprintf (name, sizeof (name), "%06zu", index);
  return name;
}

/** The seed of one frame: it depends only on the dataset seed, the scenario and the image id,
  * so a subset of scenarios or frames holds the same frames as the full dataset.
  */
std::uint32_t
frameSeed (std::uint32_t seed, BenchmarkScenario scenario, int image)
{
  return mid::simulation::DeterministicRandom (
             seed,
             1U + 1000U * static_cast<std::uint32_t> (scenario) +
                 static_cast<std::uint32_t> (image))
      .next();
}

bool
stageText (mid::io::StagedFiles& files,
           const std::string& path,
           const std::string& text)
{
  const std::string temporary = files.stage (path);
  if (temporary.empty())
    return false;
  std::ofstream file (temporary, std::ios::binary | std::ios::trunc);
  file << text;
  file.close();
  if (!file)
    print_error ("Cannot write '%s'.\n", path.c_str());
  return static_cast<bool> (file);
}

/** "name x count, ..." of a frame's products. */
std::string
describe (const mid::simulation::BenchmarkFrame& frame,
          const mid::simulation::ProductCatalog& catalog)
{
  std::map<int, int> counts;
  for (const int id : frame.product_ids)
    ++counts[id];
  std::string text;
  for (const auto& [id, count] : counts)
    text += (text.empty() ? "" : ", ") +
            mid::simulation::getProduct (catalog, id).shape->getName() + " x" +
            std::to_string (count);
  return text;
}

/** Dataset-level files: scenarios.json, models_info.json, camera.json. */
bool
stageDatasetFiles (const Options& options,
                   const mid::simulation::ProductCatalog& catalog,
                   mid::io::StagedFiles& files)
{
  std::string scenarios = "{\n";
  for (std::size_t i = 0; i < options.scenario_list.size(); ++i)
    scenarios += "  \"" + sceneFolderName (i) + "\": \"" +
                 mid::simulation::getScenarioName (options.scenario_list[i]) + "\"" +
                 (i + 1 < options.scenario_list.size() ? ",\n" : "\n");
  scenarios += "}\n";
  const mid::simulation::PinholeCamera camera;
  char camera_json[256];
  std::snprintf (
      camera_json,
      sizeof (camera_json),
      "{\"cx\": %.12g, \"cy\": %.12g, \"depth_scale\": %.12g, \"fx\": %.12g, "
      "\"fy\": %.12g, \"height\": %d, \"width\": %d}\n",
      camera.cx,
      camera.cy,
      mid::simulation::BOP_DEPTH_SCALE_MM,
      camera.fx,
      camera.fy,
      camera.height,
      camera.width);
  return stageText (files, options.out_dir + "/scenarios.json", scenarios) &&
         stageText (files,
                    options.out_dir + "/models_info.json",
                    mid::simulation::formatBopModelsInfo (catalog)) &&
         stageText (files, options.out_dir + "/camera.json", camera_json);
}

/** The scenario's name in the top left corner of a preview, white on a dark outline. */
cv::Mat
labelPreview (cv::Mat preview, const std::string& name)
{
  const double scale = preview.rows / 480.0;
  const cv::Point corner (static_cast<int> (10 * scale), static_cast<int> (36 * scale));
  for (const auto& [color, thickness] : {std::make_pair (cv::Scalar::all (0), 5),
                                         std::make_pair (cv::Scalar::all (255), 2)})
    cv::putText (preview,
                 name,
                 corner,
                 cv::FONT_HERSHEY_SIMPLEX,
                 1.1 * scale,
                 color,
                 std::max (1, static_cast<int> (thickness * scale)),
                 cv::LINE_AA);
  return preview;
}

bool
stagePreview (const std::string& path,
              const std::vector<cv::Mat>& previews,
              mid::io::StagedFiles& files)
{
  const cv::Mat picture = mid::simulation::stackPreviews (previews);
  const std::string temporary = files.stage (path);
  if (temporary.empty())
    return false; // staging said why
  bool written = false;
  try {
    written = !picture.empty() && cv::imwrite (temporary, picture);
  }
  catch (const cv::Exception&) {
    written = false;
  }
  if (!written)
    print_error ("Cannot write the preview '%s'.\n", path.c_str());
  return written;
}

/** Empties the output folder again (it was missing or empty) unless the dataset was
  * committed: the sub-folders made for staged files do not outlive a failure.
  */
class OutputFolder
{
public:
  explicit OutputFolder (const std::string& path)
  : path_ (path), existed_ (fs::exists (path))
  {}
  OutputFolder (const OutputFolder&) = delete;
  OutputFolder&
  operator= (const OutputFolder&) = delete;
  ~OutputFolder()
  {
    if (kept_)
      return;
    std::error_code error;
    if (existed_)
      for (const auto& entry : fs::directory_iterator (path_, error))
        fs::remove_all (entry.path(), error);
    else
      fs::remove_all (path_, error);
  }

  /** Create the folder; false after a one-line error. */
  bool
  create ()
  {
    std::error_code error;
    fs::create_directories (path_, error);
    if (error)
      print_error ("Cannot create the output folder '%s'.\n", path_.c_str());
    return !error;
  }

  void
  keep ()
  {
    kept_ = true;
  }

private:
  std::string path_;
  bool existed_ = false;
  bool kept_ = false;
};

int
run (int argc, char** argv)
{
  if (pcl::console::find_switch (argc, argv, "-h") ||
      pcl::console::find_switch (argc, argv, "--help")) {
    printHelp (argv[0]);
    return 0;
  }
  Options options;
  if (!parseOptions (argc, argv, options))
    return 1;
  mid::simulation::ProductCatalog catalog;
  if (!mid::simulation::makeProductCatalog (options.texture_dir, catalog))
    return 1;
  OutputFolder out_dir (options.out_dir);
  if (!out_dir.create())
    return 1;

  pcl::StopWatch total;
  mid::io::StagedFiles files;
  std::vector<cv::Mat> previews;
  for (std::size_t s = 0; s < options.scenario_list.size(); ++s) {
    const BenchmarkScenario scenario = options.scenario_list[s];
    mid::simulation::BopSceneWriter writer (options.out_dir + "/" + sceneFolderName (s),
                                            files);
    for (int image = 0; image < options.frames; ++image) {
      pcl::StopWatch watch;
      mid::simulation::BenchmarkFrameOptions frame_options;
      frame_options.scene.scenario = scenario;
      frame_options.scene.seed = frameSeed (options.seed, scenario, image);
      frame_options.scene.instances_per_type = options.instances_per_type;
      frame_options.supersampling = options.supersampling;
      frame_options.sensor_noise = options.sensor == "kinect";
      mid::simulation::BenchmarkFrame frame;
      if (!mid::simulation::makeBenchmarkFrame (frame_options, catalog, frame) ||
          !writer.addFrame (
              image, frame.frame, frame.scene, frame.product_ids, frame.info))
        return 1;
      if (!options.preview.empty() && image == 0)
        previews.push_back (labelPreview (
            mid::simulation::makeFramePreview (frame.frame, options.preview_scale),
            mid::simulation::getScenarioName (scenario)));
      print_info ("%s/%06d %-5s ",
                  sceneFolderName (s).c_str(),
                  image,
                  mid::simulation::getScenarioName (scenario).c_str());
      print_value ("%2zu", frame.product_ids.size());
      print_info (" objects (%s), %.0f ms\n",
                  describe (frame, catalog).c_str(),
                  watch.getTime());
    }
    if (!writer.stageJSON())
      return 1;
  }
  if (!stageDatasetFiles (options, catalog, files) ||
      (!options.preview.empty() && !stagePreview (options.preview, previews, files)) ||
      !files.commit())
    return 1;
  out_dir.keep();
  print_highlight ("Dataset: ");
  print_value ("%zu", options.scenario_list.size());
  print_info (" scenes x ");
  print_value ("%d", options.frames);
  print_info (" frames, seed ");
  print_value ("%u", options.seed);
  print_info (", sensor ");
  print_value ("%s", options.sensor.c_str());
  print_info (", written to ");
  print_value ("%s", options.out_dir.c_str());
  print_info (" in %.1f s\n", total.getTimeSeconds());
  return 0;
}

} // namespace

int
main (int argc, char** argv)
{
  try {
    return run (argc, argv);
  }
  catch (const std::exception& exception) {
    print_error ("Unexpected error: %s\n", exception.what());
    return 1;
  }
}
