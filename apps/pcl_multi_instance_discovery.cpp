// pcl_multi_instance_discovery: discover the objects that appear several times in ONE RGB-D
// frame, model them, and localize every instance (Abbeloos et al., 3DV 2017). Prints counts,
// objects and the time of each stage; -json writes the result (doc/result_format.md); -overlay,
// -screenshot and -view show it (doc/visualization.md).

#include "app_support.h"
#include "visual_outputs.h"

#include <mid/discovery/multi_instance_discovery.h>

#include <pcl/common/time.h>
#include <pcl/console/parse.h>
#include <pcl/console/print.h>
#include <pcl/point_types.h>

#include <string>
#include <vector>

using pcl::console::print_error;
using pcl::console::print_info;
using pcl::console::print_value;

namespace {

using mid::apps::PointT;

/** Everything the command line sets, with the library's defaults. */
struct Options
{
  mid::apps::SceneInput scene;
  std::string json_path;
  std::string model_prefix;
  mid::apps::VisualOutputs pictures;
  mid::DiscoveryParameters parameters;
};

void
printHelp (const char* program)
{
  const mid::DiscoveryParameters d;
  print_info ("Discover objects that appear several times in one RGB-D frame.\n\n");
  print_info ("Usage: %s SCENE.pcd [options]\n", program);
  print_info (
      "   or: %s -rgb COLOR.png -depth DEPTH.png -fx F -fy F -cx C -cy C [options]\n\n",
      program);
  mid::apps::printSceneInputHelp();
  print_info ("Output:\n");
  print_info ("  -json FILE          write the result as JSON (no window, no display "
              "needed)\n");
  print_info ("  -models PREFIX      write each object's model as PREFIX<id>.json + "
              "PREFIX<id>.pcd\n");
  mid::apps::VisualOutputs::printHelp();
  print_info ("Parameters (defaults: Abbeloos et al. 3DV 2017 where the paper gives a "
              "value):\n");
  const auto line = [] (const char* option, const char* meaning, double value) {
    print_info ("  %-19s %s (default ", option, meaning);
    print_value ("%g", value);
    print_info (")\n");
  };
  line ("-max_keypoints N", "keep the N strongest keypoints, 0 = all", d.max_keypoints);
  line ("-contrast T", "SIFT contrast threshold", d.contrast_threshold);
  line ("-normal_radius R",
        "keypoint normal radius, metres",
        static_cast<double> (d.normal_radius));
  line ("-max_desc_dist D",
        "largest SIFT descriptor distance of a match",
        static_cast<double> (d.max_descriptor_distance));
  line ("-min_kp_dist M",
        "skip match candidates closer than M metres",
        static_cast<double> (d.min_keypoint_distance));
  line ("-ratio R",
        "Lowe ratio test, 1 = off",
        static_cast<double> (d.max_distance_ratio));
  print_info ("  -mutual             keep only mutual best matches\n");
  line ("-knn K",
        "matches per keypoint: its K most similar keypoints",
        d.matches_per_keypoint);
  line ("-ppf_dist D",
        "point pair feature distance threshold, metres",
        static_cast<double> (d.ppf_distance));
  line ("-ppf_angle A",
        "point pair feature angle threshold, degrees",
        static_cast<double> (d.ppf_angle) * 180.0 / M_PI);
  line ("-min_edge E",
        "shortest triangle edge, metres",
        static_cast<double> (d.min_edge_length));
  line ("-max_edge E",
        "longest triangle edge, metres",
        static_cast<double> (d.max_edge_length));
  line ("-min_angle A",
        "smallest triangle angle, degrees",
        static_cast<double> (d.min_triangle_angle) * 180.0 / M_PI);
  line ("-overlap D",
        "triangles closer than D overlap, < 0 = off",
        static_cast<double> (d.overlap_distance));
  line (
      "-triplets_per_kp L", "accepted triplets per keypoint", d.triplets_per_keypoint);
  line ("-eps E", "DBSCAN distance, metres", static_cast<double> (d.cluster_distance));
  line (
      "-min_cluster N", "DBSCAN min samples", static_cast<double> (d.min_cluster_size));
  line ("-link_dist D",
        "drop a shared-keypoint link whose sets' poses disagree this much, metres",
        static_cast<double> (d.link_tolerance));
  line ("-inlier D",
        "RANSAC inlier threshold, metres",
        static_cast<double> (d.inlier_threshold));
  line (
      "-min_inliers N", "RANSAC minimum inliers", static_cast<double> (d.min_inliers));
  line ("-merge_inliers N",
        "RANSAC minimum inliers to merge two models",
        static_cast<double> (d.min_merge_inliers));
  line ("-merge_fraction F",
        "or this share of the smaller model's landmarks",
        static_cast<double> (d.merge_fraction));
  line ("-region_margin M",
        "keypoints this far beyond a model's landmarks join its region, metres",
        static_cast<double> (d.region_margin));
  line ("-region_inliers N",
        "RANSAC minimum inliers to merge two models through their regions",
        static_cast<double> (d.min_region_merge_inliers));
  line ("-join_corr C",
        "smallest grey-level correlation of a copy joining a model, each way",
        static_cast<double> (d.min_join_correlation));
  line ("-leftover_desc_dist D",
        "largest descriptor distance of a match in the leftover round",
        static_cast<double> (d.leftover_descriptor_distance));
  line ("-leftover_margin M",
        "keypoints this far from every instance's box are left over, metres",
        static_cast<double> (d.leftover_margin));
  line ("-guided_seed_dist D",
        "guided search: largest descriptor distance of its one seed match",
        static_cast<double> (d.guided_seed_distance));
  line ("-guided_desc_dist D",
        "guided search: largest descriptor distance of a guided match",
        static_cast<double> (d.guided_descriptor_distance));
  line ("-guided_inliers N",
        "guided search: fewest inliers of an instance",
        static_cast<double> (d.guided_min_inliers));
  line ("-guided_corr C",
        "guided search: smallest grey-level correlation, each way",
        static_cast<double> (d.guided_min_correlation));
  line (
      "-guided_local_corr C",
      "guided search: smallest grey-level correlation of one keypoint's neighbourhood",
      static_cast<double> (d.guided_neighbourhood_correlation));
  line ("-guided_disagree S",
        "guided search: largest share of keypoint neighbourhoods below "
        "-guided_local_corr",
        static_cast<double> (d.guided_max_disagreeing));
  line ("-guided_hypotheses N",
        "guided search: seed matches tried per model",
        static_cast<double> (d.guided_hypotheses));
  line ("-patch_radius R",
        "patches: keypoints within R metres of the patch's centre",
        static_cast<double> (d.patch_radius));
  line ("-patch_inliers N",
        "patches: fewest guided inliers of a copy",
        static_cast<double> (d.patch_min_inliers));
  line ("-patch_corr C",
        "patches: smallest grey-level correlation of a copy, each way",
        static_cast<double> (d.patch_min_correlation));
  line (
      "-max_patches N", "patches tried per frame", static_cast<double> (d.max_patches));
  line ("-box_margin M",
        "box search: keypoints this far beyond a copy's box extend its model, metres",
        static_cast<double> (d.box_search_margin));
  line ("-box_hypotheses N",
        "box search: seed matches tried per model",
        static_cast<double> (d.box_search_hypotheses));
  line ("-split_corr C",
        "instances of one model alike at this grey-level correlation, each way",
        static_cast<double> (d.split_min_correlation));
  line ("-surface_step N",
        "surface refinement: a depth sample every N pixels",
        d.surface_sample_step);
  line ("-surface_dist D",
        "surface refinement: largest partner distance, metres",
        static_cast<double> (d.surface_max_distance));
  line ("-surface_weight W",
        "surface refinement: weight of a depth sample against a landmark",
        static_cast<double> (d.surface_weight));
  line ("-surface_iterations N", "surface refinement: rounds", d.surface_iterations);
  line ("-size_tol D",
        "size merge: largest difference of two box edges, metres",
        static_cast<double> (d.size_tolerance));
  line ("-size_rel_tol R",
        "size merge: ... or R times the edge, if larger",
        static_cast<double> (d.relative_size_tolerance));
  line (
      "-size_consensus R",
      "size merge: a copy's pixels within R of another copy's make its consensus box, "
      "metres (0: none)",
      static_cast<double> (d.size_merge_consensus_radius));
  line ("-print_share S",
        "support prints: smallest share of an instance's keypoints within 1 cm of the "
        "table",
        static_cast<double> (d.support_print_min_share));
  line ("-repeat_rot A",
        "repeated prints: largest turn between two instances on one object, degrees",
        static_cast<double> (d.repeated_print_max_rotation) * 180.0 / M_PI);
  line ("-repeat_shift R",
        "repeated prints: largest shift, times the object box's shortest edge",
        static_cast<double> (d.repeated_print_max_shift));
  line ("-repeat_along R",
        "repeated prints: largest shift, times the object box's width along it",
        static_cast<double> (d.repeated_print_max_shift_along));
  line ("-repeat_inside S",
        "repeated prints: smallest share of an instance's keypoints in the other's box",
        static_cast<double> (d.repeated_print_min_inside));
  line ("-disagree_surrounded S",
        "size disagreement: largest share of occupied pixels around a copy standing "
        "alone",
        static_cast<double> (d.size_disagreement_max_surrounded));
  line ("-disagree_copies N",
        "size disagreement: fewest copies of a model it judges",
        d.size_disagreement_min_copies);
  line ("-box_turn_gain G",
        "box turns: correlation a turn must gain over the present one",
        static_cast<double> (d.box_turn_min_gain));
  line ("-obs_residual D",
        "observations: largest distance of a kept one from its landmark, metres",
        static_cast<double> (d.observation_max_residual));
  line ("-obs_margin D",
        "observations: largest distance of a kept one outside the model's landmark box "
        "and outside the box its copies occupy on the table, metres",
        static_cast<double> (d.observation_box_margin));
  line ("-size_kp N",
        "size search: free keypoints an object needs to become an instance",
        d.size_search_min_keypoints);
  line ("-size_agree N",
        "size search: copies of a model that must agree on its size",
        d.size_search_min_agreeing);
  line ("-size_surrounded S",
        "size discovery: largest share of occupied pixels around an object",
        static_cast<double> (d.size_discovery_max_surrounded));
  line ("-size_min_edge D",
        "size discovery: shortest edge of an object, metres",
        static_cast<double> (d.size_discovery_min_edge));
  line ("-min_correlation C",
        "smallest grey-level correlation of a verified cluster, each way",
        static_cast<double> (d.min_photometric_correlation));
  line (
      "-max_chroma D",
      "largest difference of the mean colours (chromaticity) a pose compares, 2 = off "
      "(with -max_vivid_chroma 2 for all colour checks)",
      static_cast<double> (d.max_chromaticity_difference));
  line ("-max_vivid_chroma D",
        "the same over the vivid colours alone (the inks), 2 = off",
        static_cast<double> (d.max_vivid_chromaticity_difference));
  line ("-verify_radius R",
        "verification: surface compared around a keypoint, metres",
        static_cast<double> (d.verification_radius));
  line ("-min_ratio R",
        "RANSAC minimum inlier ratio",
        static_cast<double> (d.min_inlier_ratio));
  line ("-min_spread D",
        "RANSAC inliers' least spread off their line, metres",
        static_cast<double> (d.min_inlier_spread));
  line ("-seed S", "seed of every random choice", d.seed);
  print_info (
      "  -keep_overlaps      keep instances that lie on one physical object (the "
      "paper's\n");
  print_info ("                      behaviour; by default such models are merged and "
              "such\n");
  print_info ("                      instances removed)\n");
  print_info ("  -keep_rows          do not split a cluster that links a row of copies "
              "(the\n");
  print_info ("                      paper's behaviour)\n");
  print_info ("  -keep_compounds     do not split a cluster whose point sets span two "
              "touching\n");
  print_info ("                      copies (half turns, pairs of pairs; the paper's "
              "behaviour)\n");
  print_info (
      "  -no_region_merge    do not merge models through the keypoints around their "
      "instances\n");
  print_info ("                      (the paper's behaviour)\n");
  print_info ("  -no_join_check      merge models and add detected instances without "
              "comparing\n");
  print_info ("                      the look of the copies (the paper's behaviour)\n");
  print_info ("  -no_leftovers       no second round on the keypoints outside every "
              "instance\n");
  print_info ("                      (the paper's behaviour)\n");
  print_info ("  -no_guided          no search for more instances from single matches "
              "(the\n");
  print_info ("                      paper's behaviour)\n");
  print_info (
      "  -no_patches         no models from patches of the keypoints no instance "
      "explains\n");
  print_info ("                      (the paper's behaviour)\n");
  print_info (
      "  -no_box_search      no search for more instances with each model extended by "
      "the\n");
  print_info (
      "                      keypoints inside its copies' boxes on the table (the "
      "paper's\n");
  print_info ("                      behaviour)\n");
  print_info (
      "  -split              split a model whose instances fall into groups that "
      "do not\n");
  print_info ("                      look alike (off by default, as in the paper)\n");
  print_info (
      "  -no_surface         keep the poses of the keypoints alone, not refined "
      "on the\n");
  print_info ("                      depth (the paper's behaviour)\n");
  print_info (
      "  -no_size_split      keep a model whole whose copies occupy boxes of two sizes "
      "on\n");
  print_info ("                      the table (the paper's behaviour)\n");
  print_info (
      "  -no_size_merge      keep models apart whose copies occupy boxes of one size "
      "on the\n");
  print_info ("                      table (the paper's behaviour)\n");
  print_info (
      "  -keep_outside_box   keep the observations outside the box a model's copies "
      "occupy\n");
  print_info ("                      on the table (the paper's behaviour)\n");
  print_info (
      "  -keep_repeated_prints  keep the instances of a model that lie on one object "
      "with\n");
  print_info (
      "                      another of its instances, shifted along a print that "
      "repeats\n");
  print_info ("                      on it (the paper's behaviour)\n");
  print_info (
      "  -keep_interpenetrating  keep the instances of a model whose boxes would "
      "interpenetrate\n");
  print_info ("                      (the paper's behaviour)\n");
  print_info ("  -keep_disagreeing_sizes  keep a model whose copies stand alone on the "
              "table and "
              "agree\n");
  print_info ("                      on no size (the paper's behaviour)\n");
  print_info (
      "  -keep_box_turns     keep the turn of the copies posed by their box alone "
      "when\n");
  print_info (
      "                      their print says another (the paper's behaviour)\n");
  print_info (
      "  -keep_support_prints  keep the instances that lie flat in the table's plane "
      "(prints\n");
  print_info ("                      on it, sheets of paper; the paper's behaviour)\n");
  print_info (
      "  -keep_unexplained   keep the observations an instance's pose does not explain "
      "and\n");
  print_info ("                      those amid another instance's keypoints (the "
              "paper's\n");
  print_info ("                      behaviour)\n");
  print_info (
      "  -no_size_search     do not look for copies of a model's size that show none "
      "of its\n");
  print_info (
      "                      landmarks, nor for objects of one size (the paper's "
      "behaviour)\n");
  print_info (
      "  -no_size_discovery  do not make models of objects that repeat by their size "
      "alone\n");
  print_info (
      "                      (different products of one size standing apart would be "
      "one)\n");
  print_info (
      "  -no_verification    keep every cluster, whatever the look of the surface "
      "its pose\n");
  print_info (
      "                      moves onto the other copy (the paper's behaviour)\n");
  print_info ("Peers (PCL's correspondence grouping instead of triplets + DBSCAN, for "
              "comparison):\n");
  print_info ("  -grouping G         triplets (ours, default), gcg "
              "(GeometricConsistencyGrouping) or\n");
  print_info ("                      hough (Hough3DGrouping with BOARD frames)\n");
  line ("-gc_size S", "GCG consensus resolution, metres", d.gc_size);
  line ("-gc_threshold N", "GCG smallest group", d.gc_threshold);
  line ("-hough_bin B", "Hough bin size, metres", d.hough_bin_size);
  line ("-hough_threshold T", "Hough vote threshold", d.hough_threshold);
  line ("-lrf_radius R",
        "BOARD frame radius, metres",
        static_cast<double> (d.lrf_radius));
}

/** The options of this app besides the scene and picture options, with their value counts. */
const mid::apps::OptionSpecs kOptions{{"-h", 0},
                                      {"--help", 0},
                                      {"-mutual", 0},
                                      {"-keep_overlaps", 0},
                                      {"-keep_rows", 0},
                                      {"-keep_compounds", 0},
                                      {"-no_region_merge", 0},
                                      {"-no_join_check", 0},
                                      {"-no_leftovers", 0},
                                      {"-no_verification", 0},
                                      {"-no_guided", 0},
                                      {"-no_patches", 0},
                                      {"-patch_radius", 1},
                                      {"-patch_inliers", 1},
                                      {"-patch_corr", 1},
                                      {"-max_patches", 1},
                                      {"-no_box_search", 0},
                                      {"-box_margin", 1},
                                      {"-box_hypotheses", 1},
                                      {"-split", 0},
                                      {"-no_surface", 0},
                                      {"-surface_step", 1},
                                      {"-surface_dist", 1},
                                      {"-surface_weight", 1},
                                      {"-surface_iterations", 1},
                                      {"-no_size_split", 0},
                                      {"-no_size_merge", 0},
                                      {"-size_tol", 1},
                                      {"-size_rel_tol", 1},
                                      {"-size_consensus", 1},
                                      {"-keep_outside_box", 0},
                                      {"-keep_support_prints", 0},
                                      {"-print_share", 1},
                                      {"-keep_repeated_prints", 0},
                                      {"-repeat_rot", 1},
                                      {"-repeat_shift", 1},
                                      {"-repeat_along", 1},
                                      {"-repeat_inside", 1},
                                      {"-disagree_surrounded", 1},
                                      {"-disagree_copies", 1},
                                      {"-keep_unexplained", 0},
                                      {"-keep_interpenetrating", 0},
                                      {"-keep_disagreeing_sizes", 0},
                                      {"-keep_box_turns", 0},
                                      {"-box_turn_gain", 1},
                                      {"-obs_residual", 1},
                                      {"-obs_margin", 1},
                                      {"-no_size_search", 0},
                                      {"-size_kp", 1},
                                      {"-size_agree", 1},
                                      {"-no_size_discovery", 0},
                                      {"-size_surrounded", 1},
                                      {"-size_min_edge", 1},
                                      {"-split_corr", 1},
                                      {"-guided_seed_dist", 1},
                                      {"-guided_desc_dist", 1},
                                      {"-guided_inliers", 1},
                                      {"-guided_corr", 1},
                                      {"-guided_local_corr", 1},
                                      {"-guided_disagree", 1},
                                      {"-guided_hypotheses", 1},
                                      {"-min_correlation", 1},
                                      {"-verify_radius", 1},
                                      {"-max_chroma", 1},
                                      {"-max_vivid_chroma", 1},
                                      {"-leftover_desc_dist", 1},
                                      {"-leftover_margin", 1},
                                      {"-region_margin", 1},
                                      {"-region_inliers", 1},
                                      {"-join_corr", 1},
                                      {"-json", 1},
                                      {"-models", 1},
                                      {"-max_keypoints", 1},
                                      {"-contrast", 1},
                                      {"-normal_radius", 1},
                                      {"-max_desc_dist", 1},
                                      {"-min_kp_dist", 1},
                                      {"-ratio", 1},
                                      {"-knn", 1},
                                      {"-ppf_dist", 1},
                                      {"-ppf_angle", 1},
                                      {"-min_edge", 1},
                                      {"-max_edge", 1},
                                      {"-min_angle", 1},
                                      {"-overlap", 1},
                                      {"-triplets_per_kp", 1},
                                      {"-eps", 1},
                                      {"-min_cluster", 1},
                                      {"-link_dist", 1},
                                      {"-inlier", 1},
                                      {"-min_inliers", 1},
                                      {"-merge_inliers", 1},
                                      {"-merge_fraction", 1},
                                      {"-min_ratio", 1},
                                      {"-min_spread", 1},
                                      {"-seed", 1},
                                      {"-grouping", 1},
                                      {"-gc_size", 1},
                                      {"-gc_threshold", 1},
                                      {"-hough_bin", 1},
                                      {"-hough_threshold", 1},
                                      {"-lrf_radius", 1}};

/** Read an angle option given in degrees into `radians`; false after a message if invalid. */
bool
parseDegrees (int argc, char** argv, const char* name, float& radians)
{
  float degrees = 0.0f;
  if (pcl::console::find_argument (argc, argv, name) < 0)
    return true;
  if (!mid::apps::parseNumber (argc, argv, name, degrees))
    return false;
  radians = degrees * static_cast<float> (M_PI / 180.0);
  return true;
}

/** Parse the command line; false (after a one-line error) if it is unusable. */
bool
parseOptions (int argc, char** argv, Options& options)
{
  using mid::apps::parseNumber;
  using pcl::console::parse_argument;
  mid::apps::OptionSpecs known = kOptions;
  for (const auto& more :
       {mid::apps::sceneInputOptions(), mid::apps::VisualOutputs::options()})
    known.insert (known.end(), more.begin(), more.end());
  if (!mid::apps::onlyKnownArguments (argc, argv, known, {".pcd"}) ||
      !mid::apps::parseSceneInput (argc, argv, options.scene) ||
      !options.pictures.parse (argc, argv))
    return false;
  mid::DiscoveryParameters& p = options.parameters;
  parse_argument (argc, argv, "-json", options.json_path);
  parse_argument (argc, argv, "-models", options.model_prefix);
  p.mutual_check = pcl::console::find_switch (argc, argv, "-mutual");
  p.resolve_overlaps = !pcl::console::find_switch (argc, argv, "-keep_overlaps");
  p.split_chains = !pcl::console::find_switch (argc, argv, "-keep_rows");
  p.split_compounds = !pcl::console::find_switch (argc, argv, "-keep_compounds");
  p.merge_through_regions = !pcl::console::find_switch (argc, argv, "-no_region_merge");
  p.verify_joins = !pcl::console::find_switch (argc, argv, "-no_join_check");
  p.discover_leftovers = !pcl::console::find_switch (argc, argv, "-no_leftovers");
  p.verify_clusters = !pcl::console::find_switch (argc, argv, "-no_verification");
  p.guided_search = !pcl::console::find_switch (argc, argv, "-no_guided");
  p.patch_discovery = !pcl::console::find_switch (argc, argv, "-no_patches");
  p.box_search = !pcl::console::find_switch (argc, argv, "-no_box_search");
  p.split_by_appearance = pcl::console::find_switch (argc, argv, "-split");
  p.surface_refinement = !pcl::console::find_switch (argc, argv, "-no_surface");
  p.split_by_size = !pcl::console::find_switch (argc, argv, "-no_size_split");
  p.merge_by_size = !pcl::console::find_switch (argc, argv, "-no_size_merge");
  p.prune_outside_box = !pcl::console::find_switch (argc, argv, "-keep_outside_box");
  p.remove_support_prints =
      !pcl::console::find_switch (argc, argv, "-keep_support_prints");
  p.remove_repeated_prints =
      !pcl::console::find_switch (argc, argv, "-keep_repeated_prints");
  p.prune_observations = !pcl::console::find_switch (argc, argv, "-keep_unexplained");
  p.remove_interpenetrating =
      !pcl::console::find_switch (argc, argv, "-keep_interpenetrating");
  p.remove_disagreeing_sizes =
      !pcl::console::find_switch (argc, argv, "-keep_disagreeing_sizes");
  p.resolve_box_turns = !pcl::console::find_switch (argc, argv, "-keep_box_turns");
  p.size_search = !pcl::console::find_switch (argc, argv, "-no_size_search");
  p.size_discovery = !pcl::console::find_switch (argc, argv, "-no_size_discovery");
  const bool numbers_valid =
      parseNumber (argc, argv, "-max_keypoints", p.max_keypoints) &&
      parseNumber (argc, argv, "-contrast", p.contrast_threshold) &&
      parseNumber (argc, argv, "-normal_radius", p.normal_radius) &&
      parseNumber (argc, argv, "-max_desc_dist", p.max_descriptor_distance) &&
      parseNumber (argc, argv, "-min_kp_dist", p.min_keypoint_distance) &&
      parseNumber (argc, argv, "-ratio", p.max_distance_ratio) &&
      parseNumber (argc, argv, "-knn", p.matches_per_keypoint) &&
      parseNumber (argc, argv, "-ppf_dist", p.ppf_distance) &&
      parseDegrees (argc, argv, "-ppf_angle", p.ppf_angle) &&
      parseNumber (argc, argv, "-min_edge", p.min_edge_length) &&
      parseNumber (argc, argv, "-max_edge", p.max_edge_length) &&
      parseDegrees (argc, argv, "-min_angle", p.min_triangle_angle) &&
      parseNumber (argc, argv, "-overlap", p.overlap_distance) &&
      parseNumber (argc, argv, "-triplets_per_kp", p.triplets_per_keypoint) &&
      parseNumber (argc, argv, "-eps", p.cluster_distance) &&
      parseNumber (argc, argv, "-min_cluster", p.min_cluster_size) &&
      parseNumber (argc, argv, "-link_dist", p.link_tolerance) &&
      parseNumber (argc, argv, "-inlier", p.inlier_threshold) &&
      parseNumber (argc, argv, "-min_inliers", p.min_inliers) &&
      parseNumber (argc, argv, "-merge_inliers", p.min_merge_inliers) &&
      parseNumber (argc, argv, "-merge_fraction", p.merge_fraction) &&
      parseNumber (argc, argv, "-region_margin", p.region_margin) &&
      parseNumber (argc, argv, "-region_inliers", p.min_region_merge_inliers) &&
      parseNumber (argc, argv, "-join_corr", p.min_join_correlation) &&
      parseNumber (argc, argv, "-leftover_desc_dist", p.leftover_descriptor_distance) &&
      parseNumber (argc, argv, "-leftover_margin", p.leftover_margin) &&
      parseNumber (argc, argv, "-min_ratio", p.min_inlier_ratio) &&
      parseNumber (argc, argv, "-min_spread", p.min_inlier_spread) &&
      parseNumber (argc, argv, "-min_correlation", p.min_photometric_correlation) &&
      parseNumber (argc, argv, "-verify_radius", p.verification_radius) &&
      parseNumber (argc, argv, "-max_chroma", p.max_chromaticity_difference) &&
      parseNumber (
          argc, argv, "-max_vivid_chroma", p.max_vivid_chromaticity_difference) &&
      parseNumber (argc, argv, "-guided_seed_dist", p.guided_seed_distance) &&
      parseNumber (argc, argv, "-guided_desc_dist", p.guided_descriptor_distance) &&
      parseNumber (argc, argv, "-guided_inliers", p.guided_min_inliers) &&
      parseNumber (argc, argv, "-guided_corr", p.guided_min_correlation) &&
      parseNumber (
          argc, argv, "-guided_local_corr", p.guided_neighbourhood_correlation) &&
      parseNumber (argc, argv, "-guided_disagree", p.guided_max_disagreeing) &&
      parseNumber (argc, argv, "-patch_radius", p.patch_radius) &&
      parseNumber (argc, argv, "-patch_inliers", p.patch_min_inliers) &&
      parseNumber (argc, argv, "-patch_corr", p.patch_min_correlation) &&
      parseNumber (argc, argv, "-max_patches", p.max_patches) &&
      parseNumber (argc, argv, "-guided_hypotheses", p.guided_hypotheses) &&
      parseNumber (argc, argv, "-box_margin", p.box_search_margin) &&
      parseNumber (argc, argv, "-box_hypotheses", p.box_search_hypotheses) &&
      parseNumber (argc, argv, "-split_corr", p.split_min_correlation) &&
      parseNumber (argc, argv, "-surface_step", p.surface_sample_step) &&
      parseNumber (argc, argv, "-surface_dist", p.surface_max_distance) &&
      parseNumber (argc, argv, "-surface_weight", p.surface_weight) &&
      parseNumber (argc, argv, "-surface_iterations", p.surface_iterations) &&
      parseNumber (argc, argv, "-size_tol", p.size_tolerance) &&
      parseNumber (argc, argv, "-size_rel_tol", p.relative_size_tolerance) &&
      parseNumber (argc, argv, "-size_consensus", p.size_merge_consensus_radius) &&
      parseNumber (argc, argv, "-print_share", p.support_print_min_share) &&
      parseDegrees (argc, argv, "-repeat_rot", p.repeated_print_max_rotation) &&
      parseNumber (argc, argv, "-repeat_shift", p.repeated_print_max_shift) &&
      parseNumber (argc, argv, "-repeat_along", p.repeated_print_max_shift_along) &&
      parseNumber (argc, argv, "-repeat_inside", p.repeated_print_min_inside) &&
      parseNumber (
          argc, argv, "-disagree_surrounded", p.size_disagreement_max_surrounded) &&
      parseNumber (argc, argv, "-disagree_copies", p.size_disagreement_min_copies) &&
      parseNumber (argc, argv, "-box_turn_gain", p.box_turn_min_gain) &&
      parseNumber (argc, argv, "-obs_residual", p.observation_max_residual) &&
      parseNumber (argc, argv, "-obs_margin", p.observation_box_margin) &&
      parseNumber (argc, argv, "-size_kp", p.size_search_min_keypoints) &&
      parseNumber (argc, argv, "-size_agree", p.size_search_min_agreeing) &&
      parseNumber (argc, argv, "-size_surrounded", p.size_discovery_max_surrounded) &&
      parseNumber (argc, argv, "-size_min_edge", p.size_discovery_min_edge) &&
      parseNumber (argc, argv, "-seed", p.seed) &&
      parseNumber (argc, argv, "-gc_size", p.gc_size) &&
      parseNumber (argc, argv, "-gc_threshold", p.gc_threshold) &&
      parseNumber (argc, argv, "-hough_bin", p.hough_bin_size) &&
      parseNumber (argc, argv, "-hough_threshold", p.hough_threshold) &&
      parseNumber (argc, argv, "-lrf_radius", p.lrf_radius);
  if (!numbers_valid)
    return false;
  std::string grouping = "triplets";
  parse_argument (argc, argv, "-grouping", grouping);
  if (grouping == "gcg")
    p.grouping = mid::Grouping::geometric_consistency;
  else if (grouping == "hough")
    p.grouping = mid::Grouping::hough3d;
  else if (grouping != "triplets") {
    print_error (
        "Invalid parameter: -grouping is '%s', must be triplets, gcg or hough.\n",
        grouping.c_str());
    return false;
  }
  std::string problem;
  if (!mid::validateDiscoveryParameters (p, problem)) {
    print_error ("Invalid parameter: %s.\n", problem.c_str());
    return false;
  }
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
  auto cloud = pcl::make_shared<pcl::PointCloud<PointT>>();
  if (!mid::apps::loadScene (options.scene, *cloud))
    return 1;
  const double load_ms = watch.getTime();
  mid::apps::ResultFiles outputs;
  if (!outputs.stage (options.json_path, options.model_prefix) ||
      !options.pictures.stage (outputs))
    return 1;

  mid::MultiInstanceDiscovery<PointT> discovery;
  discovery.setInputCloud (cloud);
  discovery.setParameters (options.parameters);
  mid::DiscoveryResult result;
  if (!discovery.discover (result))
    return 1;
  mid::apps::printResult (*cloud, result, load_ms);
  if (!options.pictures.write (cloud, result) ||
      !outputs.write (result, options.scene.name()))
    return 1;
  return options.pictures.show (cloud, result) ? 0 : 1;
}
