// ModelBoxPruning on rendered boxes resting on a table at known poses: a row of copies whose
// model took each copy's print with its neighbour's, as one cluster along a row builds it.
#include "resting_boxes.h"

#include <mid/segmentation/model_box_pruning.h>

#include <gtest/gtest.h>

#include <limits>
#include <vector>

namespace {

using mid::test::restingBox;
using Boxes = mid::test::RestingBoxes;

constexpr int kCopies = 5;

/** Five copies of one print in a row, turned alike, 0.05 m apart (their longest edges, 0.12 m,
  * along the row).
  */
std::vector<mid::test::BoxSpec>
rowOfFive ()
{
  std::vector<mid::test::BoxSpec> row;
  row.reserve (kCopies);
  for (int b = 0; b < kCopies; ++b)
    row.push_back (restingBox (mid::test::kApplePrint, 0.17 * (b - 2), 0.0, 0.0));
  return row;
}

/** Add the keypoints on box `b` to `instance` (at its pose), each as a landmark of its own;
  * with `near_half`, only those on the half of the box towards the start of the row.
  */
void
observeBox (const Boxes& scene,
            int b,
            bool near_half,
            mid::ModelInstance& instance,
            mid::ObjectModel& model)
{
  const Eigen::Affine3f to_model (instance.pose.inverse());
  const float centre = static_cast<float> (
      scene.scene.boxes[static_cast<std::size_t> (b)].pose.translation().x());
  for (const auto k : scene.on ({b})) {
    if (near_half && (*scene.keypoints)[static_cast<std::size_t> (k)].x > centre)
      continue;
    pcl::PointNormal landmark = (*scene.keypoints)[static_cast<std::size_t> (k)];
    landmark.getVector3fMap() = to_model * landmark.getVector3fMap();
    landmark.getNormalVector3fMap() =
        to_model.linear() * landmark.getNormalVector3fMap();
    instance.keypoints.push_back (k);
    instance.landmarks.push_back (static_cast<int> (model.landmarks.size()));
    model.descriptor_landmarks.push_back (instance.landmarks.back());
    model.landmarks.push_back (landmark);
    model.descriptors.push_back ((*scene.descriptors)[static_cast<std::size_t> (k)]);
  }
}

/** The model a cluster along the row builds: an instance at the true pose of each box (the
  * model frame is a box's own), each observing its box, and the first two also the half of
  * the next box that faces them. The surfaces measured from the instances' keypoints then
  * hold boxes 3 and 4 whole; the others are joined with or cut by a neighbour.
  */
mid::ObjectModel
copyWithItsNeighbour (const Boxes& scene)
{
  mid::ObjectModel model;
  for (int b = 0; b < kCopies; ++b) {
    mid::ModelInstance instance;
    instance.pose =
        scene.scene.boxes[static_cast<std::size_t> (b)].pose.matrix().cast<float>();
    observeBox (scene, b, false, instance, model);
    if (b < 2)
      observeBox (scene, b + 1, true, instance, model);
    model.instances.push_back (instance);
  }
  return model;
}

/** The model's landmarks are each observed by an instance, and each descriptor's landmark
  * exists.
  */
void
expectConsistent (const mid::ObjectModel& model)
{
  std::vector<bool> observed (model.landmarks.size(), false);
  for (const auto& instance : model.instances) {
    ASSERT_EQ (instance.keypoints.size(), instance.landmarks.size());
    for (const int l : instance.landmarks) {
      ASSERT_GE (l, 0);
      ASSERT_LT (static_cast<std::size_t> (l), model.landmarks.size());
      observed[static_cast<std::size_t> (l)] = true;
    }
  }
  for (std::size_t l = 0; l < observed.size(); ++l)
    EXPECT_TRUE (observed[l]) << "landmark " << l << " is observed by no instance";
  ASSERT_EQ (model.descriptors.size(), model.descriptor_landmarks.size());
  for (const int l : model.descriptor_landmarks)
    EXPECT_LT (static_cast<std::size_t> (l), model.landmarks.size());
}

} // namespace

TEST (ModelBoxPruning, KeepsEachCopyOfARowToItsOwnBox)
{
  const Boxes scene (rowOfFive());
  mid::ObjectModels models = {copyWithItsNeighbour (scene)};
  std::size_t on_neighbours = 0;
  for (int b = 0; b < 2; ++b)
    on_neighbours +=
        models[0].instances[static_cast<std::size_t> (b)].keypoints.size() -
        scene.on ({b}).size();
  ASSERT_GT (on_neighbours, 15u) << "the print shows too few keypoints";

  std::size_t dropped = 0;
  ASSERT_TRUE (
      mid::test::measuringStep<mid::ModelBoxPruning> (scene).prune (models, dropped));
  ASSERT_EQ (models.size(), 1u);
  ASSERT_EQ (models[0].instances.size(), static_cast<std::size_t> (kCopies));
  EXPECT_EQ (dropped, on_neighbours);
  for (std::size_t b = 0; b < kCopies; ++b) {
    const auto& instance = models[0].instances[b];
    EXPECT_EQ (instance.keypoints.size(), scene.on ({static_cast<int> (b)}).size())
        << "box " << b;
    EXPECT_EQ (scene.boxOf (instance.keypoints), static_cast<int> (b));
    for (const auto k : instance.keypoints)
      EXPECT_EQ (scene.box_of[static_cast<std::size_t> (k)], static_cast<int> (b))
          << "box " << b;
  }
  ASSERT_NO_FATAL_FAILURE (expectConsistent (models[0]));
}

TEST (ModelBoxPruning, LeavesTheModelOfWholeCopiesAsItIs)
{
  const Boxes scene (rowOfFive());
  const mid::ObjectModel truth = scene.modelOf ({0, 1, 2, 3, 4});
  mid::ObjectModels models = {truth};
  std::size_t dropped = std::numeric_limits<std::size_t>::max();
  ASSERT_TRUE (
      mid::test::measuringStep<mid::ModelBoxPruning> (scene).prune (models, dropped));
  EXPECT_EQ (dropped, 0u);
  ASSERT_EQ (models.size(), 1u);
  EXPECT_EQ (models[0].landmarks.size(), truth.landmarks.size());
  ASSERT_EQ (models[0].instances.size(), truth.instances.size());
  for (std::size_t i = 0; i < truth.instances.size(); ++i)
    EXPECT_EQ (models[0].instances[i].keypoints, truth.instances[i].keypoints);
}

TEST (ModelBoxPruning, LeavesAModelAloneWhoseCopiesDoNotAgreeOnItsSize)
{
  // Box 0 joined with half of box 1, and box 3 whole: the two measured copies differ, the
  // model has no size, and the first instance keeps its neighbour's keypoints.
  const Boxes scene (rowOfFive());
  mid::ObjectModel model = copyWithItsNeighbour (scene);
  model.instances = {model.instances[0], model.instances[3]};
  ASSERT_GT (model.instances[0].keypoints.size(), scene.on ({0}).size());
  mid::ObjectModels models = {model};
  std::size_t dropped = 1;
  ASSERT_TRUE (
      mid::test::measuringStep<mid::ModelBoxPruning> (scene).prune (models, dropped));
  EXPECT_EQ (dropped, 0u);
  EXPECT_EQ (models[0].instances[0].keypoints, model.instances[0].keypoints);
  EXPECT_EQ (models[0].instances[1].keypoints, model.instances[1].keypoints);

  // Control: a third copy measured whole (box 4) agrees with box 3, and the first instance
  // loses its neighbour's keypoints, so the table and the plane were there.
  model.instances.push_back (copyWithItsNeighbour (scene).instances[4]);
  models = {model};
  ASSERT_TRUE (
      mid::test::measuringStep<mid::ModelBoxPruning> (scene).prune (models, dropped));
  EXPECT_EQ (dropped, model.instances[0].keypoints.size() - scene.on ({0}).size());
}

TEST (ModelBoxPruning, RemovesAnInstanceWhoseBoxHoldsNoneOfItsKeypoints)
{
  // A sixth instance observes box 1's keypoints but is posed 0.3 m off the row: its box holds
  // none of them. It goes with its landmarks; an instance that never had an observation stays.
  const Boxes scene (rowOfFive());
  mid::ObjectModel model = copyWithItsNeighbour (scene);
  mid::ModelInstance off_row;
  off_row.pose = model.instances[0].pose;
  off_row.pose (1, 3) += 0.3f;
  observeBox (scene, 1, false, off_row, model);
  model.instances.push_back (off_row);
  mid::ModelInstance unobserved;
  unobserved.pose = model.instances[4].pose;
  model.instances.push_back (unobserved);

  mid::ObjectModels models = {model};
  std::size_t dropped = 0;
  ASSERT_TRUE (
      mid::test::measuringStep<mid::ModelBoxPruning> (scene).prune (models, dropped));
  ASSERT_EQ (models[0].instances.size(), static_cast<std::size_t> (kCopies + 1));
  EXPECT_TRUE (models[0].instances.back().keypoints.empty());
  std::size_t kept = 0;
  for (std::size_t b = 0; b < kCopies; ++b) {
    const auto& instance = models[0].instances[b];
    EXPECT_TRUE (instance.pose.isApprox (model.instances[b].pose)) << "box " << b;
    EXPECT_EQ (scene.boxOf (instance.keypoints), static_cast<int> (b));
    // The landmarks were renumbered: each observation still explains its keypoint.
    EXPECT_LT (instance.rms_error, 1e-4f) << "box " << b;
    kept += instance.keypoints.size();
  }
  std::size_t on_neighbours = 0;
  for (int b = 0; b < 2; ++b)
    on_neighbours += model.instances[static_cast<std::size_t> (b)].keypoints.size() -
                     scene.on ({b}).size();
  EXPECT_EQ (dropped, off_row.keypoints.size() + on_neighbours);
  EXPECT_EQ (models[0].landmarks.size(), kept);
  ASSERT_NO_FATAL_FAILURE (expectConsistent (models[0]));
}

TEST (ModelBoxPruning, LeavesAModelThatWouldKeepOneInstance)
{
  // Box 3 and box 4 whole agree on the size; the second instance is posed 0.3 m off the row,
  // so none of its keypoints is in its box. Removing it would leave one instance: the model
  // stays as it is.
  const Boxes scene (rowOfFive());
  const auto twoCopies = [&scene] (bool with_box_4_posed_right) {
    mid::ObjectModel model;
    for (int b = 3; b < kCopies; ++b) {
      mid::ModelInstance instance;
      instance.pose =
          scene.scene.boxes[static_cast<std::size_t> (b)].pose.matrix().cast<float>();
      if (b == 4)
        instance.pose (1, 3) += 0.3f;
      observeBox (scene, b, false, instance, model);
      model.instances.push_back (instance);
    }
    if (with_box_4_posed_right) {
      mid::ModelInstance instance;
      instance.pose = scene.scene.boxes[4].pose.matrix().cast<float>();
      observeBox (scene, 4, false, instance, model);
      model.instances.push_back (instance);
    }
    return model;
  };
  const mid::ObjectModel model = twoCopies (false);
  mid::ObjectModels models = {model};
  std::size_t dropped = 1;
  const auto pruning = mid::test::measuringStep<mid::ModelBoxPruning> (scene);
  ASSERT_TRUE (pruning.prune (models, dropped));
  EXPECT_EQ (dropped, 0u);
  ASSERT_EQ (models[0].instances.size(), 2u);
  EXPECT_EQ (models[0].instances[1].keypoints, model.instances[1].keypoints);
  EXPECT_EQ (models[0].landmarks.size(), model.landmarks.size());

  // Control: with box 4 also posed right, two instances stay and the one off the row goes,
  // so the two copies above did agree on the size.
  const mid::ObjectModel three = twoCopies (true);
  models = {three};
  ASSERT_TRUE (pruning.prune (models, dropped));
  EXPECT_EQ (dropped, three.instances[1].keypoints.size());
  EXPECT_EQ (models[0].instances.size(), 2u);
}

TEST (ModelBoxPruning, RefusesAModelWithInconsistentDescriptors)
{
  const Boxes scene (rowOfFive());
  mid::ObjectModel model = copyWithItsNeighbour (scene);
  model.descriptor_landmarks.back() = static_cast<int> (model.landmarks.size());
  mid::ObjectModels models = {model};
  std::size_t dropped = 3;
  EXPECT_FALSE (
      mid::test::measuringStep<mid::ModelBoxPruning> (scene).prune (models, dropped));
  EXPECT_EQ (dropped, 0u);
  EXPECT_EQ (models[0].instances[0].keypoints, model.instances[0].keypoints);
  EXPECT_EQ (models[0].landmarks.size(), model.landmarks.size());
}

TEST (ModelBoxPruning, RefusesANegativeMarginAndLeavesTheModels)
{
  const Boxes scene (rowOfFive());
  const mid::ObjectModel model = copyWithItsNeighbour (scene);
  mid::ObjectModels models = {model};
  auto pruning = mid::test::measuringStep<mid::ModelBoxPruning> (scene);
  pruning.setMargin (-0.01f);
  std::size_t dropped = 7;
  EXPECT_FALSE (pruning.prune (models, dropped));
  EXPECT_EQ (dropped, 0u);
  EXPECT_EQ (models[0].instances[0].keypoints, model.instances[0].keypoints);
  EXPECT_EQ (models[0].landmarks.size(), model.landmarks.size());
}
