// RepeatedPrintFilter on rendered boxes resting on a table at known poses: instances of one
// model that lie on one box, shifted along a print that repeats on it, against true copies.
#include "resting_boxes.h"

#include <mid/segmentation/instance_extent.h>
#include <mid/segmentation/repeated_print_filter.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using mid::test::kApplePrint;
using mid::test::kSoyPrint;
using mid::test::restingBox;
using Boxes = mid::test::RestingBoxes;

/** Boxes 0 and 1 apart with one print, lying flat (edges 0.12, 0.09 and 0.04: a repeat may
  * shift by less than 0.75 x 0.04 = 0.03 m).
  */
std::vector<mid::test::BoxSpec>
twoApart ()
{
  return {restingBox (kApplePrint, -0.16, -0.1, 10.0),
          restingBox (kApplePrint, 0.16, -0.12, -35.0)};
}

/** Boxes 0 and 1 touching along their long edges in one orientation: their tops join into
  * one flat surface, and each is the other moved by 0.09 m.
  */
std::vector<mid::test::BoxSpec>
twoTouchingAlike ()
{
  return {restingBox (kSoyPrint, 0.0, 0.1, 0.0),
          restingBox (kSoyPrint, 0.0, 0.19, 0.0)};
}

/** The keypoints on box b with a box-frame x below (`low`) or at least (`!low`) zero. */
pcl::Indices
halfOf (const Boxes& scene, int b, bool low)
{
  const Eigen::Isometry3f to_box =
      scene.scene.boxes[static_cast<std::size_t> (b)].pose.inverse().cast<float>();
  pcl::Indices half;
  for (const auto k : scene.on ({b}))
    if (((to_box * (*scene.keypoints)[static_cast<std::size_t> (k)].getVector3fMap())
             .x() < 0.0f) == low)
      half.push_back (k);
  return half;
}

/** An instance at `pose` observing `keypoints`, each on one of the model's landmarks. */
mid::ModelInstance
instanceAt (const Eigen::Matrix4f& pose,
            const pcl::Indices& keypoints,
            const mid::ObjectModel& model)
{
  mid::ModelInstance instance;
  instance.pose = pose;
  instance.keypoints = keypoints;
  for (std::size_t i = 0; i < keypoints.size(); ++i)
    instance.landmarks.push_back (static_cast<int> (i % model.landmarks.size()));
  return instance;
}

/** The pose of box b moved, in the box's frame, by `shift` metres along x and turned by
  * `turn` degrees about z: where a print that repeats on the box puts a second instance.
  */
Eigen::Matrix4f
repeatOn (const Boxes& scene, int b, float shift, float turn)
{
  const Eigen::Isometry3f box =
      scene.scene.boxes[static_cast<std::size_t> (b)].pose.cast<float>();
  const Eigen::Isometry3f moved =
      box * Eigen::Translation3f (shift, 0.0f, 0.0f) *
      Eigen::AngleAxisf (turn * static_cast<float> (M_PI / 180.0),
                         Eigen::Vector3f::UnitZ());
  return moved.matrix();
}

/** A model of box 0's low half at the box's pose, its high half at `second_pose` (a repeat),
  * and, with `with_copy`, box 1 at its true pose.
  */
mid::ObjectModel
modelWithRepeat (const Boxes& scene, const Eigen::Matrix4f& second_pose, bool with_copy)
{
  mid::ObjectModel model = scene.modelOf ({0});
  model.instances.front().keypoints = halfOf (scene, 0, true);
  model.instances.front().landmarks.resize (model.instances.front().keypoints.size());
  model.instances.push_back (instanceAt (second_pose, halfOf (scene, 0, false), model));
  if (with_copy) {
    mid::ObjectModel copy = scene.modelOf ({1});
    model.instances.push_back (instanceAt (
        copy.instances.front().pose, copy.instances.front().keypoints, model));
  }
  return model;
}

mid::RepeatedPrintFilter
filterIn (const Boxes& scene)
{
  return mid::test::measuringStep<mid::RepeatedPrintFilter> (scene);
}

/** Filter one model; its instances afterwards (none if the model went), and the count. */
std::pair<mid::ModelInstances, std::size_t>
filtered (const mid::RepeatedPrintFilter& filter, const mid::ObjectModel& model)
{
  mid::ObjectModels models = {model};
  std::size_t removed = std::numeric_limits<std::size_t>::max();
  EXPECT_TRUE (filter.filter (models, removed));
  EXPECT_LE (models.size(), 1u);
  return {models.empty() ? mid::ModelInstances() : models.front().instances, removed};
}

} // namespace

TEST (RepeatedPrintFilter, RemovesTheRepeatOnOneBoxAndKeepsTheCopy)
{
  const Boxes scene (twoApart());
  ASSERT_NE (halfOf (scene, 0, true).size(), halfOf (scene, 0, false).size());
  const mid::ObjectModel model =
      modelWithRepeat (scene, repeatOn (scene, 0, 0.02f, 3.0f), true);
  const auto [instances, removed] = filtered (filterIn (scene), model);
  EXPECT_EQ (removed, 1u);
  ASSERT_EQ (instances.size(), 2u);
  // The half of box 0 with more keypoints stays, then the copy on box 1.
  const bool low_first =
      halfOf (scene, 0, true).size() > halfOf (scene, 0, false).size();
  EXPECT_EQ (instances[0].keypoints, model.instances[low_first ? 0 : 1].keypoints);
  EXPECT_EQ (scene.boxOf (instances[1].keypoints), 1);
}

TEST (RepeatedPrintFilter, MeasuresOnASupportPlaneGivenInsteadOfFittingOne)
{
  // The plane the pipeline fits once for its three box steps: the same removal as the
  // filter's own fit; a zero plane (a frame without one) measures nothing; reset, it fits again.
  const Boxes scene (twoApart());
  const mid::ObjectModel model =
      modelWithRepeat (scene, repeatOn (scene, 0, 0.02f, 3.0f), true);
  Eigen::Vector4f plane;
  ASSERT_TRUE (mid::fitSupportPlane (*scene.surface.organized,
                                     mid::kDefaultPlaneTolerance,
                                     mid::kMinSupportPlaneShare,
                                     plane));
  mid::RepeatedPrintFilter filter = filterIn (scene);
  filter.setSupportPlane (plane);
  EXPECT_EQ (filter.getSupportPlane(), plane);
  const auto given = filtered (filter, model);
  EXPECT_EQ (given.second, 1u);
  EXPECT_EQ (given.first.size(), 2u);

  filter.setSupportPlane (Eigen::Vector4f::Zero());
  const auto none = filtered (filter, model);
  EXPECT_EQ (none.second, 0u);
  EXPECT_EQ (none.first.size(), model.instances.size());

  filter.resetSupportPlane();
  EXPECT_TRUE (filter.getSupportPlane().isZero());
  EXPECT_EQ (filtered (filter, model).second, 1u);
}

TEST (RepeatedPrintFilter, RemovesAnInstanceAtTheSamePlace)
{
  // A second instance of box 0 at its very pose (no shift, so no direction to measure the
  // box's width along) observing part of its keypoints; the copy on box 1 stays.
  const Boxes scene (twoApart());
  mid::ObjectModel model =
      modelWithRepeat (scene, repeatOn (scene, 0, 0.0f, 0.0f), true);
  const auto [instances, removed] = filtered (filterIn (scene), model);
  EXPECT_EQ (removed, 1u);
  ASSERT_EQ (instances.size(), 2u);
  EXPECT_EQ (scene.boxOf (instances[1].keypoints), 1);
}

TEST (RepeatedPrintFilter, RemovesAModelOfRepeatsAlone)
{
  const Boxes scene (twoApart());
  const auto [instances, removed] =
      filtered (filterIn (scene),
                modelWithRepeat (scene, repeatOn (scene, 0, 0.02f, 0.0f), false));
  // The repeat goes, then the model with its last instance: both count as removed.
  EXPECT_EQ (removed, 2u);
  EXPECT_TRUE (instances.empty());
}

TEST (RepeatedPrintFilter, KeepsTurnedInstancesUnlessTurnsAreAllowed)
{
  // The second instance lies on the same box but turned by a quarter turn: no repeat of a
  // print along one face.
  const Boxes scene (twoApart());
  const mid::ObjectModel model =
      modelWithRepeat (scene, repeatOn (scene, 0, 0.02f, 90.0f), false);
  EXPECT_EQ (filtered (filterIn (scene), model).second, 0u);
  mid::RepeatedPrintFilter any_turn = filterIn (scene);
  any_turn.setMaxRotation (static_cast<float> (M_PI));
  EXPECT_EQ (filtered (any_turn, model).second, 2u); // the repeat, then the model
}

TEST (RepeatedPrintFilter, KeepsAnInstanceWhoseKeypointsLieOnAnotherBox)
{
  // The second instance's pose is a small shift of the first's, but what it observes lies
  // on box 1: not the object the first lies on.
  const Boxes scene (twoApart());
  mid::ObjectModel model = scene.modelOf ({0});
  model.instances.push_back (
      instanceAt (repeatOn (scene, 0, 0.02f, 0.0f), scene.on ({1}), model));
  EXPECT_EQ (filtered (filterIn (scene), model).second, 0u);
  mid::RepeatedPrintFilter anywhere = filterIn (scene);
  anywhere.setMinInsideShare (0.0f);
  EXPECT_EQ (filtered (anywhere, model).second, 2u); // the repeat, then the model
}

TEST (RepeatedPrintFilter, KeepsTouchingCopiesThatLieAlike)
{
  // The two copies' tops join into one surface, so the box grown from one holds the other's
  // keypoints; they lie a copy's width (0.09 m) apart.
  const Boxes scene (twoTouchingAlike());
  const mid::ObjectModel model = scene.modelOf ({0, 1});
  const auto [instances, removed] = filtered (filterIn (scene), model);
  EXPECT_EQ (removed, 0u);
  EXPECT_EQ (instances.size(), 2u);
  // Both shift bounds keep them (0.09 m against 0.75 x 0.04 m and 0.25 x 0.18 m): with either
  // loosened they stay, with both loosened the model of the two is taken for a repeat.
  mid::RepeatedPrintFilter far_edges = filterIn (scene);
  far_edges.setMaxShiftRatio (10.0f);
  EXPECT_EQ (filtered (far_edges, model).second, 0u);
  mid::RepeatedPrintFilter far_width = filterIn (scene);
  far_width.setMaxShiftAlongWidth (10.0f);
  EXPECT_EQ (filtered (far_width, model).second, 0u);
  mid::RepeatedPrintFilter far = filterIn (scene);
  far.setMaxShiftRatio (10.0f);
  far.setMaxShiftAlongWidth (10.0f);
  EXPECT_EQ (filtered (far, model).second, 2u);
}

TEST (RepeatedPrintFilter, KeepsThinCopiesStandingSideBySide)
{
  // Two boxes standing on their 0.12 x 0.04 face, touching along it like books: their tops
  // join into a 0.12 x 0.08 face, the box of both is 0.08 thick, and the copies lie 0.04 m
  // apart, less than 0.75 x 0.08 m. The box's width along the shift (0.08 m) keeps them.
  const Eigen::Vector3d standing (0.12, 0.04, 0.09);
  const Boxes scene ({restingBox (kSoyPrint, 0.0, 0.1, 0.0, standing),
                      restingBox (kSoyPrint, 0.0, 0.14, 0.0, standing)});
  const mid::ObjectModel model = scene.modelOf ({0, 1});
  const auto [instances, removed] = filtered (filterIn (scene), model);
  EXPECT_EQ (removed, 0u);
  EXPECT_EQ (instances.size(), 2u);
  mid::RepeatedPrintFilter far_width = filterIn (scene);
  far_width.setMaxShiftAlongWidth (10.0f);
  EXPECT_EQ (filtered (far_width, model).second, 2u);
}

TEST (RepeatedPrintFilter, RefusesBadInputAndLeavesTheModels)
{
  const Boxes scene (twoApart());
  const mid::ObjectModel model =
      modelWithRepeat (scene, repeatOn (scene, 0, 0.02f, 0.0f), true);
  const auto refused = [&model] (const mid::RepeatedPrintFilter& filter) {
    mid::ObjectModels models = {model};
    std::size_t removed = 7;
    EXPECT_FALSE (filter.filter (models, removed));
    EXPECT_EQ (removed, 0u);
    ASSERT_EQ (models.size(), 1u);
    EXPECT_EQ (models[0].instances.size(), model.instances.size());
  };
  refused (mid::RepeatedPrintFilter()); // no keypoints, no surface
  mid::RepeatedPrintFilter turn = filterIn (scene);
  turn.setMaxRotation (4.0f);
  refused (turn);
  mid::RepeatedPrintFilter shift = filterIn (scene);
  shift.setMaxShiftRatio (-1.0f);
  refused (shift);
  mid::RepeatedPrintFilter along = filterIn (scene);
  along.setMaxShiftAlongWidth (std::numeric_limits<float>::quiet_NaN());
  refused (along);
  mid::RepeatedPrintFilter share = filterIn (scene);
  share.setMinInsideShare (1.5f);
  refused (share);
  mid::RepeatedPrintFilter step = filterIn (scene);
  step.setMaxStep (0.0f);
  refused (step);
  mid::RepeatedPrintFilter tilted = filterIn (scene);
  tilted.setSupportPlane (Eigen::Vector4f (0.0f, 2.0f, 0.0f, 1.0f)); // no unit normal
  refused (tilted);
  mid::RepeatedPrintFilter broken = filterIn (scene);
  broken.setSupportPlane (
      Eigen::Vector4f (0.0f, 1.0f, 0.0f, std::numeric_limits<float>::quiet_NaN()));
  refused (broken);

  mid::ObjectModels outside = {model};
  outside[0].instances[1].keypoints.push_back (
      static_cast<pcl::index_t> (scene.keypoints->size()));
  std::size_t removed = 0;
  EXPECT_FALSE (filterIn (scene).filter (outside, removed));
  EXPECT_EQ (outside[0].instances.size(), model.instances.size());
}
