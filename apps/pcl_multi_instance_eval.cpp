// pcl_multi_instance_eval: score discovery results against BOP ground truth with the rules of
// Abbeloos et al. (3DV 2017) and print a Table-2-style report per scenario and in total.

#include "strict_options.h"

#include <mid/evaluation/benchmark_report.h>
#include <mid/evaluation/detection_result.h>
#include <mid/evaluation/ground_truth.h>
#include <mid/evaluation/object_size.h>
#include <mid/evaluation/object_symmetry.h>
#include <mid/evaluation/shared_surface.h>
#include <mid/io/staged_files.h>

#include <nlohmann/json.hpp>
#include <pcl/console/parse.h>
#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using pcl::console::print_error;
using pcl::console::print_info;

namespace {

namespace fs = std::filesystem;

/** How the surface each annotated instance shares with another copy is measured
  * (mid::evaluation::measureSharedSurface()) and reported.
  */
struct SharedSurfaceSettings
{
  float cell = 0.01f;    ///< edge of the model-frame cubes, metres; 0 = no such table
  float max_tilt = 2.0f; ///< largest transition tilt between two views of a shared cube
  float min_contrast =
      4.0f;          ///< mean local contrast of a textured cube; 0 = no texture test
  int findable = 10; ///< shared cubes from which an instance counts as findable
};

void
printHelp (const char* program)
{
  print_info ("Score discovery results against BOP ground truth (Abbeloos et al. 3DV "
              "2017 rules).\n\n");
  print_info ("Usage: %s DATASET_DIR RESULTS_DIR [RESULTS_DIR...] [-names A,B,...] "
              "[-report FILE]\n"
              "          [-min_inside F] [-frames] [-shared_cell M] [-findable N]\n"
              "          [-max_tilt T] [-min_contrast C]\n\n",
              program);
  print_info ("  DATASET_DIR   BOP scene folders (000000/, 000001/, ...) with "
              "scene_gt.json,\n");
  print_info ("                scene_gt_info.json and mask_visib/; an optional "
              "scenarios.json maps\n");
  print_info (
      "                a scene folder name to its scenario name, an optional\n");
  print_info ("                models_info.json (BOP) the symmetries of each object's "
              "shape\n");
  print_info ("                and its size (then a table compares the results' "
              "boxes with it)\n");
  print_info ("  RESULTS_DIR   <scene>/<image>.json: results of "
              "pcl_multi_instance_discovery -json\n");
  print_info ("                (a missing result counts as an empty one and is "
              "reported); with\n");
  print_info (
      "                several (methods on the same frames, e.g. ours and PCL's "
      "peers), one\n");
  print_info ("                table per method and a side-by-side table, the first "
              "method being\n");
  print_info ("                the reference of the grouping time ratio\n");
  print_info ("  -names A,B    the methods' names in the tables (default: the folders' "
              "names)\n");
  print_info ("  -report FILE  also write the report (markdown tables) to FILE\n");
  print_info ("  -min_inside F share of an instance's keypoints that must lie on the "
              "annotated\n");
  print_info ("                instance (default 0.9, the paper's)\n");
  print_info ("  -frames       also print each frame's counts on instances (true and "
              "false\n");
  print_info (
      "                positives, false negatives), its number of objects and its "
      "missed\n");
  print_info ("                instances (type, visible pixels, shared surface, and "
              "whether a\n");
  print_info ("                false positive object lies on them)\n");
  print_info (
      "  -shared_cell M  when every scene has depth/ and scene_camera.json: edge "
      "of the\n");
  print_info ("                model-frame cubes in which the surface each annotated "
              "instance\n");
  print_info (
      "                shares with another copy of its type is counted (default "
      "0.01 m;\n");
  print_info ("                0 = no such table); a second table gives recall against "
              "it\n");
  print_info (
      "  -findable N   that table's recall and F1 count only instances sharing at "
      "least\n");
  print_info ("                N cubes (default 10)\n");
  print_info (
      "  -max_tilt T   a cube counts as shared when the transition tilt between "
      "the two\n");
  print_info ("                views of it is at most T (default 2, where SIFT stops "
              "matching)\n");
  print_info ("  -min_contrast C  and when both views show texture there: a mean local "
              "contrast\n");
  print_info ("                (grey-level standard deviation in 5 x 5 pixels) of C or "
              "more\n");
  print_info (
      "                (default 4; 0 = plain surface counts too; needs rgb/)\n");
}

/** A number as printf's %g writes it. */
std::string
formatNumber (double value)
{
  char text[32];
  std::snprintf (text, sizeof (text), "%g", value);
  return text;
}

std::string
imageName (int image)
{
  char name[32];
  std::snprintf (name, sizeof (name), "%06d.json", image);
  return name;
}

/** Scene folder name -> scenario name, from DATASET_DIR/scenarios.json when present. */
std::map<std::string, std::string>
readScenarios (const fs::path& dataset)
{
  std::map<std::string, std::string> names;
  std::ifstream file (dataset / "scenarios.json");
  if (!file)
    return names;
  try {
    nlohmann::json document;
    file >> document;
    for (const auto& [scene, name] : document.items())
      names[scene] = name.get<std::string>();
  }
  catch (const std::exception& error) {
    print_error (
        "scenarios.json is not valid: %s; scene folders are used as scenarios.\n",
        error.what());
  }
  return names;
}

/** The -frames lines of one frame: its counts, then each missed instance with its type,
  * visible pixels and shared surface, and whether a false positive object lies on it.
  */
void
printFrame (const std::string& scene,
            int image,
            const mid::evaluation::GroundTruthFrame& frame,
            const mid::evaluation::DetectionResult& result,
            const mid::evaluation::FrameScore& score,
            bool textured)
{
  std::printf ("%s/%06d: %zu objects, instances TP %d FP %d FN %d\n",
               scene.c_str(),
               image,
               result.objects.size(),
               score.instance_tp,
               score.instance_fp,
               score.instance_fn);
  for (const std::size_t k : score.missed_instances) {
    const auto& instance = frame.instances[k];
    std::printf ("  missed instance %zu: obj_id %d, %d pixels visible",
                 k,
                 instance.object_id,
                 instance.visible_pixels);
    if (instance.shared_surface_cells >= 0)
      std::printf (", shares %d %scubes",
                   instance.shared_surface_cells,
                   textured ? "textured " : "");
    const bool located = std::find (score.missed_but_located.begin(),
                                    score.missed_but_located.end(),
                                    k) != score.missed_but_located.end();
    std::printf ("%s\n", located ? ", located by a false positive object" : "");
  }
}

/** Every scene's frames scored against one method's results, per scenario; false if a scene or
  * a result cannot be read (the reader printed why).
  */
bool
scoreMethod (const std::vector<fs::path>& scenes,
             const std::map<std::string, std::string>& scenario_of,
             const fs::path& results,
             double min_inside,
             const SharedSurfaceSettings& surface,
             const mid::evaluation::ObjectSymmetryTable& symmetries,
             bool per_frame,
             std::map<std::string, mid::evaluation::ScoreSummary>& scenarios)
{
  std::size_t missing = 0;
  for (const auto& scene_path : scenes) {
    mid::evaluation::GroundTruthScene truth;
    if (!mid::evaluation::loadBopScene (scene_path.string(), truth) ||
        (surface.cell > 0.0f &&
         !mid::evaluation::measureSharedSurface (scene_path.string(),
                                                 surface.cell,
                                                 surface.max_tilt,
                                                 surface.min_contrast,
                                                 truth)))
      return false;
    const std::string scene = scene_path.filename().string();
    const auto named = scenario_of.find (scene);
    auto& summary = scenarios[named != scenario_of.end() ? named->second : scene];
    for (const auto& [image, frame] : truth) {
      const fs::path result_path = results / scene / imageName (image);
      mid::evaluation::DetectionResult result;
      if (!fs::exists (result_path))
        ++missing;
      else if (!mid::evaluation::readDetectionResult (result_path.string(), result))
        return false;
      const auto score =
          mid::evaluation::scoreFrame (frame, result, min_inside, symmetries);
      if (per_frame)
        printFrame (scene, image, frame, result, score, surface.min_contrast > 0.0f);
      summary.add (score, result);
    }
  }
  if (missing > 0)
    print_info ("%zu frames had no result file in '%s' and were scored as empty "
                "results.\n",
                missing,
                results.string().c_str());
  return true;
}

/** The comma-separated names of -names, or the results folders' own names without it. */
std::vector<std::string>
methodNames (const std::string& list, const std::vector<fs::path>& results)
{
  std::vector<std::string> names;
  std::stringstream stream (list);
  for (std::string name; std::getline (stream, name, ',');)
    names.push_back (name);
  if (list.empty())
    for (const auto& folder : results) {
      const fs::path normal = fs::absolute (folder).lexically_normal();
      names.push_back (normal.has_filename()
                           ? normal.filename().string()
                           : normal.parent_path().filename().string());
    }
  return names;
}

/** True if some pair of some scenario has the groups of the result (discovery results do). */
bool
anyPairGroups (const std::map<std::string, mid::evaluation::ScoreSummary>& scenarios)
{
  for (const auto& [name, summary] : scenarios)
    for (const int g : summary.pair_groups)
      if (g >= 0)
        return true;
  return false;
}

} // namespace

int
main (int argc, char** argv)
{
  if (argc < 3 || pcl::console::find_switch (argc, argv, "-h")) {
    printHelp (argv[0]);
    return argc < 3 && !pcl::console::find_switch (argc, argv, "-h") ? 1 : 0;
  }
  const fs::path dataset (argv[1]);
  std::vector<fs::path> results;
  for (int i = 2; i < argc && argv[i][0] != '-'; ++i)
    results.emplace_back (argv[i]);
  // Every folder comes before the options, which are checked like every app's (an unknown
  // word or a missing value would otherwise be ignored).
  std::vector<char*> options{argv[0]};
  options.insert (options.end(), argv + 2 + results.size(), argv + argc);
  if (!mid::apps::onlyKnownArguments (static_cast<int> (options.size()),
                                      options.data(),
                                      {{"-report", 1},
                                       {"-min_inside", 1},
                                       {"-names", 1},
                                       {"-frames", 0},
                                       {"-shared_cell", 1},
                                       {"-findable", 1},
                                       {"-max_tilt", 1},
                                       {"-min_contrast", 1}}))
    return 1;
  std::string report_path, names_list;
  double min_inside = 0.9;
  SharedSurfaceSettings surface;
  pcl::console::parse_argument (argc, argv, "-report", report_path);
  if (!mid::apps::parseNumber (argc, argv, "-min_inside", min_inside) ||
      !mid::apps::parseNumber (argc, argv, "-shared_cell", surface.cell) ||
      !mid::apps::parseNumber (argc, argv, "-findable", surface.findable) ||
      !mid::apps::parseNumber (argc, argv, "-max_tilt", surface.max_tilt) ||
      !mid::apps::parseNumber (argc, argv, "-min_contrast", surface.min_contrast))
    return 1;
  pcl::console::parse_argument (argc, argv, "-names", names_list);
  const bool per_frame = pcl::console::find_switch (argc, argv, "-frames");
  if (!(min_inside > 0.0 && min_inside <= 1.0)) {
    print_error ("Invalid parameter: min_inside is %g, must be in (0, 1].\n",
                 min_inside);
    return 1;
  }
  if (!(surface.cell >= 0.0f) || surface.findable < 0 || !(surface.max_tilt >= 1.0f) ||
      !(surface.min_contrast >= 0.0f)) {
    print_error (
        "Invalid parameter: -shared_cell is %g, -findable %d and -min_contrast %g "
        "(none may be negative), -max_tilt %g (must be 1 or more).\n",
        static_cast<double> (surface.cell),
        surface.findable,
        static_cast<double> (surface.min_contrast),
        static_cast<double> (surface.max_tilt));
    return 1;
  }
  if (results.empty()) {
    print_error ("No RESULTS_DIR given.\n");
    return 1;
  }
  const auto not_folder = [] (const fs::path& folder) {
    return !fs::is_directory (folder);
  };
  const auto missing = std::find_if (results.begin(), results.end(), not_folder);
  if (not_folder (dataset) || missing != results.end()) {
    print_error ("'%s' is not a folder.\n",
                 (not_folder (dataset) ? dataset : *missing).string().c_str());
    return 1;
  }
  const std::vector<std::string> names = methodNames (names_list, results);
  if (names.size() != results.size()) {
    print_error (
        "-names gives %zu names for %zu RESULTS_DIRs.\n", names.size(), results.size());
    return 1;
  }
  mid::io::StagedFiles outputs;
  const std::string report_temporary =
      report_path.empty() ? std::string() : outputs.stage (report_path);
  if (!report_path.empty() && report_temporary.empty())
    return 1;
  const auto scenario_of = readScenarios (dataset);
  std::vector<fs::path> scenes;
  for (const auto& entry : fs::directory_iterator (dataset))
    if (entry.is_directory() && fs::exists (entry.path() / "scene_gt.json"))
      scenes.push_back (entry.path());
  std::sort (scenes.begin(), scenes.end());
  if (scenes.empty()) {
    print_error ("'%s' holds no BOP scene folder (with scene_gt.json).\n", argv[1]);
    return 1;
  }
  const bool has_depth =
      std::all_of (scenes.begin(), scenes.end(), [] (const fs::path& s) {
        return fs::is_directory (s / "depth") && fs::exists (s / "scene_camera.json");
      });
  if (surface.cell > 0.0f && !has_depth) {
    print_info (
        "Not every scene folder has depth/ and scene_camera.json: no shared-surface "
        "table.\n");
    surface.cell = 0.0f;
  }
  const bool has_colour =
      std::all_of (scenes.begin(), scenes.end(), [] (const fs::path& s) {
        return fs::is_directory (s / "rgb");
      });
  if (surface.cell > 0.0f && surface.min_contrast > 0.0f && !has_colour) {
    print_info ("Not every scene folder has rgb/: the shared surface counts plain "
                "surface too.\n");
    surface.min_contrast = 0.0f;
  }
  mid::evaluation::ObjectSymmetryTable symmetries;
  mid::evaluation::ObjectSizeTable sizes;
  if (!fs::exists (dataset / "models_info.json"))
    print_info (
        "'%s' has no models_info.json: pose errors modulo the shapes' symmetries "
        "are the plain ones, and the objects' boxes are not compared.\n",
        argv[1]);
  else if (!mid::evaluation::loadBopModelSymmetries (
               (dataset / "models_info.json").string(), symmetries) ||
           !mid::evaluation::loadBopModelSizes ((dataset / "models_info.json").string(),
                                                sizes))
    return 1;
  std::vector<mid::evaluation::MethodScores> methods;
  for (std::size_t m = 0; m < results.size(); ++m) {
    mid::evaluation::MethodScores method;
    method.name = names[m];
    if (!scoreMethod (scenes,
                      scenario_of,
                      results[m],
                      min_inside,
                      surface,
                      symmetries,
                      per_frame,
                      method.scenarios))
      return 1;
    methods.push_back (method);
  }
  std::string report;
  for (const auto& method : methods) {
    if (methods.size() > 1)
      report += "\n" + method.name + ":\n\n";
    report += mid::evaluation::formatReport (method.scenarios);
    report +=
        "\nRelative poses of the correctly found instances of one object (pairs "
        "whose rotation is wrong by more than 10 and 45 deg, then the same modulo "
        "the symmetries of the object's shape, from models_info.json):\n\n" +
        mid::evaluation::formatPoseErrorReport (method.scenarios, {10.0, 45.0});
    if (anyPairGroups (method.scenarios))
      report +=
          "\nThe same pairs within one group of the result (copies whose relative "
          "pose rests on landmarks they share, their print) and across groups "
          "(relative poses that rest on a box):\n\n" +
          mid::evaluation::formatGroupPoseReport (method.scenarios, 45.0);
    if (!sizes.empty())
      report +=
          "\nThe box each correct object's copies occupy on the table (the result's "
          "\"box\"; edges against the product's size from models_info.json, largest "
          "edge error):\n\n" +
          mid::evaluation::formatBoxSizeReport (method.scenarios, sizes);
    if (surface.cell > 0.0f)
      report +=
          "\nRecall against the " +
          std::string (surface.min_contrast > 0.0f ? "textured " : "") +
          "surface each instance shares with another copy of its type (cubes "
          "of " +
          std::to_string (static_cast<int> (std::lround (surface.cell * 1000.0f))) +
          " mm in the model frame" +
          (surface.min_contrast > 0.0f
               ? ", local contrast " +
                     formatNumber (static_cast<double> (surface.min_contrast)) +
                     " grey levels or more in both views"
               : std::string()) +
          "):\n\n" +
          mid::evaluation::formatSharedSurfaceReport (method.scenarios,
                                                      surface.findable);
  }
  if (methods.size() > 1)
    report += "\nSide by side (time ratio: " + methods.front().name +
              "'s median grouping time / the method's):\n\n" +
              mid::evaluation::formatComparison (methods);
  std::printf ("%s", report.c_str());
  if (!report_path.empty()) {
    std::ofstream file (report_temporary);
    file << report;
    file.close();
    if (!file || !outputs.commit()) {
      print_error ("Could not write '%s'.\n", report_path.c_str());
      return 1;
    }
  }
  return 0;
}
