#include "rendered_keypoints.h"

#include <mid/segmentation/appearance_model_splitter.h>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

using mid::test::boxPose;
using mid::test::kApplePrint;
using mid::test::kPrintedBoxSize;
using mid::test::kSoyPrint;

/** Four boxes of one size, each turned its own way, with the prints given per box; every
  * keypoint looked up in the truth.
  */
struct Boxes : mid::test::RenderedKeypoints
{
  explicit Boxes (const std::vector<std::string>& prints)
  : RenderedKeypoints (mid::test::renderBoxes (
        {{prints[0], kPrintedBoxSize, boxPose (-0.12, -0.07, 0.8, 15.0)},
         {prints[1], kPrintedBoxSize, boxPose (0.11, -0.06, 0.84, 200.0, 20.0)},
         {prints[2], kPrintedBoxSize, boxPose (-0.1, 0.1, 0.82, -70.0)},
         {prints[3], kPrintedBoxSize, boxPose (0.12, 0.11, 0.81, 30.0)}},
        0.95))
  {}

  /** One model claiming all four boxes as copies of one object, the model frame each box's
    * own: every instance at its box's true pose, observing its box's keypoints.
    */
  mid::ObjectModel
  oneModel () const
  {
    mid::ObjectModel model;
    for (std::size_t b = 0; b < scene.boxes.size(); ++b)
      addTruthInstance (b, model);
    return model;
  }

  mid::AppearanceModelSplitter
  splitter () const
  {
    mid::PhotometricVerification verification;
    verification.setKeypointSurface (surface);
    mid::AppearanceModelSplitter splitter;
    splitter.setVerification (verification);
    return splitter;
  }

  /** The boxes a part's instances lie on, in its order (-1: an instance off the boxes). */
  std::vector<int>
  boxesOf (const mid::ObjectModel& part) const
  {
    std::vector<int> boxes;
    for (const auto& instance : part.instances)
      boxes.push_back (boxOf (instance.keypoints));
    return boxes;
  }
};

TEST (AppearanceModelSplitter, SplitsAModelOfTwoPrintsIntoOnePerPrint)
{
  const Boxes boxes ({kApplePrint, kSoyPrint, kApplePrint, kSoyPrint});
  const mid::ObjectModel model = boxes.oneModel();
  mid::ObjectModels parts;
  ASSERT_TRUE (boxes.splitter().split (model, parts));
  ASSERT_EQ (parts.size(), 2u);
  EXPECT_EQ (boxes.boxesOf (parts[0]), (std::vector<int>{0, 2}));
  EXPECT_EQ (boxes.boxesOf (parts[1]), (std::vector<int>{1, 3}));
  for (const auto& part : parts) {
    // Each part keeps exactly the landmarks its instances observe, renumbered.
    std::set<int> observed;
    for (const auto& instance : part.instances) {
      ASSERT_EQ (instance.keypoints.size(), instance.landmarks.size());
      observed.insert (instance.landmarks.begin(), instance.landmarks.end());
    }
    EXPECT_EQ (observed.size(), part.landmarks.size());
    EXPECT_EQ (*observed.rbegin() + 1, static_cast<int> (part.landmarks.size()));
    EXPECT_EQ (part.descriptors.size(), part.landmarks.size());
    EXPECT_GT (part.diameter, 0.0f);
  }
  // The poses are the model's own.
  EXPECT_TRUE (parts[1].instances[0].pose.isApprox (model.instances[1].pose));
}

TEST (AppearanceModelSplitter, KeepsAModelOfOnePrintWhole)
{
  const Boxes boxes ({kApplePrint, kApplePrint, kApplePrint, kApplePrint});
  const mid::ObjectModel model = boxes.oneModel();
  mid::ObjectModels parts;
  ASSERT_TRUE (boxes.splitter().split (model, parts));
  ASSERT_EQ (parts.size(), 1u);
  EXPECT_EQ (boxes.boxesOf (parts[0]), (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ (parts[0].landmarks.size(), model.landmarks.size());
}

TEST (AppearanceModelSplitter, KeepsGroupsThatNeverShowACommonSurface)
{
  // The soy boxes' poses are shifted by one offset in the model frame: their relative pose
  // stays true, but each cross pose moves a print out of the frame, so no pair of a group
  // of each is compared, and nothing tells the groups apart.
  const Boxes boxes ({kApplePrint, kSoyPrint, kApplePrint, kSoyPrint});
  mid::ObjectModel model = boxes.oneModel();
  const Eigen::Affine3f shift (Eigen::Translation3f (3.0f, 0.0f, 0.0f));
  for (const std::size_t i : {1u, 3u})
    model.instances[i].pose = model.instances[i].pose * shift.matrix();
  mid::ObjectModels parts;
  ASSERT_TRUE (boxes.splitter().split (model, parts));
  EXPECT_EQ (parts.size(), 1u);
}

TEST (AppearanceModelSplitter, RefusesBadInputWithClearedOutput)
{
  const Boxes boxes ({kApplePrint, kSoyPrint, kApplePrint, kSoyPrint});
  const mid::ObjectModel model = boxes.oneModel();
  mid::ObjectModels parts (1);

  mid::AppearanceModelSplitter no_frame; // no keypoint surface at all
  EXPECT_FALSE (no_frame.split (model, parts));
  EXPECT_TRUE (parts.empty());

  mid::KeypointSurface grey_less = boxes.surface;
  grey_less.intensity = nullptr;
  mid::PhotometricVerification verification;
  verification.setKeypointSurface (grey_less);
  mid::AppearanceModelSplitter splitter;
  splitter.setVerification (verification);
  parts.resize (1);
  EXPECT_FALSE (splitter.split (model, parts));
  EXPECT_TRUE (parts.empty());

  mid::ObjectModel bad = model;
  bad.instances[2].keypoints[0] = static_cast<pcl::index_t> (boxes.keypoints->size());
  parts.resize (1);
  EXPECT_FALSE (boxes.splitter().split (bad, parts));
  EXPECT_TRUE (parts.empty());

  bad = model;
  bad.instances[0].landmarks[0] = static_cast<int> (model.landmarks.size());
  parts.resize (1);
  EXPECT_FALSE (boxes.splitter().split (bad, parts));
  EXPECT_TRUE (parts.empty());
}

} // namespace
