// SupportPrintFilter on rendered boxes resting on a table at known poses, some of them sheets
// lying flat on it.
#include "resting_boxes.h"

#include <mid/segmentation/support_print_filter.h>

#include <gtest/gtest.h>

#include <limits>
#include <vector>

namespace {

using Boxes = mid::test::RestingBoxes;

/** fourBoxes() with boxes 2 and 3 of the given thickness (metres) on the table. */
std::vector<mid::test::BoxSpec>
fourBoxesWithThin2And3 (double thickness)
{
  return mid::test::fourBoxes (Eigen::Vector3d (0.12, 0.09, thickness));
}

mid::SupportPrintFilter
filterFor (const Boxes& scene)
{
  return mid::test::measuringStep<mid::SupportPrintFilter> (scene);
}

/** The box each instance of `model` lies on (its keypoints), in order. */
std::vector<int>
boxesOf (const Boxes& scene, const mid::ObjectModel& model)
{
  std::vector<int> boxes;
  for (const auto& instance : model.instances)
    boxes.push_back (scene.boxOf (instance.keypoints));
  return boxes;
}

} // namespace

TEST (SupportPrintFilter, RemovesAModelOfSheetsLyingOnTheTable)
{
  // Boxes 0 and 1 stand 4 cm off the table; 2 and 3 are sheets 2 mm thick lying on it.
  const Boxes scene (fourBoxesWithThin2And3 (0.002));
  mid::ObjectModels models = {scene.modelOf ({0, 1}), scene.modelOf ({2, 3})};
  ASSERT_FALSE (models[1].instances[0].keypoints.empty());
  std::size_t removed = 0;
  ASSERT_TRUE (filterFor (scene).filter (models, removed));
  EXPECT_EQ (removed, 2u);
  ASSERT_EQ (models.size(), 1u);
  EXPECT_EQ (boxesOf (scene, models[0]), (std::vector<int>{0, 1}));
}

TEST (SupportPrintFilter, RemovesTheInstanceOnASheetAndKeepsTheCopiesOffTheTable)
{
  const Boxes scene (fourBoxesWithThin2And3 (0.002));
  mid::ObjectModels models = {scene.modelOf ({0, 2, 1})};
  std::size_t removed = 0;
  ASSERT_TRUE (filterFor (scene).filter (models, removed));
  EXPECT_EQ (removed, 1u);
  ASSERT_EQ (models.size(), 1u);
  EXPECT_EQ (boxesOf (scene, models[0]), (std::vector<int>{0, 1})); // in their order
}

TEST (SupportPrintFilter, AThinObjectIsAPrintOnlyWithinThePlaneTolerance)
{
  // Boxes 2 and 3 are 15 mm thick: their tops stand off the table by more than the default
  // 1 cm, and lie within a 2 cm tolerance.
  const Boxes scene (fourBoxesWithThin2And3 (0.015));
  const mid::ObjectModels original = {scene.modelOf ({0, 1}), scene.modelOf ({2, 3})};
  mid::SupportPrintFilter filter = filterFor (scene);
  EXPECT_FLOAT_EQ (filter.getPlaneTolerance(), 0.01f);
  mid::ObjectModels models = original;
  std::size_t removed = 0;
  ASSERT_TRUE (filter.filter (models, removed));
  EXPECT_EQ (removed, 0u);
  EXPECT_EQ (models.size(), 2u);

  filter.setPlaneTolerance (0.02f);
  models = original;
  ASSERT_TRUE (filter.filter (models, removed));
  EXPECT_EQ (removed, 2u);
  ASSERT_EQ (models.size(), 1u);
  EXPECT_EQ (boxesOf (scene, models[0]), (std::vector<int>{0, 1}));
}

TEST (SupportPrintFilter, AnInstanceHalfOnASheetIsAPrintOnlyBelowItsShare)
{
  // One instance holds the keypoints of box 0 and of sheet 2: it is a print when the share
  // of its keypoints on the table reaches the smallest share asked for.
  const Boxes scene (fourBoxesWithThin2And3 (0.002));
  mid::ObjectModel model = scene.modelOf ({0, 1, 2});
  const mid::ModelInstance sheet = model.instances[2];
  model.instances.pop_back();
  auto& mixed = model.instances[0];
  const double on_sheet =
      static_cast<double> (sheet.keypoints.size()) /
      static_cast<double> (mixed.keypoints.size() + sheet.keypoints.size());
  mixed.keypoints.insert (
      mixed.keypoints.end(), sheet.keypoints.begin(), sheet.keypoints.end());
  mixed.landmarks.insert (
      mixed.landmarks.end(), sheet.landmarks.begin(), sheet.landmarks.end());
  ASSERT_GT (on_sheet, 0.05);
  ASSERT_LT (on_sheet, 0.95);

  mid::SupportPrintFilter filter = filterFor (scene);
  for (const double share : {on_sheet - 0.02, on_sheet + 0.02}) {
    filter.setMinShareOnPlane (static_cast<float> (share));
    mid::ObjectModels models = {model};
    std::size_t removed = 0;
    ASSERT_TRUE (filter.filter (models, removed));
    // Below the share on the sheet the mixed instance goes, and the model of one copy left.
    EXPECT_EQ (removed, share < on_sheet ? 2u : 0u) << share;
    EXPECT_EQ (models.size(), share < on_sheet ? 0u : 1u) << share;
  }
}

TEST (SupportPrintFilter, KeepsTheCopiesOnWhoseTopsThePlaneLies)
{
  // The plane given is the top of boxes 0 and 1 (4 cm off the table), as fitted where their
  // tops fill the view; boxes 2 and 3 (8 cm) stand in front of it. The keypoints of 0 and 1
  // lie in the plane, but the surface around them falls away to the table: no print.
  const Boxes scene (fourBoxesWithThin2And3 (0.08));
  mid::SupportPrintFilter filter = filterFor (scene);
  const auto top = static_cast<float> (mid::test::kTableDepth - 0.04);
  filter.setSupportPlane (Eigen::Vector4f (0.0f, 0.0f, -1.0f, top));
  mid::ObjectModels models = {scene.modelOf ({0, 1}), scene.modelOf ({2, 3})};
  std::size_t removed = 0;
  ASSERT_TRUE (filter.filter (models, removed));
  EXPECT_EQ (removed, 0u);
  EXPECT_EQ (models.size(), 2u);
}

TEST (SupportPrintFilter, LeavesSheetsWhenNothingStandsOnTheTable)
{
  // Nothing found stands off the plane: it is not seen to support anything (it may be a layer
  // of tops seen from above), so its prints are left.
  const Boxes scene (fourBoxesWithThin2And3 (0.002));
  mid::ObjectModels models = {scene.modelOf ({2, 3})};
  std::size_t removed = 0;
  ASSERT_TRUE (filterFor (scene).filter (models, removed));
  EXPECT_EQ (removed, 0u);
  ASSERT_EQ (models.size(), 1u);
  EXPECT_EQ (models[0].instances.size(), 2u);
}

TEST (SupportPrintFilter, LeavesPrintsOnAPlaneWithFoundObjectsBehindIt)
{
  // Sheets 0 and 1 lie on the top of a large flat box 2 (5 cm); boxes 3 and 4 (10 cm) stand
  // on the table in front of that top, boxes 5 and 6 (2 cm) on the table behind it. The plane
  // given is the large box's top.
  const double table = mid::test::kTableDepth;
  const double top = table - 0.05;
  const Eigen::Vector3d sheet (0.09, 0.07, 0.002), tall (0.09, 0.07, 0.10),
      flat (0.09, 0.07, 0.02);
  using mid::test::boxPose;
  const std::vector<mid::test::BoxSpec> boxes = {
      {mid::test::kSoyPrint, sheet, boxPose (-0.06, -0.03, top - 0.001, 10.0)},
      {mid::test::kSoyPrint, sheet, boxPose (0.07, 0.04, top - 0.001, -30.0)},
      {mid::test::kApplePrint,
       Eigen::Vector3d (0.36, 0.26, 0.05),
       boxPose (0.0, 0.0, table - 0.025, 0.0)},
      mid::test::restingBox (mid::test::kApplePrint, -0.3, -0.2, 20.0, tall),
      mid::test::restingBox (mid::test::kApplePrint, 0.3, -0.2, -20.0, tall),
      mid::test::restingBox (mid::test::kApplePrint, -0.3, 0.2, 60.0, flat),
      mid::test::restingBox (mid::test::kApplePrint, 0.3, 0.2, -60.0, flat)};
  const Boxes scene (boxes);
  mid::SupportPrintFilter filter = filterFor (scene);
  filter.setSupportPlane (
      Eigen::Vector4f (0.0f, 0.0f, -1.0f, static_cast<float> (top)));
  const mid::ObjectModel sheets = scene.modelOf ({0, 1});
  ASSERT_FALSE (sheets.instances[0].keypoints.empty());
  ASSERT_FALSE (sheets.instances[1].keypoints.empty());

  // With only the tall boxes found, the plane supports them and the sheets are prints on it.
  mid::ObjectModels models = {sheets, scene.modelOf ({3, 4})};
  std::size_t removed = 0;
  ASSERT_TRUE (filter.filter (models, removed));
  EXPECT_EQ (removed, 2u);
  ASSERT_EQ (models.size(), 1u);
  EXPECT_EQ (boxesOf (scene, models[0]), (std::vector<int>{3, 4}));

  // With the flat boxes found as well, objects lie beyond the plane: it is no table.
  models = {sheets, scene.modelOf ({3, 4}), scene.modelOf ({5, 6})};
  ASSERT_TRUE (filter.filter (models, removed));
  EXPECT_EQ (removed, 0u);
  EXPECT_EQ (models.size(), 3u);
}

TEST (SupportPrintFilter, LeavesTheModelsOfAFrameWithoutASupportPlane)
{
  const Boxes scene (fourBoxesWithThin2And3 (0.002));
  mid::SupportPrintFilter filter = filterFor (scene);
  filter.setSupportPlane (Eigen::Vector4f::Zero()); // given as: the frame has none
  mid::ObjectModels models = {scene.modelOf ({2, 3})};
  std::size_t removed = 0;
  ASSERT_TRUE (filter.filter (models, removed));
  EXPECT_EQ (removed, 0u);
  ASSERT_EQ (models.size(), 1u);
  EXPECT_EQ (models[0].instances.size(), 2u);
}

TEST (SupportPrintFilter, RefusesBadInputAndLeavesTheModels)
{
  const Boxes scene (fourBoxesWithThin2And3 (0.002));
  const mid::ObjectModels original = {scene.modelOf ({2, 3})};
  const auto refuses = [&] (const mid::SupportPrintFilter& filter) {
    mid::ObjectModels models = original;
    std::size_t removed = std::numeric_limits<std::size_t>::max();
    EXPECT_FALSE (filter.filter (models, removed));
    EXPECT_EQ (removed, 0u);
    ASSERT_EQ (models.size(), 1u);
    EXPECT_EQ (models[0].instances.size(), 2u);
  };
  for (const float share :
       {0.0f, -0.5f, 1.5f, std::numeric_limits<float>::quiet_NaN()}) {
    mid::SupportPrintFilter filter = filterFor (scene);
    filter.setMinShareOnPlane (share);
    refuses (filter);
  }
  mid::SupportPrintFilter no_keypoints = filterFor (scene);
  no_keypoints.setInputKeypoints (nullptr);
  refuses (no_keypoints);
  mid::SupportPrintFilter no_tolerance = filterFor (scene);
  no_tolerance.setPlaneTolerance (0.0f);
  refuses (no_tolerance);
}
