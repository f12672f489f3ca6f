#include "rendered_keypoints.h"

#include <mid/segmentation/guided_instance_search.h>
#include <mid/segmentation/photometric_verification.h>

#include <gtest/gtest.h>
#include <pcl/common/io.h>

#include <functional>
#include <memory>
#include <set>
#include <vector>

namespace {

using mid::test::boxPose;
using mid::test::kApplePrint;
using mid::test::kPrintedBoxSize;
using mid::test::kSoyPrint;

/** Three copies of one print, each turned its own way in the image (box 1 also tilted), and a
  * box of another print; every keypoint looked up in the truth; a model made from the truth
  * of box 0 (its frame is the box's own), with one instance there.
  */
struct FourBoxes : mid::test::RenderedKeypoints
{
  mid::ObjectModel model;

  /** The scene, changed by `edit` (if given) before its keypoints are found. */
  explicit FourBoxes (
      const std::function<void (mid::test::RenderedObjectsScene&)>& edit = {})
  : RenderedKeypoints (rendered (edit))
  {
    addTruthInstance (0, model);
  }

  static mid::test::RenderedObjectsScene
  rendered (const std::function<void (mid::test::RenderedObjectsScene&)>& edit)
  {
    auto scene = mid::test::renderBoxes (
        {{kApplePrint, kPrintedBoxSize, boxPose (-0.12, -0.07, 0.8, 15.0)},
         {kApplePrint, kPrintedBoxSize, boxPose (0.11, -0.06, 0.84, 200.0, 20.0)},
         {kApplePrint, kPrintedBoxSize, boxPose (-0.1, 0.1, 0.82, -70.0)},
         {kSoyPrint, kPrintedBoxSize, boxPose (0.12, 0.11, 0.81, 30.0)}},
        0.95);
    if (edit)
      edit (scene);
    return scene;
  }

  /** How many copies a search finds among the keypoints of box `box` and the table, set up
    * by `configure`.
    */
  std::size_t
  foundOn (int box,
           const std::function<void (mid::GuidedInstanceSearch&)>& configure) const
  {
    auto searching = search();
    searching.setCandidates (on ({-1, box}));
    configure (searching);
    mid::ModelInstances found;
    EXPECT_TRUE (searching.search (model, found));
    return found.size();
  }

  /** A search over every keypoint off box 0. */
  mid::GuidedInstanceSearch
  search () const
  {
    mid::GuidedInstanceSearch search;
    search.setInputKeypoints (keypoints);
    search.setInputDescriptors (descriptors);
    search.setImageKeypoints (image_keypoints);
    search.setKeypointSurface (surface);
    search.setCandidates (on ({-1, 1, 2, 3}));
    return search;
  }
};

/** Rotation angle (degrees) and distance (metres) between two poses. */
std::pair<double, double>
poseError (const Eigen::Matrix4f& a, const Eigen::Matrix4d& b)
{
  const Eigen::Matrix4d d = a.cast<double>().inverse() * b;
  return {Eigen::AngleAxisd (d.block<3, 3> (0, 0)).angle() * 180.0 / M_PI,
          (a.cast<double>().block<3, 1> (0, 3) - b.block<3, 1> (0, 3)).norm()};
}

TEST (GuidedInstanceSearch, FindsTheOtherCopiesAtTheirTruePoses)
{
  const FourBoxes boxes;
  ASSERT_GE (boxes.model.landmarks.size(), 20u);
  mid::ModelInstances found;
  ASSERT_TRUE (boxes.search().search (boxes.model, found));
  std::set<int> copies;
  for (const auto& instance : found) {
    const int box = boxes.boxOf (instance.keypoints);
    ASSERT_TRUE (box == 1 || box == 2) << "an instance off the copies: box " << box;
    EXPECT_TRUE (copies.insert (box).second) << "box " << box << " found twice";
    EXPECT_GE (instance.keypoints.size(), 6u);
    ASSERT_EQ (instance.keypoints.size(), instance.landmarks.size());
    // The model frame is box 0's own frame, so the pose is the copy's true pose.
    const auto error = poseError (
        instance.pose, boxes.scene.boxes[static_cast<std::size_t> (box)].pose.matrix());
    EXPECT_LT (error.first, 2.0) << "box " << box;
    EXPECT_LT (error.second, 0.003) << "box " << box;
  }
  EXPECT_EQ (copies, (std::set<int>{1, 2}));
}

TEST (GuidedInstanceSearch, RefusesAnotherPrint)
{
  const FourBoxes boxes;
  auto search = boxes.search();
  search.setCandidates (boxes.on ({-1, 3}));
  mid::ModelInstances found;
  ASSERT_TRUE (search.search (boxes.model, found));
  EXPECT_TRUE (found.empty());
}

TEST (GuidedInstanceSearch, RefusesACopyFoundAlready)
{
  const FourBoxes boxes;
  mid::ModelInstance box1;
  box1.keypoints = boxes.on ({1});
  auto search = boxes.search();
  search.setFoundInstances ({box1});
  mid::ModelInstances found;
  ASSERT_TRUE (search.search (boxes.model, found));
  ASSERT_EQ (found.size(), 1u);
  EXPECT_EQ (boxes.boxOf (found.front().keypoints), 2);
}

TEST (GuidedInstanceSearch, RefusesACopyInAnotherInkByTheVividColours)
{
  // The print's ink repainted, grey levels kept: green on box 0 (the model) and box 1, blue on
  // box 2 (another product of the brand). The vivid colours refuse box 2; off, it is found.
  const FourBoxes boxes;
  pcl::PointCloud<pcl::PointXYZRGB> colour;
  pcl::copyPointCloud (*boxes.scene.cloud, colour);
  const Eigen::Vector3f green (0.5f, 1.0f, 0.6f), blue (0.3f, 0.5f, 1.0f);
  mid::test::paintInkKeepingGreyLevels (boxes.scene, 0, green, colour);
  mid::test::paintInkKeepingGreyLevels (boxes.scene, 1, green, colour);
  mid::test::paintInkKeepingGreyLevels (boxes.scene, 2, blue, colour);
  mid::KeypointSurface painted = boxes.surface;
  painted.chromaticity = std::make_shared<const std::vector<mid::Chromaticity>> (
      mid::chromaticities (colour));
  const auto findOn = [&] (int box, float max_vivid_difference) {
    return boxes.foundOn (box, [&] (mid::GuidedInstanceSearch& search) {
      search.setKeypointSurface (painted);
      search.setMaxVividChromaticityDifference (max_vivid_difference);
    });
  };
  EXPECT_EQ (findOn (1, 0.15f), 1u);
  EXPECT_EQ (findOn (2, 0.15f), 0u);
  EXPECT_EQ (findOn (2, 2.0f), 1u);
}

TEST (GuidedInstanceSearch, RefusesACopyWithAnotherWordByItsNeighbourhoods)
{
  // Box 2 shows the print with a third of its face mirrored: the layout of the model's print
  // with another word, as on two printed sides of one carton. Found as a copy by the
  // correlation of all pairs, it is refused once few disagreeing neighbourhoods are allowed,
  // or returned apart as unconfirmed; box 1, a true copy, is still found. (It disagrees in
  // about 17 % of its neighbourhoods: the share asked here is 0.1, not the pipeline's 0.3.)
  const FourBoxes boxes ([] (mid::test::RenderedObjectsScene& scene) {
    ASSERT_GT (mid::test::mirrorPrintPart (scene, 2, 0.02, 0.06), 200u);
  });
  const auto findOn = [&] (int box, float max_share) {
    return boxes.foundOn (box, [max_share] (mid::GuidedInstanceSearch& search) {
      search.setMaxDisagreeingShare (max_share);
    });
  };
  EXPECT_EQ (findOn (2, 1.0f), 1u);
  EXPECT_EQ (findOn (2, 0.1f), 0u);
  EXPECT_EQ (findOn (1, 0.1f), 1u);

  auto search = boxes.search();
  search.setMaxDisagreeingShare (0.1f);
  mid::ModelInstances found, unconfirmed;
  ASSERT_TRUE (search.search (boxes.model, found, unconfirmed));
  ASSERT_EQ (found.size(), 1u);
  EXPECT_EQ (boxes.boxOf (found.front().keypoints), 1);
  ASSERT_EQ (unconfirmed.size(), 1u);
  EXPECT_EQ (boxes.boxOf (unconfirmed.front().keypoints), 2);
  EXPECT_GE (unconfirmed.front().keypoints.size(), 6u);
  // The bad input clears both outputs.
  search.setMaxDisagreeingShare (2.0f);
  EXPECT_FALSE (search.search (boxes.model, found, unconfirmed));
  EXPECT_TRUE (found.empty() && unconfirmed.empty());
}

TEST (GuidedInstanceSearch, RefusesBadInputWithClearedOutput)
{
  const FourBoxes boxes;
  const mid::ModelInstances stale (1);
  const auto refused = [&stale] (const mid::GuidedInstanceSearch& search,
                                 const mid::ObjectModel& model) {
    mid::ModelInstances found = stale;
    const bool ok = search.search (model, found);
    return !ok && found.empty();
  };
  auto search = boxes.search();
  search.setImageKeypoints ({});
  EXPECT_TRUE (refused (search, boxes.model)) << "no image keypoints";
  search = boxes.search();
  search.setCandidates ({static_cast<pcl::index_t> (boxes.keypoints->size())});
  EXPECT_TRUE (refused (search, boxes.model)) << "a candidate beyond the keypoints";
  search = boxes.search();
  search.setMinInliers (2);
  EXPECT_TRUE (refused (search, boxes.model)) << "two inliers";
  search = boxes.search();
  search.setMinCorrelation (1.5f);
  EXPECT_TRUE (refused (search, boxes.model)) << "correlation above 1";
  search = boxes.search();
  search.setMaxDisagreeingShare (1.5f);
  EXPECT_TRUE (refused (search, boxes.model)) << "a share above 1";
  search = boxes.search();
  search.setMinNeighbourhoodCorrelation (-2.0f);
  EXPECT_TRUE (refused (search, boxes.model)) << "a neighbourhood correlation below -1";
  search = boxes.search();
  search.setMaxVividChromaticityDifference (0.0f);
  EXPECT_TRUE (refused (search, boxes.model)) << "no vivid colour difference allowed";
  search = boxes.search();
  mid::KeypointSurface no_grey = boxes.surface;
  no_grey.intensity = nullptr;
  search.setKeypointSurface (no_grey);
  EXPECT_TRUE (refused (search, boxes.model)) << "no grey levels";
  mid::ObjectModel broken = boxes.model;
  broken.instances.front().landmarks.front() = 100000;
  EXPECT_TRUE (refused (boxes.search(), broken)) << "an instance of a missing landmark";
}

} // namespace
