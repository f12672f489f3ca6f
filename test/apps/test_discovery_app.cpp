// pcl_multi_instance_discovery on good and bad input: a clear one-line error and a non-zero exit
// for every unusable input, never a crash, hang or partial output; an empty result for a valid
// scene that holds nothing; counts for a scene with a known repeated pattern.
//
// The bad-input matrix (doc/quality_gates.md): missing, empty and garbage files, a truncated
// binary PCD, every PCD and image the fuzzers crashed on, an unorganized cloud, a cloud without
// color, all-NaN depth, an all-zero depth image, a 1x1 image pair, an 8-bit depth image, a
// color file that is neither PNG nor JPEG, depth in millimetres where metres are expected (PCD,
// and PNG with a wrong depth scale), negative or zero parameters and intrinsics, a textureless
// scene (valid, no keypoints: exit 0 and empty counts). Output files: test_discovery_app_json.cpp
// and test_discovery_app_pictures.cpp.

#include "app_runner.h"
#include "temporary_folder.h"
#include "two_copies_scene.h"

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <pcl/io/pcd_io.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>

namespace {

namespace fs = std::filesystem;

/** An RGB-D pair of the two-copies scene: 8-bit BGR and 16-bit depth in millimetres. */
void
makeImages (cv::Mat& color, cv::Mat& depth)
{
  const auto scene = mid::test::makeTwoCopiesScene();
  color.create (480, 640, CV_8UC3);
  depth.create (480, 640, CV_16UC1);
  for (int v = 0; v < 480; ++v)
    for (int u = 0; u < 640; ++u) {
      const auto& p = scene.cloud->at (u, v);
      color.at<cv::Vec3b> (v, u) = cv::Vec3b (p.b, p.g, p.r);
      depth.at<std::uint16_t> (v, u) =
          static_cast<std::uint16_t> (std::lround (p.z * 1000.0f));
    }
}

const std::string kIntrinsics = " -fx 525 -fy 525 -cx 319.5 -cy 239.5";

class DiscoveryApp : public ::testing::Test
{
protected:
  std::string
  path (const std::string& name) const
  {
    return folder_.file (name);
  }

  /** The arguments of an RGB-D pair written as PNG files into the test folder. */
  std::string
  writePair (const cv::Mat& color,
             const cv::Mat& depth,
             const std::string& name = "pair") const
  {
    EXPECT_TRUE (cv::imwrite (path (name + "_rgb.png"), color));
    EXPECT_TRUE (cv::imwrite (path (name + "_depth.png"), depth));
    return "-rgb " + path (name + "_rgb.png") + " -depth " + path (name + "_depth.png");
  }

  static mid::test::RunResult
  run (const std::string& arguments)
  {
    return mid::test::runCommand (std::string (MID_DISCOVERY_APP) + " " + arguments);
  }

  /** The app must refuse the input: non-zero exit, no crash, one error line naming it. */
  static void
  expectRefused (const std::string& arguments, const std::string& message)
  {
    const auto result = run (arguments);
    EXPECT_FALSE (result.crashed) << result.output;
    EXPECT_NE (result.exit_code, 0) << result.output;
    EXPECT_NE (result.output.find (message), std::string::npos)
        << "expected '" << message << "' in:\n"
        << result.output;
    EXPECT_EQ (std::count (result.output.begin(), result.output.end(), '\n'), 1)
        << result.output;
  }

  mid::test::TemporaryFolder folder_;
};

} // namespace

TEST_F (DiscoveryApp, CountsKeypointsAndMatchesOfARepeatedPattern)
{
  const auto scene = mid::test::makeTwoCopiesScene();
  ASSERT_EQ (pcl::io::savePCDFileBinaryCompressed (path ("scene.pcd"), *scene.cloud),
             0);
  const auto result = run (path ("scene.pcd"));
  ASSERT_EQ (result.exit_code, 0) << result.output;
  std::smatch keypoints, matches;
  ASSERT_TRUE (
      std::regex_search (result.output, keypoints, std::regex ("keypoints: (\\d+)")));
  ASSERT_TRUE (
      std::regex_search (result.output, matches, std::regex ("matches: +(\\d+)")));
  // Two copies of one texture: nearly every keypoint finds its twin.
  EXPECT_GT (std::stoi (keypoints[1]), 100);
  EXPECT_GT (std::stoi (matches[1]), std::stoi (keypoints[1]) * 7 / 10);
  EXPECT_NE (result.output.find ("timing_ms"), std::string::npos);
}

TEST_F (DiscoveryApp, ReadsColorAndDepthPngsWithIntrinsics)
{
  cv::Mat color, depth;
  makeImages (color, depth);
  ASSERT_TRUE (cv::imwrite (path ("rgb.png"), color));
  ASSERT_TRUE (cv::imwrite (path ("depth.png"), depth));
  const auto result = run ("-rgb " + path ("rgb.png") + " -depth " +
                           path ("depth.png") + " -fx 525 -fy 525 -cx 319.5 -cy 239.5");
  ASSERT_EQ (result.exit_code, 0) << result.output;
  EXPECT_NE (result.output.find ("640 x 480"), std::string::npos) << result.output;

  cv::imwrite (path ("small_depth.png"), cv::Mat (depth, cv::Rect (0, 0, 320, 240)));
  expectRefused ("-rgb " + path ("rgb.png") + " -depth " + path ("small_depth.png") +
                     " -fx 525 -fy 525 -cx 319.5 -cy 239.5",
                 "sizes differ");
  expectRefused ("-rgb " + path ("rgb.png") + " -depth " + path ("depth.png"),
                 "intrinsics");
  expectRefused ("-rgb " + path ("rgb.png") + " -depth " + path ("depth.png") +
                     " -fx 0 -fy 525 -cx 319.5 -cy 239.5",
                 "focal");
}

TEST_F (DiscoveryApp, RefusesUnusableFiles)
{
  expectRefused (path ("missing.pcd"), "cannot open");
  std::ofstream (path ("empty.pcd")).flush();
  expectRefused (path ("empty.pcd"), "is empty");
  std::ofstream (path ("garbage.pcd")) << "garbage\n";
  expectRefused (path ("garbage.pcd"), "not a valid PCD");

  auto cloud = mid::test::makeTwoCopiesScene().cloud;
  pcl::PointCloud<pcl::PointXYZ> xyz;
  pcl::copyPointCloud (*cloud, xyz);
  ASSERT_EQ (pcl::io::savePCDFileBinary (path ("xyz.pcd"), xyz), 0);
  expectRefused (path ("xyz.pcd"), "no color field");

  cloud->width = static_cast<std::uint32_t> (cloud->size());
  cloud->height = 1;
  ASSERT_EQ (pcl::io::savePCDFileBinary (path ("flat.pcd"), *cloud), 0);
  expectRefused (path ("flat.pcd"), "not organized");

  cloud->width = 640;
  cloud->height = 480;
  for (auto& p : *cloud)
    p.z = std::numeric_limits<float>::quiet_NaN();
  ASSERT_EQ (pcl::io::savePCDFileBinary (path ("nan.pcd"), *cloud), 0);
  expectRefused (path ("nan.pcd"), "no valid depth");
}

TEST_F (DiscoveryApp, RefusesBadArguments)
{
  expectRefused ("a.pcd b.pcd", "exactly one input");
  expectRefused ("-rgb x.png", "together");
  const auto scene = mid::test::makeTwoCopiesScene();
  ASSERT_EQ (pcl::io::savePCDFileBinaryCompressed (path ("scene.pcd"), *scene.cloud),
             0);
  expectRefused (path ("scene.pcd") + " -max_desc_dist -5", "Invalid parameter");
  expectRefused (path ("scene.pcd") + " -normal_radius 0", "Invalid parameter");
  const auto usage = run ("");
  EXPECT_NE (usage.exit_code, 0);
  EXPECT_NE (usage.output.find ("Usage"), std::string::npos);
}

TEST_F (DiscoveryApp, RefusesUnknownArgumentsAndMalformedNumbers)
{
  const auto scene = mid::test::makeTwoCopiesScene();
  ASSERT_EQ (pcl::io::savePCDFileBinaryCompressed (path ("scene.pcd"), *scene.cloud),
             0);
  const std::string pcd = path ("scene.pcd");
  // A misspelt option or a stray file would otherwise be ignored, and run with the defaults.
  expectRefused (pcd + " -merge_fractoin 0.5", "Unknown argument '-merge_fractoin'");
  expectRefused (pcd + " notes.txt", "Unknown argument 'notes.txt'");
  expectRefused (pcd + " -json", "-json needs 1 value");
  expectRefused (pcd + " -size 640", "-size needs 2 values");
  // pcl::console::parse_argument reads these as 0 or as their leading digits.
  expectRefused (pcd + " -merge_fraction abc",
                 "-merge_fraction must be a number, got 'abc'");
  expectRefused (pcd + " -contrast 0.04x", "-contrast must be a number");
  expectRefused (pcd + " -ppf_angle nan", "-ppf_angle must be a number");
  expectRefused (pcd + " -seed 1.5", "-seed must be an integer");
  expectRefused (pcd + " -seed -1", "-seed must be an integer in [0, 4294967295]");
  expectRefused (pcd + " -min_cluster -3", "-min_cluster must be an integer");
  expectRefused (pcd + " -min_inliers -1", "-min_inliers must be an integer");
  cv::Mat color, depth;
  makeImages (color, depth);
  expectRefused (writePair (color, depth) + " -fx 525px -fy 525 -cx 319.5 -cy 239.5",
                 "-fx must be a number, got '525px'");
  // Still a scene: an upper-case name, after a switch.
  fs::copy_file (pcd, path ("SCENE.PCD"));
  const auto upper = run ("-keep_rows " + path ("SCENE.PCD"));
  EXPECT_EQ (upper.exit_code, 0) << upper.output;
}

TEST_F (DiscoveryApp, RefusesATruncatedBinaryPcd)
{
  const auto scene = mid::test::makeTwoCopiesScene();
  ASSERT_EQ (pcl::io::savePCDFileBinary (path ("full.pcd"), *scene.cloud), 0);
  fs::copy_file (path ("full.pcd"), path ("cut.pcd"));
  fs::resize_file (path ("cut.pcd"), fs::file_size (path ("full.pcd")) / 2);
  expectRefused (path ("cut.pcd"), "truncated or corrupt");
}

TEST_F (DiscoveryApp, RefusesEveryPcdTheFuzzerCrashedOn)
{
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator (MID_FUZZ_REGRESSIONS_DIR "/pcd")) {
    const std::string copy = path ("regression_" + std::to_string (files++) + ".pcd");
    fs::copy_file (entry.path(), copy);
    SCOPED_TRACE (entry.path().filename().string());
    expectRefused (copy, "[mid::io::loadOrganizedPCD]");
  }
  EXPECT_GT (files, 0u);
}

TEST_F (DiscoveryApp, RefusesImagesThatAreNotAUsableRgbdPair)
{
  cv::Mat color, depth;
  makeImages (color, depth);
  // A file named .png that OpenCV would hand to its DICOM decoder (which asserts on it).
  fs::copy_file (MID_FUZZ_REGRESSIONS_DIR "/rgbd/dicom_signature_gdcm_assert.bin",
                 path ("x.png"));
  writePair (color, depth);
  expectRefused ("-rgb " + path ("x.png") + " -depth " + path ("pair_depth.png") +
                     kIntrinsics,
                 "is not a PNG or JPEG image");
  expectRefused ("-rgb " + path ("pair_rgb.png") + " -depth " + path ("x.png") +
                     kIntrinsics,
                 "is not a PNG image");
  // A color image as depth: not 16-bit.
  expectRefused ("-rgb " + path ("pair_rgb.png") + " -depth " + path ("pair_rgb.png") +
                     kIntrinsics,
                 "16-bit");
  expectRefused ("-rgb " + path ("missing.png") + " -depth " + path ("pair_depth.png") +
                     kIntrinsics,
                 "cannot open");
  // A 1x1 pair, and a pair whose depth is all zero (no measurement anywhere).
  expectRefused (writePair (cv::Mat (1, 1, CV_8UC3, cv::Scalar (1, 2, 3)),
                            cv::Mat (1, 1, CV_16UC1, cv::Scalar (1000)),
                            "tiny") +
                     kIntrinsics,
                 "too small");
  expectRefused (writePair (color, cv::Mat::zeros (depth.size(), CV_16UC1), "zero") +
                     kIntrinsics,
                 "no valid depth");
}

TEST_F (DiscoveryApp, RefusesDepthInMillimetresWhereMetresAreExpected)
{
  auto cloud = mid::test::makeTwoCopiesScene().cloud;
  for (auto& p : *cloud)
    p.getVector3fMap() *= 1000.0f;
  ASSERT_EQ (pcl::io::savePCDFileBinaryCompressed (path ("mm.pcd"), *cloud), 0);
  expectRefused (path ("mm.pcd"), "millimetres");
  // Millimetre PNGs read with a depth scale of 1 (metres per unit) instead of 0.001.
  cv::Mat color, depth;
  makeImages (color, depth);
  expectRefused (writePair (color, depth) + kIntrinsics + " -depth_scale 1",
                 "millimetres");
}

TEST_F (DiscoveryApp, RefusesNegativeOrZeroParameters)
{
  const auto scene = mid::test::makeTwoCopiesScene();
  ASSERT_EQ (pcl::io::savePCDFileBinaryCompressed (path ("scene.pcd"), *scene.cloud),
             0);
  for (const char* option : {"-max_keypoints -1",
                             "-contrast 0",
                             "-contrast -0.1",
                             "-normal_radius -0.01",
                             "-max_desc_dist 0",
                             "-min_kp_dist -1",
                             "-ratio 0",
                             "-ratio 1.5",
                             "-ppf_dist -1",
                             "-min_edge 0",
                             "-max_edge -1",
                             "-triplets_per_kp 0",
                             "-eps 0",
                             "-eps -1",
                             "-min_cluster 0",
                             "-inlier 0",
                             "-merge_inliers 2",
                             "-merge_fraction 1.5",
                             "-merge_fraction -0.1",
                             "-region_margin -0.01",
                             "-region_inliers 2",
                             "-leftover_desc_dist 0",
                             "-leftover_margin -0.01",
                             "-min_ratio -0.5",
                             "-min_spread -0.001",
                             "-disagree_surrounded 1.5",
                             "-disagree_copies 1",
                             "-box_turn_gain 2.5",
                             "-print_share 0",
                             "-print_share 1.5"}) {
    SCOPED_TRACE (option);
    expectRefused (path ("scene.pcd") + " " + option, "Invalid parameter");
  }
  cv::Mat color, depth;
  makeImages (color, depth);
  const std::string pair = writePair (color, depth);
  expectRefused (pair + kIntrinsics + " -depth_scale 0",
                 "depth scale must be positive");
  expectRefused (pair + kIntrinsics + " -depth_scale -0.001",
                 "depth scale must be positive");
  expectRefused (pair + " -fx -525 -fy 525 -cx 319.5 -cy 239.5", "focal lengths");
  expectRefused (pair + " -fx 525 -fy 0 -cx 319.5 -cy 239.5", "focal lengths");
}

TEST_F (DiscoveryApp, ATexturelessSceneIsValidAndHoldsNothing)
{
  // A flat, evenly lit wall 1 m away: a valid frame in which SIFT finds no keypoint.
  pcl::PointCloud<pcl::PointXYZRGB> wall (640, 480);
  for (int v = 0; v < 480; ++v)
    for (int u = 0; u < 640; ++u) {
      auto& p = wall.at (u, v);
      p.x = static_cast<float> ((u - 319.5) / 525.0);
      p.y = static_cast<float> ((v - 239.5) / 525.0);
      p.z = 1.0f;
      p.r = p.g = p.b = 128;
    }
  ASSERT_EQ (pcl::io::savePCDFileBinaryCompressed (path ("wall.pcd"), wall), 0);
  const auto result = run (path ("wall.pcd") + " -json " + path ("wall.json"));
  EXPECT_FALSE (result.crashed) << result.output;
  ASSERT_EQ (result.exit_code, 0) << result.output;
  EXPECT_NE (result.output.find ("keypoints: 0"), std::string::npos) << result.output;
  EXPECT_TRUE (std::regex_search (result.output, std::regex ("matches: +0\\b")))
      << result.output;
  EXPECT_TRUE (std::regex_search (result.output, std::regex ("objects: +0\\b")))
      << result.output;
  EXPECT_TRUE (fs::exists (path ("wall.json"))) << "the empty result is written too";
}
