// ModelSizeSplitter on rendered boxes resting on a table at known poses: one model holding
// the copies of two products, known by which box each instance lies on.
#include "resting_boxes.h"

#include <mid/segmentation/model_size_splitter.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

namespace {

using mid::test::kApplePrint;
using mid::test::kPrintedBoxSize;
using mid::test::kSoyPrint;
using mid::test::restingBox;
using Boxes = mid::test::RestingBoxes;

/** A box larger than kPrintedBoxSize (0.12 x 0.09 x 0.04) on every edge. */
const Eigen::Vector3d kLargerBox{0.15, 0.11, 0.06};

mid::ModelSizeSplitter
splitterFor (const Boxes& scene)
{
  return mid::test::measuringStep<mid::ModelSizeSplitter> (scene);
}

/** The boxes the instances of `model` lie on (every instance on one box). */
std::set<int>
boxesOf (const Boxes& scene, const mid::ObjectModel& model)
{
  std::set<int> boxes;
  for (const auto& instance : model.instances) {
    const int b = scene.boxOf (instance.keypoints);
    EXPECT_GE (b, 0) << "an instance spans several boxes";
    boxes.insert (b);
  }
  return boxes;
}

/** Three small apple boxes (0 to 2) and two larger soy boxes (3, 4), apart on the table. */
std::vector<mid::test::BoxSpec>
threeSmallTwoLarge (const Eigen::Vector3d& larger = kLargerBox)
{
  return {restingBox (kApplePrint, -0.17, -0.12, 10.0),
          restingBox (kApplePrint, 0.0, -0.13, 100.0),
          restingBox (kApplePrint, 0.17, -0.11, -35.0),
          restingBox (kSoyPrint, -0.14, 0.12, 70.0, larger),
          restingBox (kSoyPrint, 0.15, 0.12, 160.0, larger)};
}

TEST (ModelSizeSplitter, SplitsAModelOfTwoProductsOfDifferentSizes)
{
  const Boxes scene (threeSmallTwoLarge());
  const mid::ObjectModel whole = scene.modelOf ({3, 0, 4, 1, 2});
  mid::ObjectModels models = {whole};
  std::size_t added = 0;
  ASSERT_TRUE (splitterFor (scene).split (models, added));
  EXPECT_EQ (added, 1u);
  ASSERT_EQ (models.size(), 2u);
  // The larger group (three copies) keeps the model's place; the other part is appended.
  EXPECT_EQ (boxesOf (scene, models[0]), (std::set<int>{0, 1, 2}));
  EXPECT_EQ (boxesOf (scene, models[1]), (std::set<int>{3, 4}));
  // Each part keeps the model frame, its instances' poses and only the landmarks they
  // observe: together, every landmark of the whole model once.
  std::size_t landmarks = 0;
  for (const auto& part : models) {
    for (const auto& instance : part.instances) {
      const int b = scene.boxOf (instance.keypoints);
      const Eigen::Matrix4f truth =
          scene.scene.boxes[static_cast<std::size_t> (b)].pose.matrix().cast<float>();
      EXPECT_TRUE (instance.pose.isApprox (truth, 1e-5f)) << "box " << b;
      for (const int l : instance.landmarks)
        EXPECT_LT (l, static_cast<int> (part.landmarks.size()));
    }
    landmarks += part.landmarks.size();
    EXPECT_EQ (part.descriptors.size(), part.descriptor_landmarks.size());
  }
  EXPECT_EQ (landmarks, whole.landmarks.size());
}

TEST (ModelSizeSplitter, KeepsAModelWhoseBoxesDifferOnOneEdgeOnly)
{
  // The larger boxes are longer only, as a copy joined with a neighbour or partly hidden
  // measures: one product, the step keeps it whole.
  const Boxes scene (threeSmallTwoLarge ({0.15, 0.09, 0.04}));
  mid::ObjectModels models = {scene.modelOf ({0, 1, 2, 3, 4})};
  std::size_t added = 1;
  ASSERT_TRUE (splitterFor (scene).split (models, added));
  EXPECT_EQ (added, 0u);
  ASSERT_EQ (models.size(), 1u);
  EXPECT_EQ (models[0].instances.size(), 5u);
}

TEST (ModelSizeSplitter, KeepsAModelWithASingleCopyOfAnotherSize)
{
  const Boxes scene (threeSmallTwoLarge());
  mid::ObjectModels models = {scene.modelOf ({0, 1, 2, 3})};
  std::size_t added = 1;
  ASSERT_TRUE (splitterFor (scene).split (models, added));
  EXPECT_EQ (added, 0u);
  ASSERT_EQ (models.size(), 1u);
  EXPECT_EQ (models[0].instances.size(), 4u);

  // Two copies of each size are enough by default, three are not when asked for.
  models = {scene.modelOf ({0, 1, 3, 4})};
  ASSERT_TRUE (splitterFor (scene).split (models, added));
  EXPECT_EQ (models.size(), 2u);
  models = {scene.modelOf ({0, 1, 2, 3, 4})};
  mid::ModelSizeSplitter three = splitterFor (scene);
  three.setMinAgreeing (3);
  ASSERT_TRUE (three.split (models, added));
  EXPECT_EQ (models.size(), 1u);
}

TEST (ModelSizeSplitter, GivesAnUnmeasuredCopyToTheGroupThatSharesItsLandmarks)
{
  // Box 5, a soy print 5 mm thin, lies within the support plane's tolerance: it has no box.
  auto boxes = threeSmallTwoLarge();
  boxes.push_back (restingBox (kSoyPrint, 0.0, 0.14, 20.0, {0.12, 0.09, 0.005}));
  const Boxes scene (boxes);
  mid::ObjectModel model = scene.modelOf ({0, 1, 2, 3, 4, 5});
  // Its observations are made those of landmarks box 3 observes (its own landmarks are its
  // alone), so it shares landmarks with the soy copies only.
  auto& thin = model.instances[5];
  const auto& soy = model.instances[3];
  const std::size_t n = std::min (thin.keypoints.size(), soy.landmarks.size());
  ASSERT_GT (n, 0u);
  thin.keypoints.resize (n);
  thin.landmarks.assign (soy.landmarks.begin(),
                         soy.landmarks.begin() + static_cast<std::ptrdiff_t> (n));

  mid::ObjectModels models = {model};
  std::size_t added = 0;
  ASSERT_TRUE (splitterFor (scene).split (models, added));
  ASSERT_EQ (models.size(), 2u);
  EXPECT_EQ (boxesOf (scene, models[0]), (std::set<int>{0, 1, 2}));
  EXPECT_EQ (boxesOf (scene, models[1]), (std::set<int>{3, 4, 5}));

  // Sharing nothing, it would go with the larger group.
  mid::ObjectModels unshared = {scene.modelOf ({0, 1, 2, 3, 4, 5})};
  ASSERT_TRUE (splitterFor (scene).split (unshared, added));
  ASSERT_EQ (unshared.size(), 2u);
  EXPECT_EQ (boxesOf (scene, unshared[0]), (std::set<int>{0, 1, 2, 5}));
}

TEST (ModelSizeSplitter, ChangesNothingWithoutASupportPlane)
{
  const Boxes scene (threeSmallTwoLarge());
  mid::ObjectModels models = {scene.modelOf ({0, 1, 2, 3, 4})};
  mid::ModelSizeSplitter splitter = splitterFor (scene);
  splitter.setSupportPlane (Eigen::Vector4f::Zero());
  std::size_t added = 1;
  ASSERT_TRUE (splitter.split (models, added));
  EXPECT_EQ (added, 0u);
  EXPECT_EQ (models.size(), 1u);
}

TEST (ModelSizeSplitter, RefusesBadInputAndLeavesTheModels)
{
  const Boxes scene (threeSmallTwoLarge());
  const mid::ObjectModels original = {scene.modelOf ({0, 1, 2, 3, 4})};
  const auto refuses = [&] (const mid::ModelSizeSplitter& splitter,
                            mid::ObjectModels models) {
    std::size_t added = 1;
    EXPECT_FALSE (splitter.split (models, added));
    EXPECT_EQ (added, 0u);
    ASSERT_EQ (models.size(), 1u);
    EXPECT_EQ (models[0].instances.size(), original[0].instances.size());
  };
  mid::ModelSizeSplitter no_keypoints = splitterFor (scene);
  no_keypoints.setInputKeypoints (nullptr);
  refuses (no_keypoints, original);

  mid::ModelSizeSplitter one_copy = splitterFor (scene);
  one_copy.setMinAgreeing (1);
  refuses (one_copy, original);

  mid::ModelSizeSplitter negative = splitterFor (scene);
  negative.setSizeTolerance (-0.001f, 0.03f);
  refuses (negative, original);

  mid::ObjectModels outside = original;
  outside[0].instances[0].keypoints[0] =
      static_cast<pcl::index_t> (scene.keypoints->size());
  std::size_t added = 1;
  EXPECT_FALSE (splitterFor (scene).split (outside, added));
  EXPECT_EQ (outside.size(), 1u);
}

} // namespace
