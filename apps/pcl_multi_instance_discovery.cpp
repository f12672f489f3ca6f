// pcl_multi_instance_discovery: discover objects that appear several times in ONE RGB-D frame.
// This version runs the feature stage: SIFT keypoints with valid depth and normals, and the
// self-matches between them, printing counts and the time of each step.

#include <mid/features/self_matcher.h>
#include <mid/features/sift_keypoint_extractor.h>
#include <mid/io/organized_cloud_io.h>

#include <pcl/common/time.h>
#include <pcl/console/parse.h>
#include <pcl/console/print.h>
#include <pcl/point_types.h>

#include <string>
#include <vector>

using pcl::console::print_error;
using pcl::console::print_highlight;
using pcl::console::print_info;
using pcl::console::print_value;

namespace {

using PointT = pcl::PointXYZRGBA;

/** Everything the command line sets, with the library's defaults. */
struct Options
{
  std::string pcd_path;
  std::string color_path;
  std::string depth_path;
  mid::io::CameraIntrinsics intrinsics;
  int max_keypoints = 0;
  double contrast_threshold = 0.04;
  float normal_radius = 0.015f;
  float max_descriptor_distance = 200.0f;
  float min_keypoint_distance = 0.01f;
  float max_distance_ratio = 1.0f;
  bool mutual_check = false;
};

void
printHelp (const char* program)
{
  const Options defaults;
  print_info ("Discover objects that appear several times in one RGB-D frame.\n\n");
  print_info ("Usage: %s SCENE.pcd [options]\n", program);
  print_info ("   or: %s -rgb COLOR.png -depth DEPTH.png -fx F -fy F -cx C -cy C [options]\n\n",
              program);
  print_info ("Input:\n");
  print_info ("  SCENE.pcd           organized PCD with x y z rgb(a), metres\n");
  print_info ("  -rgb FILE           color image (PNG/JPG), with -depth\n");
  print_info ("  -depth FILE         16-bit depth PNG registered to the color image\n");
  print_info ("  -fx -fy -cx -cy     pinhole intrinsics in pixels (required with -rgb)\n");
  print_info ("  -depth_scale S      metres per depth unit (default ");
  print_value ("%g", defaults.intrinsics.depth_scale);
  print_info (")\n\nFeatures:\n");
  print_info ("  -max_keypoints N    keep the N strongest keypoints, 0 = all (default ");
  print_value ("%d", defaults.max_keypoints);
  print_info (")\n  -contrast T         SIFT contrast threshold (default ");
  print_value ("%g", defaults.contrast_threshold);
  print_info (")\n  -normal_radius R    normal neighbourhood radius in metres (default ");
  print_value ("%g", static_cast<double> (defaults.normal_radius));
  print_info (")\n  -max_desc_dist D    largest SIFT descriptor distance of a match (default ");
  print_value ("%g", static_cast<double> (defaults.max_descriptor_distance));
  print_info (")\n  -min_kp_dist M      skip match candidates closer than M metres (default ");
  print_value ("%g", static_cast<double> (defaults.min_keypoint_distance));
  print_info (")\n  -ratio R            Lowe ratio test, 1 = off (default ");
  print_value ("%g", static_cast<double> (defaults.max_distance_ratio));
  print_info (")\n  -mutual             keep only mutual best matches\n");
}

/** Parse the command line; false (after a one-line error) if it is unusable. */
bool
parseOptions (int argc, char** argv, Options& options)
{
  using pcl::console::parse_argument;
  const std::vector<int> pcd_indices = pcl::console::parse_file_extension_argument (argc, argv, ".pcd");
  parse_argument (argc, argv, "-rgb", options.color_path);
  parse_argument (argc, argv, "-depth", options.depth_path);
  const bool rgbd = !options.color_path.empty () || !options.depth_path.empty ();
  if (pcd_indices.size () + (rgbd ? 1 : 0) != 1) {
    print_error ("Give exactly one input: one SCENE.pcd, or -rgb and -depth.\n");
    return false;
  }
  if (rgbd) {
    if (options.color_path.empty () || options.depth_path.empty ()) {
      print_error ("-rgb and -depth must be given together.\n");
      return false;
    }
    const bool has_intrinsics = parse_argument (argc, argv, "-fx", options.intrinsics.fx) >= 0 &&
                                parse_argument (argc, argv, "-fy", options.intrinsics.fy) >= 0 &&
                                parse_argument (argc, argv, "-cx", options.intrinsics.cx) >= 0 &&
                                parse_argument (argc, argv, "-cy", options.intrinsics.cy) >= 0;
    if (!has_intrinsics) {
      print_error ("-rgb/-depth input needs the intrinsics -fx -fy -cx -cy.\n");
      return false;
    }
    parse_argument (argc, argv, "-depth_scale", options.intrinsics.depth_scale);
  }
  else
    options.pcd_path = argv[pcd_indices.front ()];

  parse_argument (argc, argv, "-max_keypoints", options.max_keypoints);
  parse_argument (argc, argv, "-contrast", options.contrast_threshold);
  parse_argument (argc, argv, "-normal_radius", options.normal_radius);
  parse_argument (argc, argv, "-max_desc_dist", options.max_descriptor_distance);
  parse_argument (argc, argv, "-min_kp_dist", options.min_keypoint_distance);
  parse_argument (argc, argv, "-ratio", options.max_distance_ratio);
  options.mutual_check = pcl::console::find_switch (argc, argv, "-mutual");
  return true;
}

bool
loadScene (const Options& options, pcl::PointCloud<PointT>& cloud)
{
  if (!options.pcd_path.empty ())
    return mid::io::loadOrganizedPCD (options.pcd_path, cloud);
  return mid::io::loadRGBD (options.color_path, options.depth_path, options.intrinsics, cloud);
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

  pcl::StopWatch total;
  pcl::StopWatch step;
  auto cloud = pcl::make_shared<pcl::PointCloud<PointT>> ();
  if (!loadScene (options, *cloud))
    return 1;
  const double load_ms = step.getTime ();

  step.reset ();
  mid::SIFTKeypointExtractor<PointT> extractor;
  extractor.setInputCloud (cloud);
  extractor.setMaxKeypoints (options.max_keypoints);
  extractor.setContrastThreshold (options.contrast_threshold);
  extractor.setNormalRadius (options.normal_radius);
  auto keypoints = pcl::make_shared<mid::KeypointCloud> ();
  auto descriptors = pcl::make_shared<mid::SIFTDescriptorCloud> ();
  if (!extractor.compute (*keypoints, *descriptors))
    return 1;
  const double features_ms = step.getTime ();

  step.reset ();
  mid::SelfMatcher matcher;
  matcher.setInputKeypoints (keypoints);
  matcher.setInputDescriptors (descriptors);
  matcher.setMaxDescriptorDistance (options.max_descriptor_distance);
  matcher.setMinKeypointDistance (options.min_keypoint_distance);
  matcher.setMaxDistanceRatio (options.max_distance_ratio);
  matcher.setMutualCheck (options.mutual_check);
  pcl::Correspondences matches;
  if (!matcher.match (matches))
    return 1;
  const double matching_ms = step.getTime ();

  print_highlight ("Scene: ");
  print_value ("%u x %u", cloud->width, cloud->height);
  print_info (" points\n");
  print_info ("keypoints: ");
  print_value ("%zu", keypoints->size ());
  print_info (" (valid depth and normal)\nmatches:   ");
  print_value ("%zu", matches.size ());
  print_info ("\ntiming_ms: load ");
  print_value ("%.1f", load_ms);
  print_info (", features ");
  print_value ("%.1f", features_ms);
  print_info (", matching ");
  print_value ("%.1f", matching_ms);
  print_info (", total ");
  print_value ("%.1f", total.getTime ());
  print_info ("\n");
  return 0;
}
