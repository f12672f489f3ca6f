#include "rendered_keypoints.h"

#include <mid/segmentation/frame_pinhole.h>
#include <mid/segmentation/photometric_verification.h>

#include <gtest/gtest.h>
#include <pcl/common/io.h>
#include <pcl/common/point_tests.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>

namespace {

using mid::test::boxPose;
using mid::test::BoxSpec;

const char* const kApple = mid::test::kApplePrint;
const char* const kSoy = mid::test::kSoyPrint;

/** Three boxes of one size in front of a table: copies 0 and 1 of one print, box 2 of another
  * print, each turned its own way.
  */
mid::test::RenderedObjectsScene
threeBoxes ()
{
  return mid::test::renderBoxes (
      {{kApple, {0.12, 0.09, 0.04}, boxPose (-0.12, -0.06, 0.8, 15.0)},
       {kApple, {0.12, 0.09, 0.04}, boxPose (0.1, -0.05, 0.85, 200.0, 20.0)},
       {kSoy, {0.12, 0.09, 0.04}, boxPose (0.0, 0.1, 0.82, -40.0)}},
      0.95);
}

/** The frame as XYZ points. */
pcl::PointCloud<pcl::PointXYZ>::Ptr
pointsOf (const mid::test::RenderedObjectsScene& scene)
{
  auto points = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  pcl::copyPointCloud (*scene.cloud, *points);
  return points;
}

/** The pixel of a camera-frame point in the scene's camera. */
pcl::index_t
pixelOf (const mid::test::RenderedObjectsScene& scene, const Eigen::Vector3d& point)
{
  const auto& camera = scene.frame.camera;
  const auto u = static_cast<int> (
                 std::lround (camera.fx * point.x() / point.z() + camera.cx)),
             v = static_cast<int> (
                 std::lround (camera.fy * point.y() / point.z() + camera.cy));
  return v * camera.width + u;
}

/** The printed face's keypoints: a 4 x 3 grid of points of the box model, seen on each box in
  * turn (keypoint 12 b + i is grid point i on box b); and the cluster from box `from` to box
  * `to` that the boxes' poses give.
  */
struct PrintedFaces
{
  mid::KeypointSurface surface;
  std::vector<Eigen::Isometry3d> poses;

  explicit PrintedFaces (const mid::test::RenderedObjectsScene& scene)
  {
    surface.organized = pointsOf (scene);
    pcl::PointCloud<pcl::PointXYZRGB> colour;
    pcl::copyPointCloud (*scene.cloud, colour);
    surface.intensity =
        std::make_shared<const std::vector<float>> (mid::greyLevels (colour));
    for (const auto& box : scene.boxes) {
      poses.push_back (box.pose);
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 3; ++j)
          surface.keypoint_pixels.push_back (pixelOf (
              scene,
              box.pose * Eigen::Vector3d (-0.045 + 0.03 * i, -0.03 + 0.03 * j, -0.02)));
    }
  }

  mid::TripletCluster
  cluster (int from, int to) const
  {
    mid::TripletCluster c;
    for (int i = 0; i < 12; ++i) {
      c.source_indices.push_back (12 * from + i);
      c.target_indices.push_back (12 * to + i);
      c.correspondences.emplace_back (12 * from + i, 12 * to + i, 0.0f);
    }
    c.transformation = (poses[static_cast<std::size_t> (to)] *
                        poses[static_cast<std::size_t> (from)].inverse())
                           .matrix()
                           .cast<float>();
    return c;
  }
};

} // namespace

TEST (FramePinhole, RecoversTheCameraOfAnOrganizedFrame)
{
  const auto scene = threeBoxes();
  const auto points = pointsOf (scene);
  mid::FramePinhole pinhole;
  ASSERT_TRUE (mid::fitFramePinhole (*points, pinhole));
  const auto& camera = scene.frame.camera;
  EXPECT_NEAR (pinhole.fx, camera.fx, 1e-3 * camera.fx);
  EXPECT_NEAR (pinhole.fy, camera.fy, 1e-3 * camera.fy);
  EXPECT_NEAR (pinhole.cx, camera.cx, 0.05);
  EXPECT_NEAR (pinhole.cy, camera.cy, 0.05);

  // Turned by a half turn about x (z < 0, as PCL's milk scene): every point still projects
  // onto its own pixel.
  auto turned = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>> (*points);
  for (auto& p : *turned) {
    p.y = -p.y;
    p.z = -p.z;
  }
  ASSERT_TRUE (mid::fitFramePinhole (*turned, pinhole));
  EXPECT_LT (pinhole.fx, 0.0);
  std::size_t checked = 0;
  for (int v = 0; v < camera.height; v += 7)
    for (int u = 0; u < camera.width; u += 7) {
      const auto& p =
          (*turned) (static_cast<std::size_t> (u), static_cast<std::size_t> (v));
      if (!pcl::isXYZFinite (p))
        continue;
      int pu = -1, pv = -1;
      ASSERT_TRUE (
          pinhole.project (p.getVector3fMap(), camera.width, camera.height, pu, pv));
      EXPECT_EQ (pu, u);
      EXPECT_EQ (pv, v);
      ++checked;
    }
  EXPECT_GT (checked, 1000u);
}

TEST (FramePinhole, RefusesFramesNoPinholeCameraMade)
{
  const auto points = pointsOf (threeBoxes());
  mid::FramePinhole pinhole;
  // The same points, shuffled over the pixels.
  auto shuffled = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>> (*points);
  std::mt19937 random (7);
  std::shuffle (shuffled->begin(), shuffled->end(), random);
  EXPECT_FALSE (mid::fitFramePinhole (*shuffled, pinhole));
  EXPECT_EQ (pinhole.fx, 0.0);
  // Not organized.
  pcl::PointCloud<pcl::PointXYZ> unorganized (*points);
  unorganized.height = 1;
  unorganized.width = static_cast<std::uint32_t> (unorganized.size());
  EXPECT_FALSE (mid::fitFramePinhole (unorganized, pinhole));
  // No valid point.
  pcl::PointCloud<pcl::PointXYZ> empty (640, 480, pcl::PointXYZ (NAN, NAN, NAN));
  EXPECT_FALSE (mid::fitFramePinhole (empty, pinhole));
}

TEST (PhotometricVerification, KeepsTheTruePoseAndRejectsAPoseOntoAnotherPrint)
{
  const auto scene = threeBoxes();
  const PrintedFaces faces (scene);
  mid::PhotometricVerification verification;
  verification.setKeypointSurface (faces.surface);

  // Copies 0 and 1: the same print under their true relative pose. Box 2 has the same shape,
  // so the pose onto it is as consistent geometrically, but its print differs.
  const mid::TripletCluster copies = faces.cluster (0, 1), other = faces.cluster (0, 2);
  bool tested = false;
  EXPECT_GT (verification.correlation (copies, tested), 0.8);
  EXPECT_TRUE (tested);
  EXPECT_LT (verification.correlation (other, tested), 0.4);
  EXPECT_TRUE (tested);

  mid::TripletClusters verified;
  ASSERT_TRUE (verification.filter ({other, copies, faces.cluster (2, 0)}, verified));
  ASSERT_EQ (verified.size(), 1u);
  EXPECT_EQ (verified.front().target_indices, copies.target_indices);

  // Without a minimum, every cluster stays.
  verification.setMinCorrelation (-1.0f);
  ASSERT_TRUE (verification.filter ({other, copies}, verified));
  EXPECT_EQ (verified.size(), 2u);
}

TEST (PhotometricVerification, WorksInAFrameThatLooksDownMinusZ)
{
  // The same frame turned by a half turn about x (PCL's milk scene is stored so): the poses
  // turn with it, the pixels stay.
  const auto scene = threeBoxes();
  PrintedFaces faces (scene);
  auto turned =
      pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>> (*faces.surface.organized);
  for (auto& p : *turned) {
    p.y = -p.y;
    p.z = -p.z;
  }
  faces.surface.organized = turned;
  const Eigen::Isometry3d half_turn (
      Eigen::AngleAxisd (M_PI, Eigen::Vector3d::UnitX()));
  for (auto& pose : faces.poses)
    pose = half_turn * pose;
  mid::PhotometricVerification verification;
  verification.setKeypointSurface (faces.surface);
  ASSERT_TRUE (verification.hasProjection());
  mid::TripletClusters verified;
  ASSERT_TRUE (
      verification.filter ({faces.cluster (0, 2), faces.cluster (0, 1)}, verified));
  ASSERT_EQ (verified.size(), 1u);
  EXPECT_EQ (verified.front().target_indices, faces.cluster (0, 1).target_indices);
}

TEST (PhotometricVerification, UsesTheProjectionTheKeypointSurfaceHolds)
{
  const auto scene = threeBoxes();
  PrintedFaces faces (scene);
  const auto& camera = scene.frame.camera;
  const mid::FramePinhole exact{camera.fx, camera.fy, camera.cx, camera.cy};
  faces.surface.pinhole = std::make_shared<const mid::FramePinhole> (exact);
  mid::PhotometricVerification verification;
  verification.setKeypointSurface (faces.surface);
  ASSERT_TRUE (verification.hasProjection());
  bool tested = false;
  EXPECT_GT (verification.correlation (faces.cluster (0, 1), tested), 0.8);
  EXPECT_TRUE (tested);

  // A principal point 25 pixels off (the wrong camera): every moved point is looked up 25
  // pixels beside its true pixel, so even the true pose between the copies fails. A fit of
  // the frame would have kept it.
  mid::FramePinhole shifted = exact;
  shifted.cx += 25.0;
  faces.surface.pinhole = std::make_shared<const mid::FramePinhole> (shifted);
  verification.setKeypointSurface (faces.surface);
  EXPECT_LT (verification.correlation (faces.cluster (0, 1), tested), 0.4);
  mid::TripletClusters verified;
  ASSERT_TRUE (verification.filter ({faces.cluster (0, 1)}, verified));
  EXPECT_TRUE (verified.empty());
}

TEST (PhotometricVerification, NeverPairsAPointMovedBehindTheCamera)
{
  // A half turn about the camera's x axis puts every point behind the camera, where the
  // projection sees it in the mirrored column: there, box 1 lies exactly as far from the
  // camera as box 0. That is no evidence.
  const PrintedFaces faces (mid::test::renderBoxes (
      {{kApple, {0.12, 0.09, 0.04}, boxPose (-0.1, 0.0, 0.8, 0.0)},
       {kApple, {0.12, 0.09, 0.04}, boxPose (0.1, 0.0, 0.8, 0.0)}},
      0.95));
  mid::TripletCluster behind = faces.cluster (0, 1);
  behind.transformation = Eigen::Affine3f (Eigen::AngleAxisf (static_cast<float> (M_PI),
                                                              Eigen::Vector3f::UnitX()))
                              .matrix();
  mid::PhotometricVerification verification;
  verification.setKeypointSurface (faces.surface);
  verification.setMinPairs (1);
  bool tested = true;
  EXPECT_EQ (verification.correlation (behind, tested), 0.0);
  EXPECT_FALSE (tested);
}

TEST (PhotometricVerification, KeepsWhatAUniformSurfaceOrTooFewPairsCannotTell)
{
  const PrintedFaces faces (threeBoxes());
  const mid::TripletClusters other{faces.cluster (0, 2)};
  mid::TripletClusters verified;
  // A frame without contrast (all one grey level): the pose onto the other print stays.
  mid::KeypointSurface flat = faces.surface;
  flat.intensity = std::make_shared<const std::vector<float>> (
      faces.surface.intensity->size(), 128.0f);
  mid::PhotometricVerification verification;
  verification.setKeypointSurface (flat);
  ASSERT_TRUE (verification.filter (other, verified));
  EXPECT_EQ (verified.size(), 1u);
  // Asking for more pairs than the keypoints' surroundings hold: untested, kept.
  verification.setKeypointSurface (faces.surface);
  ASSERT_TRUE (verification.filter (other, verified));
  EXPECT_TRUE (verified.empty());
  verification.setMinPairs (100000);
  ASSERT_TRUE (verification.filter (other, verified));
  EXPECT_EQ (verified.size(), 1u);
}

TEST (PhotometricVerification, GreyLevelsWeighTheChannelsLikeTheEye)
{
  pcl::PointCloud<pcl::PointXYZRGB> frame (3, 1);
  frame[0].r = 255;
  frame[1].g = 255;
  frame[2].r = frame[2].g = frame[2].b = 100;
  const std::vector<float> grey = mid::greyLevels (frame);
  ASSERT_EQ (grey.size(), 3u);
  EXPECT_NEAR (grey[0], 0.299f * 255.0f, 1e-3f);
  EXPECT_NEAR (grey[1], 0.587f * 255.0f, 1e-3f);
  EXPECT_NEAR (grey[2], 100.0f, 1e-3f);
}

TEST (PhotometricVerification, ChromaticityIsTheShareOfRedAndGreenWhereBrightEnough)
{
  pcl::PointCloud<pcl::PointXYZRGB> frame (3, 1);
  frame[0].r = 200;
  frame[0].g = frame[0].b = 100;
  frame[1].r = frame[1].g = frame[1].b = 19; // 57 < 60: too dark
  frame[2].g = 255;
  const std::vector<mid::Chromaticity> shares = mid::chromaticities (frame);
  ASSERT_EQ (shares.size(), 3u);
  EXPECT_NEAR (shares[0][0], 0.5f, 1e-6f);
  EXPECT_NEAR (shares[0][1], 0.25f, 1e-6f);
  EXPECT_TRUE (std::isnan (shares[1][0]) && std::isnan (shares[1][1]));
  EXPECT_NEAR (shares[2][0], 0.0f, 1e-6f);
  EXPECT_NEAR (shares[2][1], 1.0f, 1e-6f);
  EXPECT_FALSE (std::isnan (mid::chromaticities (frame, 50.0f)[1][0]));
}

TEST (PhotometricVerification, RejectsTheSamePrintInOtherColours)
{
  // Box 1 carries box 0's print with the same grey levels but tinted (blue up, red down):
  // grey levels alone take it for a copy, its colours do not.
  const auto scene = threeBoxes();
  PrintedFaces faces (scene);
  pcl::PointCloud<pcl::PointXYZRGB> colour, tinted;
  pcl::copyPointCloud (*scene.cloud, colour);
  tinted = colour;
  const std::size_t recoloured = mid::test::tintKeepingGreyLevels (scene, 1, tinted);
  ASSERT_GT (recoloured, 1000u);
  const mid::TripletCluster copies = faces.cluster (0, 1);
  mid::PhotometricVerification verification;

  faces.surface.chromaticity = std::make_shared<const std::vector<mid::Chromaticity>> (
      mid::chromaticities (colour));
  verification.setKeypointSurface (faces.surface);
  const auto same = verification.compare (copies);
  ASSERT_TRUE (same.correlation_tested && same.chromaticity_tested);
  EXPECT_GT (same.correlation, 0.8);
  EXPECT_LT (same.chromaticity_difference, 0.03);
  EXPECT_FALSE (verification.rejects (same));

  faces.surface.chromaticity = std::make_shared<const std::vector<mid::Chromaticity>> (
      mid::chromaticities (tinted));
  verification.setKeypointSurface (faces.surface);
  const auto other = verification.compare (copies);
  ASSERT_TRUE (other.correlation_tested && other.chromaticity_tested);
  EXPECT_NEAR (
      other.correlation, same.correlation, 1e-9); // the grey levels are the same
  EXPECT_GT (other.chromaticity_difference, 0.1);
  EXPECT_TRUE (verification.rejects (other));
  mid::TripletClusters verified;
  ASSERT_TRUE (verification.filter ({copies}, verified));
  EXPECT_TRUE (verified.empty());

  // Colours off (2 or more, all of them and the vivid ones), or a frame without them: the
  // grey levels decide alone.
  verification.setMaxChromaticityDifference (2.0f);
  verification.setMaxVividChromaticityDifference (2.0f);
  ASSERT_TRUE (verification.filter ({copies}, verified));
  EXPECT_EQ (verified.size(), 1u);
  verification.setMaxChromaticityDifference (0.1f);
  verification.setMaxVividChromaticityDifference (0.15f);
  faces.surface.chromaticity = nullptr;
  verification.setKeypointSurface (faces.surface);
  EXPECT_FALSE (verification.compare (copies).chromaticity_tested);
  ASSERT_TRUE (verification.filter ({copies}, verified));
  EXPECT_EQ (verified.size(), 1u);
}

TEST (PhotometricVerification, RejectsTheSameLayoutInAnotherInkByTheVividColours)
{
  // Boxes 0 and 1 carry one print; box 0's ink is repainted dark green, box 1's dark green
  // (a copy) or dark blue (another product of the brand), on grey paper. The grey levels are
  // the same either way, and the mean of all colours hardly differs: the paper dominates it.
  // The vivid colours, the inks, tell the products apart.
  const auto scene = threeBoxes();
  PrintedFaces faces (scene);
  const mid::TripletCluster copies = faces.cluster (0, 1);
  const Eigen::Vector3f green (0.5f, 1.0f, 0.6f), blue (0.3f, 0.5f, 1.0f);
  const auto compareInks = [&] (const Eigen::Vector3f& ink,
                                const mid::PhotometricVerification& verification) {
    pcl::PointCloud<pcl::PointXYZRGB> colour;
    pcl::copyPointCloud (*scene.cloud, colour);
    mid::test::paintInkKeepingGreyLevels (scene, 0, green, colour);
    mid::test::paintInkKeepingGreyLevels (scene, 1, ink, colour);
    PrintedFaces painted = faces;
    painted.surface.chromaticity =
        std::make_shared<const std::vector<mid::Chromaticity>> (
            mid::chromaticities (colour));
    mid::PhotometricVerification with_colours = verification;
    with_colours.setKeypointSurface (painted.surface);
    return std::make_pair (with_colours.compare (copies), with_colours);
  };

  const auto [same, verification] = compareInks (green, mid::PhotometricVerification());
  ASSERT_TRUE (same.correlation_tested && same.chromaticity_tested &&
               same.vivid_tested);
  EXPECT_GT (same.correlation, 0.8);
  EXPECT_LT (same.vivid_difference, 0.03);
  EXPECT_FALSE (verification.rejects (same));

  const auto [other, checked] = compareInks (blue, mid::PhotometricVerification());
  ASSERT_TRUE (other.vivid_tested);
  EXPECT_NEAR (other.correlation, same.correlation, 0.02); // grey levels up to rounding
  EXPECT_LT (other.chromaticity_difference, 0.1);          // the mean alone keeps it
  EXPECT_GT (other.vivid_difference, 0.15);
  EXPECT_TRUE (checked.rejects (other));
  mid::TripletClusters verified;
  ASSERT_TRUE (checked.filter ({copies}, verified));
  EXPECT_TRUE (verified.empty());

  // The vivid colours off (2 or more): the mean of all colours keeps the other product.
  mid::PhotometricVerification vivid_off;
  vivid_off.setMaxVividChromaticityDifference (2.0f);
  const auto [unchecked_agreement, unchecked] = compareInks (blue, vivid_off);
  EXPECT_FALSE (unchecked.rejects (unchecked_agreement));
  // A vivid saturation beyond both inks leaves too few vivid pairs to decide.
  mid::PhotometricVerification pale;
  pale.setVividSaturation (0.5f);
  const auto [pale_agreement, pale_check] = compareInks (blue, pale);
  EXPECT_FALSE (pale_agreement.vivid_tested);
  EXPECT_FALSE (pale_check.rejects (pale_agreement));
}

TEST (PhotometricVerification, TellsAnotherWordInOneLayoutByItsNeighbourhoods)
{
  // Box 1 shows box 0's print with the right quarter of its face mirrored: one layout with
  // another word. The correlation of all pairs keeps it; the neighbourhoods of the keypoints
  // in that quarter, each on its own, do not correlate, and their share rejects it when asked
  // to. The copy as printed has no such neighbourhood.
  auto scene = threeBoxes();
  const PrintedFaces printed (scene);
  ASSERT_GT (mid::test::mirrorPrintPart (scene, 1, 0.03, 0.06), 200u);
  const PrintedFaces reworded (scene);
  const mid::TripletCluster copies = printed.cluster (0, 1);
  mid::PhotometricVerification verification;
  EXPECT_FLOAT_EQ (verification.getMaxDisagreeingShare(), 1.0f); // off by default

  verification.setKeypointSurface (printed.surface);
  const auto same = verification.compare (copies);
  ASSERT_TRUE (same.correlation_tested);
  EXPECT_GE (same.neighbourhoods, 16u); // of 12 keypoints each way
  EXPECT_EQ (same.disagreeing_neighbourhoods, 0u);

  verification.setKeypointSurface (reworded.surface);
  const auto other = verification.compare (copies);
  ASSERT_TRUE (other.correlation_tested);
  EXPECT_GT (other.correlation, 0.6); // the guided search's minimum keeps it
  EXPECT_EQ (other.neighbourhoods, same.neighbourhoods);
  // The three keypoints in the mirrored quarter, each way.
  EXPECT_GE (other.disagreeing_neighbourhoods, 4u);
  EXPECT_LE (other.disagreeing_neighbourhoods, 6u);
  EXPECT_FALSE (verification.rejects (other));

  verification.setMaxDisagreeingShare (0.15f);
  EXPECT_TRUE (verification.rejects (other));
  EXPECT_FALSE (verification.rejects (same));
  mid::TripletClusters verified;
  ASSERT_TRUE (verification.filter ({copies}, verified));
  EXPECT_TRUE (verified.empty());
  verification.setKeypointSurface (printed.surface);
  ASSERT_TRUE (verification.filter ({copies}, verified));
  EXPECT_EQ (verified.size(), 1u);
  // A neighbourhood correlation that nothing reaches makes every one disagree.
  verification.setMinNeighbourhoodCorrelation (1.0f);
  EXPECT_EQ (verification.compare (copies).disagreeing_neighbourhoods,
             same.neighbourhoods);
}

TEST (PhotometricVerification, KeepsAClusterTheFrameCannotTell)
{
  // No table: the pose from box 0 onto a box moved far out of the view lands on no surface,
  // so no grey level can be compared and the cluster is kept untested.
  const auto scene = mid::test::renderBoxes (
      {{kApple, {0.12, 0.09, 0.04}, boxPose (-0.05, 0.0, 0.8, 15.0)}});
  const PrintedFaces faces (scene);
  mid::TripletCluster away;
  away.source_indices = away.target_indices = {0, 1, 2, 3};
  away.transformation = Eigen::Matrix4f::Identity();
  away.transformation (0, 3) = 2.0f;
  mid::PhotometricVerification verification;
  verification.setKeypointSurface (faces.surface);
  bool tested = true;
  verification.correlation (away, tested);
  EXPECT_FALSE (tested);
  mid::TripletClusters verified;
  ASSERT_TRUE (verification.filter ({away}, verified));
  EXPECT_EQ (verified.size(), 1u);
}

TEST (PhotometricVerification, RefusesBadInputWithClearedOutput)
{
  const auto scene = threeBoxes();
  const PrintedFaces faces (scene);
  const mid::TripletClusters clusters{faces.cluster (0, 1)};
  const mid::TripletClusters stale{faces.cluster (0, 2)};
  const auto refuses = [&clusters, &stale] (const mid::KeypointSurface& surface,
                                            float radius = 0.015f,
                                            float correlation = 0.4f,
                                            float tolerance = 0.01f) {
    mid::PhotometricVerification verification;
    verification.setKeypointSurface (surface);
    verification.setRadius (radius);
    verification.setMinCorrelation (correlation);
    verification.setDepthTolerance (tolerance);
    mid::TripletClusters verified = stale;
    return !verification.filter (clusters, verified) && verified.empty();
  };
  mid::KeypointSurface no_grey = faces.surface;
  no_grey.intensity = nullptr;
  EXPECT_TRUE (refuses (no_grey));
  mid::KeypointSurface short_grey = faces.surface;
  short_grey.intensity = std::make_shared<std::vector<float>> (100, 0.0f);
  EXPECT_TRUE (refuses (short_grey));
  mid::KeypointSurface short_colour = faces.surface;
  short_colour.chromaticity = std::make_shared<std::vector<mid::Chromaticity>> (
      100, mid::Chromaticity{0.3f, 0.3f});
  EXPECT_TRUE (refuses (short_colour));
  mid::KeypointSurface few_pixels = faces.surface;
  few_pixels.keypoint_pixels.resize (12); // the clusters' box-1 keypoints have no pixel
  EXPECT_TRUE (refuses (few_pixels));
  mid::KeypointSurface no_frame = faces.surface;
  no_frame.organized = nullptr;
  EXPECT_TRUE (refuses (no_frame));
  mid::KeypointSurface shuffled = faces.surface;
  auto points =
      pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>> (*faces.surface.organized);
  std::mt19937 random (3);
  std::shuffle (points->begin(), points->end(), random);
  shuffled.organized = points;
  EXPECT_TRUE (refuses (shuffled));
  for (const double focal : {0.0, double (NAN)}) {
    mid::KeypointSurface bad_pinhole = faces.surface;
    bad_pinhole.pinhole = std::make_shared<const mid::FramePinhole> (
        mid::FramePinhole{focal, 500.0, 320.0, 240.0});
    EXPECT_TRUE (refuses (bad_pinhole));
  }
  EXPECT_TRUE (refuses (faces.surface, 0.0f));
  EXPECT_TRUE (refuses (faces.surface, 0.015f, 1.5f));
  EXPECT_TRUE (refuses (faces.surface, 0.015f, -1.5f));
  EXPECT_TRUE (refuses (faces.surface, 0.015f, 0.4f, 0.0f));
  EXPECT_TRUE (refuses (faces.surface, NAN));
  EXPECT_FALSE (refuses (faces.surface));
  // One parameter out of range, the others at their defaults.
  using Setting = std::function<void (mid::PhotometricVerification&)>;
  const auto refusesSetting = [&] (const Setting& set) {
    mid::PhotometricVerification verification;
    verification.setKeypointSurface (faces.surface);
    set (verification);
    mid::TripletClusters verified = stale;
    return !verification.filter (clusters, verified) && verified.empty();
  };
  for (const float chroma : {0.0f, float (NAN)}) {
    EXPECT_TRUE (refusesSetting ([chroma] (auto& v) {
      v.setMaxChromaticityDifference (chroma);
    })) << chroma;
    EXPECT_TRUE (refusesSetting ([chroma] (auto& v) {
      v.setMaxVividChromaticityDifference (chroma);
    })) << chroma;
  }
  for (const float saturation : {0.0f, 1.5f, float (NAN)})
    EXPECT_TRUE (refusesSetting ([saturation] (auto& v) {
      v.setVividSaturation (saturation);
    })) << saturation;
  for (const float share : {-0.1f, 1.1f, float (NAN)})
    EXPECT_TRUE (refusesSetting ([share] (auto& v) {
      v.setMaxDisagreeingShare (share);
    })) << share;
  for (const float correlation : {-1.5f, 1.5f, float (NAN)})
    EXPECT_TRUE (refusesSetting ([correlation] (auto& v) {
      v.setMinNeighbourhoodCorrelation (correlation);
    })) << correlation;
}
