// pcl_multi_instance_synth: render a deterministic synthetic RGB-D frame of a table with several
// identical textured objects and a few distractors, with its exact ground truth.
// Writes scene.pcd, rgb.png, depth.png (16-bit, mm) and ground_truth.json into the output folder.

#include "strict_options.h"

#include <mid/io/staged_files.h>
#include <mid/simulation/frame_io.h>
#include <mid/simulation/ground_truth_json.h>
#include <mid/simulation/scene_renderer.h>
#include <mid/simulation/sensor_model.h>
#include <mid/simulation/tabletop_scene.h>

#include <opencv2/imgcodecs.hpp>
#include <pcl/common/time.h>
#include <pcl/console/parse.h>
#include <pcl/console/print.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

using pcl::console::print_error;
using pcl::console::print_highlight;
using pcl::console::print_info;
using pcl::console::print_value;

namespace {

/** Everything the command line sets, with the library's defaults. */
struct Options
{
  mid::simulation::TabletopSceneOptions scene;
  std::string texture_dir = "data/textures";
  std::string out_dir = ".";
  std::string sensor = "kinect";
  /** Colour rays per pixel along each axis: anti-aliased textures keep SIFT repeatable. */
  int supersampling = 3;
};

/** The options of the command line, each with the number of values it takes. */
const mid::apps::OptionSpecs kOptions{{"-h", 0},
                                      {"--help", 0},
                                      {"-seed", 1},
                                      {"-instances", 1},
                                      {"-distractors", 1},
                                      {"-texture_dir", 1},
                                      {"-out_dir", 1},
                                      {"-sensor", 1},
                                      {"-supersampling", 1}};

void
printHelp (const char* program)
{
  const Options defaults;
  print_info (
      "Render a synthetic RGB-D frame with several identical objects on a table, and "
      "its ground truth.\n\n");
  print_info ("Usage: %s [options]\n\n", program);
  print_info (
      "  -seed S             seed of the layout and of the sensor noise (default ");
  print_value ("%u", defaults.scene.seed);
  print_info (")\n  -instances N        identical juice cartons, 1 to 10 (default ");
  print_value ("%d", defaults.scene.instances);
  print_info (")\n  -distractors N      objects that appear once, 0 to 2 (default ");
  print_value ("%d", defaults.scene.distractors);
  print_info (")\n  -texture_dir DIR    folder with the textures (default ");
  print_value ("%s", defaults.texture_dir.c_str());
  print_info (")\n  -out_dir DIR        output folder, created if missing (default ");
  print_value ("%s", defaults.out_dir.c_str());
  print_info (")\n  -sensor NAME        kinect (Kinect v1-like noise, holes) or exact "
              "(default ");
  print_value ("%s", defaults.sensor.c_str());
  print_info (")\n  -supersampling N    colour rays per pixel along each axis, 1 to %d "
              "(default ",
              mid::simulation::SceneRenderer::kMaxSupersampling);
  print_value ("%d", defaults.supersampling);
  print_info (
      ")\n\nOutput: scene.pcd (organized XYZRGB, binary_compressed, metres), rgb.png, "
      "depth.png\n(16-bit, millimetres), ground_truth.json (camera, per instance: "
      "object, "
      "4x4 pose model-to-camera, bbox, visible pixels).\n");
}

/** Parse the command line; false (after a one-line error) if it is unusable. */
bool
parseOptions (int argc, char** argv, Options& options)
{
  if (!mid::apps::onlyKnownArguments (argc, argv, kOptions))
    return false;
  long seed = options.scene.seed, instances = options.scene.instances,
       distractors = options.scene.distractors, supersampling = options.supersampling;
  if (!mid::apps::parseIntegerOption (argc, argv, "-seed", 0, 4294967295L, seed) ||
      !mid::apps::parseIntegerOption (argc, argv, "-instances", 1, 10, instances) ||
      !mid::apps::parseIntegerOption (argc, argv, "-distractors", 0, 2, distractors) ||
      !mid::apps::parseIntegerOption (argc,
                                      argv,
                                      "-supersampling",
                                      1,
                                      mid::simulation::SceneRenderer::kMaxSupersampling,
                                      supersampling))
    return false;
  options.scene.seed = static_cast<std::uint32_t> (seed);
  options.scene.instances = static_cast<int> (instances);
  options.scene.distractors = static_cast<int> (distractors);
  options.supersampling = static_cast<int> (supersampling);
  using pcl::console::parse_argument;
  parse_argument (argc, argv, "-texture_dir", options.texture_dir);
  parse_argument (argc, argv, "-out_dir", options.out_dir);
  parse_argument (argc, argv, "-sensor", options.sensor);
  if (options.sensor != "kinect" && options.sensor != "exact") {
    print_error ("-sensor must be 'kinect' or 'exact', got '%s'.\n",
                 options.sensor.c_str());
    return false;
  }
  if (options.texture_dir.empty() || options.out_dir.empty()) {
    print_error ("-texture_dir and -out_dir must not be empty.\n");
    return false;
  }
  std::error_code error;
  if (!std::filesystem::is_directory (options.texture_dir, error)) {
    print_error ("The texture folder '%s' does not exist (see -texture_dir).\n",
                 options.texture_dir.c_str());
    return false;
  }
  if (std::filesystem::exists (options.out_dir, error) &&
      !std::filesystem::is_directory (options.out_dir, error)) {
    print_error ("The output path '%s' is not a folder.\n", options.out_dir.c_str());
    return false;
  }
  return true;
}

bool
writeText (const std::string& path, const std::string& text)
{
  std::ofstream file (path, std::ios::binary | std::ios::trunc);
  file << text;
  file.close();
  if (!file) {
    print_error ("Cannot write '%s'.\n", path.c_str());
    return false;
  }
  return true;
}

bool
writeImage (const std::string& path, const cv::Mat& image)
{
  bool written = false;
  try {
    written = cv::imwrite (path, image);
  }
  catch (const cv::Exception&) {
    written = false;
  }
  if (!written)
    print_error ("Cannot write '%s'.\n", path.c_str());
  return written;
}

/** Write the four output files all-or-nothing. */
bool
writeOutputs (const Options& options,
              const mid::simulation::Scene& scene,
              const mid::simulation::RenderedFrame& frame,
              const pcl::PointCloud<pcl::PointXYZRGB>& cloud)
{
  std::error_code error;
  std::filesystem::create_directories (options.out_dir, error);
  if (error || !std::filesystem::is_directory (options.out_dir)) {
    print_error ("Cannot create the output folder '%s'.\n", options.out_dir.c_str());
    return false;
  }
  cv::Mat depth_16u;
  if (!mid::simulation::quantizeDepth (
          frame.depth, mid::simulation::MILLIMETRE_DEPTH_SCALE, depth_16u))
    return false;
  const std::string json = mid::simulation::formatGroundTruthJSON (
      scene,
      frame,
      mid::simulation::MILLIMETRE_DEPTH_SCALE,
      {{"seed", static_cast<double> (options.scene.seed)},
       {"sensor_noise", options.sensor == "kinect" ? 1.0 : 0.0}});

  const std::string dir = options.out_dir + "/";
  mid::io::StagedFiles files;
  if (!writeImage (files.stage (dir + "rgb.png"), frame.color) ||
      !writeImage (files.stage (dir + "depth.png"), depth_16u))
    return false;
  const std::string pcd_path = files.stage (dir + "scene.pcd");
  if (pcl::io::savePCDFileBinaryCompressed (pcd_path, cloud) != 0) {
    print_error ("Cannot write '%s'.\n", pcd_path.c_str());
    return false;
  }
  return writeText (files.stage (dir + "ground_truth.json"), json) && files.commit();
}

/** The whole program; main() only adds a last-resort handler for exceptions. */
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

  pcl::StopWatch step;
  mid::simulation::Scene scene;
  if (!mid::simulation::makeTabletopScene (options.scene, options.texture_dir, scene))
    return 1;
  const double scene_ms = step.getTime();

  step.reset();
  mid::simulation::SceneRenderer renderer;
  renderer.setSupersampling (options.supersampling);
  mid::simulation::RenderedFrame frame;
  if (!renderer.render (scene, frame))
    return 1;
  const double render_ms = step.getTime();

  step.reset();
  if (options.sensor == "kinect" &&
      !mid::simulation::applySensorModel (
          frame, mid::simulation::kinectSensorModel(), options.scene.seed, frame))
    return 1;
  pcl::PointCloud<pcl::PointXYZRGB> cloud;
  if (!mid::simulation::frameToCloud (
          frame, mid::simulation::MILLIMETRE_DEPTH_SCALE, cloud))
    return 1;
  const double sensor_ms = step.getTime();

  step.reset();
  if (!writeOutputs (options, scene, frame, cloud))
    return 1;
  const double write_ms = step.getTime();

  print_highlight ("Scene: ");
  print_value ("%zu", scene.getObjects().size());
  print_info (" objects (");
  print_value ("%d", options.scene.instances);
  print_info (" identical), seed ");
  print_value ("%u", options.scene.seed);
  print_info (", sensor ");
  print_value ("%s", options.sensor.c_str());
  print_info ("\n");
  for (std::size_t id = 0; id < scene.getObjects().size(); ++id) {
    const auto& stats = frame.instance_stats[id];
    print_info ("  %2zu %-14s ", id, scene.getObjects()[id].shape->getName().c_str());
    print_value ("%6d", stats.visible_pixels);
    print_info (" px, bbox %d %d %d %d\n",
                stats.bbox.x,
                stats.bbox.y,
                stats.bbox.width,
                stats.bbox.height);
  }
  print_info ("written to ");
  print_value ("%s", options.out_dir.c_str());
  print_info ("\ntiming_ms: scene ");
  print_value ("%.1f", scene_ms);
  print_info (", render ");
  print_value ("%.1f", render_ms);
  print_info (", sensor+cloud ");
  print_value ("%.1f", sensor_ms);
  print_info (", write ");
  print_value ("%.1f", write_ms);
  print_info ("\n");
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
