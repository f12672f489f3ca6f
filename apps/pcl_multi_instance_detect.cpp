// pcl_multi_instance_detect: find every instance of a previously discovered object model in a new
// RGB-D frame, also when only one instance is present. Same result format as discovery.

#include "app_support.h"
#include "visual_outputs.h"

#include <mid/features/sift_keypoint_extractor.h>
#include <mid/registration/instance_overlap.h>
#include <mid/registration/model_instance_detector.h>
#include <mid/registration/object_model_io.h>
#include <mid/segmentation/instance_extent.h>
#include <mid/segmentation/model_box_extension.h>

#include <pcl/common/io.h>
#include <pcl/common/time.h>
#include <pcl/console/parse.h>
#include <pcl/console/print.h>

#include <filesystem>
#include <string>

using pcl::console::print_error;
using pcl::console::print_info;
using pcl::console::print_value;

namespace {

using mid::apps::PointT;

/** Everything the command line sets. */
struct Options
{
  std::string model_path;
  mid::apps::SceneInput scene;
  std::string json_path;
  std::string extend_path;
  mid::apps::VisualOutputs pictures;
  float max_descriptor_distance = 350.0f;
  float inlier_threshold = 0.005f;
  int min_inliers = 5;
  float min_inlier_ratio = 0.125f;
  float min_inlier_spread = mid::ModelInstanceDetector().getMinInlierSpread();
  int iterations = 1000;
  unsigned seed = 0;
};

void
printHelp (const char* program)
{
  const Options d;
  print_info (
      "Find the instances of a discovered object model in a new RGB-D frame.\n\n");
  print_info ("Usage: %s MODEL.json SCENE.pcd [options]\n", program);
  print_info ("   or: %s MODEL.json -rgb COLOR.png -depth DEPTH.png -fx F -fy F -cx C "
              "-cy C\n\n",
              program);
  print_info ("  MODEL.json          a model written by pcl_multi_instance_discovery "
              "-models\n");
  mid::apps::printSceneInputHelp();
  print_info ("Output:\n  -json FILE          write the result as JSON (same format as "
              "discovery)\n");
  print_info (
      "  -extend FILE.json   write the model (FILE.json + FILE.pcd) extended by the "
      "keypoints\n                      each detected instance shows inside the "
      "object's box (the\n                      model file must hold one)\n");
  mid::apps::VisualOutputs::printHelp();
  print_info ("Parameters:\n");
  const auto line = [] (const char* option, const char* meaning, double value) {
    print_info ("  %-19s %s (default ", option, meaning);
    print_value ("%g", value);
    print_info (")\n");
  };
  line ("-max_desc_dist D",
        "largest SIFT descriptor distance of a match",
        static_cast<double> (d.max_descriptor_distance));
  line ("-inlier D",
        "RANSAC inlier threshold, metres",
        static_cast<double> (d.inlier_threshold));
  line ("-min_inliers N", "RANSAC minimum inliers", d.min_inliers);
  line ("-min_ratio R",
        "RANSAC minimum inlier ratio",
        static_cast<double> (d.min_inlier_ratio));
  line ("-min_spread D",
        "RANSAC inliers' least spread off their line, metres",
        static_cast<double> (d.min_inlier_spread));
  line ("-iterations N", "RANSAC hypotheses per detection", d.iterations);
  line ("-seed S", "seed of the random draws", d.seed);
}

/** The options of this app besides the scene and picture options, with their value counts. */
const mid::apps::OptionSpecs kOptions{{"-h", 0},
                                      {"-json", 1},
                                      {"-extend", 1},
                                      {"-max_desc_dist", 1},
                                      {"-inlier", 1},
                                      {"-min_inliers", 1},
                                      {"-min_ratio", 1},
                                      {"-min_spread", 1},
                                      {"-iterations", 1},
                                      {"-seed", 1}};

/** Whether the extended model's files (FILE.json and FILE.pcd) can be written without
  * replacing the result or the scene; false after a one-line error.
  */
bool
extendPathUsable (const Options& options)
{
  namespace fs = std::filesystem;
  const fs::path json (options.extend_path);
  if (json.extension() != ".json") {
    print_error ("The extended model's file must end in .json (got '%s').\n",
                 options.extend_path.c_str());
    return false;
  }
  // Two names of one file (a path that cannot be resolved names none).
  const auto same = [] (const fs::path& a, const std::string& b) {
    std::error_code error_a, error_b;
    const fs::path resolved_a = fs::weakly_canonical (a, error_a),
                   resolved_b = fs::weakly_canonical (fs::path (b), error_b);
    return !b.empty() && !error_a && !error_b && resolved_a == resolved_b;
  };
  const fs::path data = fs::path (json).replace_extension (".pcd");
  if (same (json, options.json_path) || same (data, options.scene.pcd_path)) {
    print_error ("-extend %s would write over %s.\n",
                 options.extend_path.c_str(),
                 same (json, options.json_path) ? "the -json result" : "the scene");
    return false;
  }
  return true;
}

bool
parseOptions (int argc, char** argv, Options& options)
{
  using pcl::console::parse_argument;
  // The model: the one .json argument that is not the value of -json or -extend.
  std::vector<std::string> models;
  for (int i = 1; i < argc; ++i)
    if (mid::apps::endsWithIgnoringCase (argv[i], ".json") &&
        std::string (argv[i - 1]) != "-json" && std::string (argv[i - 1]) != "-extend")
      models.emplace_back (argv[i]);
  if (models.size() != 1) {
    print_error ("Give exactly one model file MODEL.json (got %zu).\n", models.size());
    return false;
  }
  options.model_path = models.front();
  mid::apps::OptionSpecs known = kOptions;
  for (const auto& more :
       {mid::apps::sceneInputOptions(), mid::apps::VisualOutputs::options()})
    known.insert (known.end(), more.begin(), more.end());
  if (!mid::apps::onlyKnownArguments (argc, argv, known, {".json", ".pcd"}) ||
      !mid::apps::parseSceneInput (argc, argv, options.scene) ||
      !options.pictures.parse (argc, argv))
    return false;
  parse_argument (argc, argv, "-json", options.json_path);
  parse_argument (argc, argv, "-extend", options.extend_path);
  if (!options.extend_path.empty() && !extendPathUsable (options))
    return false;
  using mid::apps::parseNumber;
  if (!parseNumber (argc, argv, "-max_desc_dist", options.max_descriptor_distance) ||
      !parseNumber (argc, argv, "-inlier", options.inlier_threshold) ||
      !parseNumber (argc, argv, "-min_inliers", options.min_inliers) ||
      !parseNumber (argc, argv, "-min_ratio", options.min_inlier_ratio) ||
      !parseNumber (argc, argv, "-min_spread", options.min_inlier_spread) ||
      !parseNumber (argc, argv, "-iterations", options.iterations) ||
      !parseNumber (argc, argv, "-seed", options.seed))
    return false;
  if (options.min_inliers < 3) {
    print_error ("Invalid parameter: min_inliers is %d, must be >= 3.\n",
                 options.min_inliers);
    return false;
  }
  if (!(options.min_inlier_spread >= 0.0f)) {
    print_error ("Invalid parameter: min_spread is %g, must be >= 0.\n",
                 static_cast<double> (options.min_inlier_spread));
    return false;
  }
  return true;
}

/** The model extended by the keypoints each detected instance (the model's instances) shows
  * inside the object's box, placed at the instance (ModelBoxExtender, with the box known from
  * the model file); prints what was added. False after an error message.
  */
bool
extendModel (const pcl::PointCloud<PointT>& cloud,
             const mid::DiscoveryResult& result,
             const mid::ModelSize& box,
             mid::ObjectModel& model)
{
  if (model.instances.empty()) {
    print_info ("extended:  nothing detected, the model is written as it was\n");
    return true;
  }
  auto organized = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  pcl::copyPointCloud (cloud, *organized);
  Eigen::Vector4f plane;
  if (!mid::fitSupportPlane (
          *organized, mid::kDefaultPlaneTolerance, mid::kMinSupportPlaneShare, plane)) {
    print_info ("extended:  no support plane in the frame (the box stands on one), the "
                "model is written as it was\n");
    return true;
  }
  mid::ModelBoxExtender extender;
  extender.setInputKeypoints (result.keypoints);
  extender.setKeypointSurface ({organized, mid::pixelIndices (result.image_keypoints)});
  extender.setSupportPlane (plane);
  extender.setInputDescriptors (result.descriptors);
  extender.setKnownSizes ({box});
  mid::ObjectModels models{model};
  mid::ModelExtension extension;
  if (!extender.extend (models, extension)) {
    print_error ("Could not extend the model (see the message above).\n");
    return false;
  }
  print_info ("extended:  ");
  print_value ("%zu", models[0].landmarks.size() - model.landmarks.size());
  print_info (" landmarks added from %zu instances (%zu in all)\n",
              model.instances.size(),
              models[0].landmarks.size());
  model = std::move (models[0]);
  return true;
}

} // namespace

int
main (int argc, char** argv)
{
  if (argc < 2 || pcl::console::find_switch (argc, argv, "-h") ||
      pcl::console::find_switch (argc, argv, "--help")) {
    printHelp (argv[0]);
    return argc < 2 ? 1 : 0;
  }
  Options options;
  if (!parseOptions (argc, argv, options))
    return 1;

  pcl::StopWatch watch;
  auto model = std::make_shared<mid::ObjectModel>();
  mid::ModelSize box;
  if (!mid::loadObjectModel (options.model_path, *model, box))
    return 1;
  if (!options.extend_path.empty() && !box.valid) {
    print_error (
        "-extend: the model file '%s' holds no box of the object (its discovery "
        "measured none), and only the box tells which keypoints belong to it.\n",
        options.model_path.c_str());
    return 1;
  }
  auto cloud = pcl::make_shared<pcl::PointCloud<PointT>>();
  if (!mid::apps::loadScene (options.scene, *cloud))
    return 1;
  const double load_ms = watch.getTime();
  mid::apps::ResultFiles outputs;
  // Each instance rests on the model by its own matches: no discovery groups.
  outputs.setInstanceGroups (false);
  if (!outputs.stage (options.json_path, "") || !options.pictures.stage (outputs) ||
      (!options.extend_path.empty() &&
       !mid::apps::ResultFiles::canStage (options.extend_path)))
    return 1;

  pcl::StopWatch total;
  watch.reset();
  mid::DiscoveryResult result;
  mid::SIFTKeypointExtractor<PointT> extractor;
  extractor.setInputCloud (cloud);
  result.keypoints = pcl::make_shared<mid::KeypointCloud>();
  result.descriptors = pcl::make_shared<mid::SIFTDescriptorCloud>();
  if (!extractor.compute (*result.keypoints, *result.descriptors))
    return 1;
  result.image_keypoints = extractor.getImageKeypoints();
  result.timing_ms.emplace_back ("features", watch.getTime());

  watch.reset();
  mid::ModelInstanceDetector detector;
  detector.setModel (model);
  detector.setInputKeypoints (result.keypoints);
  detector.setInputDescriptors (result.descriptors);
  detector.setMaxDescriptorDistance (options.max_descriptor_distance);
  detector.setInlierThreshold (options.inlier_threshold);
  detector.setMinInliers (static_cast<std::size_t> (options.min_inliers));
  detector.setMinInlierRatio (options.min_inlier_ratio);
  detector.setMinInlierSpread (options.min_inlier_spread);
  detector.setMaxIterations (options.iterations);
  detector.setSeed (options.seed);
  if (!detector.detect (model->instances))
    return 1;
  // Each detection takes only its inliers out of the matches: the rest of a copy's keypoints
  // can detect it a second time. Drop a detection whose keypoints intermix with those of one
  // with more keypoints, as discovery does.
  const std::size_t overlapping =
      mid::removeOverlappingInstances (*result.keypoints, *model);
  result.timing_ms.emplace_back ("detection", watch.getTime());
  result.timing_ms.emplace_back ("total", total.getTime());
  if (!model->instances.empty()) {
    result.models.push_back (*model);
    result.model_sizes.push_back (box);
  }

  mid::apps::printResult (*cloud, result, load_ms);
  if (overlapping > 0)
    print_info (
        "(%zu more detections intermixed with a larger one's keypoints: dropped)\n",
        overlapping);
  if (!options.extend_path.empty() &&
      (!extendModel (*cloud, result, box, *model) ||
       !outputs.saveModel (options.extend_path, *model, box)))
    return 1;
  if (!options.pictures.write (cloud, result) ||
      !outputs.write (result, options.scene.name()))
    return 1;
  return options.pictures.show (cloud, result) ? 0 : 1;
}
