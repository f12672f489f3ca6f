// SizeInstanceSearch on rendered boxes resting on a table at known poses: copies that show
// none of a model's landmarks, found by the size of their box.
#include "resting_boxes.h"

#include <mid/segmentation/photometric_verification.h>
#include <mid/segmentation/size_instance_search.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <vector>

namespace {

using mid::test::fourBoxes;
using mid::test::kApplePrint;
using mid::test::kSoyPrint;
using mid::test::restingBox;
using mid::test::rotationErrorModuloBox;
using mid::test::twoApartTwoTouching;
using Boxes = mid::test::RestingBoxes;

/** Edges 0.12 (x), 0.04 and 0.09: the printed box lying on its 0.12 x 0.04 face. */
const Eigen::Vector3d kOnSide (0.12, 0.04, 0.09);

/** Boxes 0 and 1 lie flat with one print; box 2 is the same box on its side with another
  * print, so that no descriptor links it to them.
  */
std::vector<mid::test::BoxSpec>
twoFlatOneOnItsSide ()
{
  return {restingBox (kApplePrint, -0.16, -0.1, 10.0),
          restingBox (kApplePrint, 0.16, -0.12, -35.0),
          restingBox (kSoyPrint, 0.0, 0.12, 70.0, kOnSide)};
}

mid::SizeInstanceSearch
searchIn (const Boxes& scene)
{
  return mid::test::describingStep<mid::SizeInstanceSearch> (scene);
}

/** The search adds nothing: it succeeds, counts none and leaves the model as it was. */
void
expectNothingFound (const mid::SizeInstanceSearch& search,
                    const mid::ObjectModel& model)
{
  mid::ObjectModels models = {model};
  std::size_t found = std::numeric_limits<std::size_t>::max();
  ASSERT_TRUE (search.search (models, found));
  EXPECT_EQ (found, 0u);
  ASSERT_EQ (models.size(), 1u);
  EXPECT_EQ (models[0].instances.size(), model.instances.size());
  EXPECT_EQ (models[0].landmarks.size(), model.landmarks.size());
}

/** `copy`, an instance of a model in the frame of flat box 0, lies on box 2 (lying on its
  * side) at its pose, up to the box's symmetries (3 deg, 4 mm): box 0's axes x (0.12), y
  * (0.09), z (0.04) are box 2's x, z and -y.
  */
void
expectPoseOfTheBoxOnItsSide (const Boxes& scene, const mid::ModelInstance& copy)
{
  Eigen::Matrix3d flat_in_side;
  flat_in_side << 1, 0, 0, 0, 0, -1, 0, 1, 0;
  Eigen::Isometry3d truth = scene.scene.boxes[2].pose;
  truth.linear() = truth.linear() * flat_in_side;
  EXPECT_LT (rotationErrorModuloBox (copy.pose, truth), 3.0);
  EXPECT_LT (
      (copy.pose.topRightCorner<3, 1>() - truth.translation().cast<float>()).norm(),
      0.004f);
}

} // namespace

TEST (SizeInstanceSearch, FindsACopyShowingAnotherFaceUpByItsSize)
{
  const Boxes scene (twoFlatOneOnItsSide());
  mid::ObjectModels models = {scene.modelOf ({0, 1})};
  const mid::ObjectModel before = models[0];
  std::size_t found = 0;
  ASSERT_TRUE (searchIn (scene).search (models, found));
  EXPECT_EQ (found, 1u);
  ASSERT_EQ (models.size(), 1u);
  ASSERT_EQ (models[0].instances.size(), 3u);
  for (std::size_t i = 0; i < 2; ++i)
    EXPECT_TRUE (models[0].instances[i].pose.isApprox (before.instances[i].pose));

  // The new instance observes keypoints of box 2 alone, most of them (not those in the
  // creases along its edges, where no surface grows), each a new landmark.
  const mid::ModelInstance& copy = models[0].instances[2];
  EXPECT_EQ (scene.boxOf (copy.keypoints), 2);
  EXPECT_GE (2 * copy.keypoints.size(), scene.on ({2}).size());
  EXPECT_EQ (models[0].landmarks.size(),
             before.landmarks.size() + copy.keypoints.size());
  EXPECT_EQ (models[0].descriptors.size(),
             before.descriptors.size() + copy.keypoints.size());
  // Its pose brings the model (box 0's frame) onto box 2, up to the box's symmetries.
  expectPoseOfTheBoxOnItsSide (scene, copy);

  // Box 2 now holds an instance: a second search adds none.
  expectNothingFound (searchIn (scene), models[0]);
}

TEST (SizeInstanceSearch, AddsNoCopyWhereTheModelHasOneAlready)
{
  // The model knows a copy on box 2 (at its true pose, up to the box's symmetries) that
  // observes none of its keypoints: they stay free, and their object has the model's size.
  // It is that copy seen again, not a second one.
  const Boxes scene (twoFlatOneOnItsSide());
  mid::ObjectModels models = {scene.modelOf ({0, 1})};
  std::size_t found = 0;
  ASSERT_TRUE (searchIn (scene).search (models, found));
  ASSERT_EQ (models[0].instances.size(), 3u);
  mid::ModelInstance known = models[0].instances[2];
  known.keypoints.clear();
  known.landmarks.clear();
  mid::ObjectModel model = scene.modelOf ({0, 1});
  model.instances.push_back (known);
  expectNothingFound (searchIn (scene), model);

  // Known 20 cm away from box 2, over the empty table, the copy on box 2 is found.
  model.instances.back().pose (1, 3) += 0.2f;
  models = {model};
  ASSERT_TRUE (searchIn (scene).search (models, found));
  EXPECT_EQ (found, 1u);
  ASSERT_EQ (models[0].instances.size(), 4u);
  EXPECT_EQ (scene.boxOf (models[0].instances[3].keypoints), 2);
  expectPoseOfTheBoxOnItsSide (scene, models[0].instances[3]);
}

TEST (SizeInstanceSearch, NeedsCopiesThatAgreeOnTheSizeAndKeypointsToReport)
{
  const Boxes scene (twoFlatOneOnItsSide());
  const mid::ObjectModel model = scene.modelOf ({0, 1});
  mid::SizeInstanceSearch three_agreeing = searchIn (scene);
  three_agreeing.setMinAgreeing (3);
  expectNothingFound (three_agreeing, model);
  mid::SizeInstanceSearch many_keypoints = searchIn (scene);
  many_keypoints.setMinKeypoints (static_cast<int> (scene.on ({2}).size()) + 1);
  expectNothingFound (many_keypoints, model);
}

TEST (SizeInstanceSearch, LeavesBoxesOfAnotherSizeAlone)
{
  const Boxes scene (fourBoxes ({0.1, 0.09, 0.04}));
  expectNothingFound (searchIn (scene), scene.modelOf ({0, 1}));
}

TEST (SizeInstanceSearch, CutsCopiesTouchingEachOtherFlushApart)
{
  // Boxes 2 and 3 have the model's size and touch along their long edges, neither found: their
  // tops join into one surface of twice the width, which the copies' rectangles cut apart.
  const Boxes scene (twoApartTwoTouching());
  mid::ObjectModels models = {scene.modelOf ({0, 1})};
  std::size_t found = 0;
  ASSERT_TRUE (searchIn (scene).search (models, found));
  EXPECT_EQ (found, 2u);
  ASSERT_EQ (models[0].instances.size(), 4u);
  std::set<int> boxes;
  for (std::size_t i = 2; i < 4; ++i) {
    const mid::ModelInstance& copy = models[0].instances[i];
    const int box = scene.boxOf (copy.keypoints);
    boxes.insert (box);
    ASSERT_GE (box, 2);
    const Eigen::Isometry3d& truth =
        scene.scene.boxes[static_cast<std::size_t> (box)].pose;
    EXPECT_LT (rotationErrorModuloBox (copy.pose, truth), 3.0);
    EXPECT_LT (
        (copy.pose.topRightCorner<3, 1>() - truth.translation().cast<float>()).norm(),
        0.006f);
  }
  EXPECT_EQ (boxes, (std::set<int>{2, 3}));

  // Two touching boxes of another size: the model's square rectangles (0.1 m) cover most of
  // their tops, but each part, measured on its own outline, is a box of 0.12 x 0.09 m.
  const Boxes other (twoApartTwoTouching ({0.1, 0.1, 0.04}));
  expectNothingFound (searchIn (other), other.modelOf ({0, 1}));
}

TEST (SizeInstanceSearch, MeasuresACopyTouchingAFoundOneOutsideTheFoundOnesBox)
{
  // Boxes 2 and 3 touch along their long edges, their tops one flat surface. Box 2 is a found
  // copy: its box (its pose times the model's box) holds its part of the surface, and box 3
  // is measured on the rest alone.
  const Boxes scene (twoApartTwoTouching());
  mid::ObjectModels models = {scene.modelOf ({0, 1, 2})};
  std::size_t found = 0;
  ASSERT_TRUE (searchIn (scene).search (models, found));
  EXPECT_EQ (found, 1u);
  ASSERT_EQ (models[0].instances.size(), 4u);
  const mid::ModelInstance& copy = models[0].instances[3];
  EXPECT_EQ (scene.boxOf (copy.keypoints), 3);
  const Eigen::Isometry3d& truth = scene.scene.boxes[3].pose;
  EXPECT_LT (rotationErrorModuloBox (copy.pose, truth), 3.0);
  EXPECT_LT (
      (copy.pose.topRightCorner<3, 1>() - truth.translation().cast<float>()).norm(),
      0.004f);

  // A shorter box in its place is no copy.
  std::vector<mid::test::BoxSpec> boxes = twoApartTwoTouching();
  boxes[3] = restingBox (kSoyPrint, 0.0, 0.19, 180.0, {0.09, 0.09, 0.04});
  const Boxes shorter (boxes);
  expectNothingFound (searchIn (shorter), shorter.modelOf ({0, 1, 2}));
}

TEST (SizeInstanceSearch, FindsACopyByTheBoxOfTheOneCopyMeasuredWhole)
{
  // Box 1, a found copy, lies across the frame's right border (at the boxes' tops, 0.91 m from
  // the camera, the frame shows x < 0.555 m): its box is measured 0.075 x 0.09 m, on a smaller
  // surface than box 0's. The two copies disagree (no size with two agreeing), and the
  // model's size is box 1's. Box 2, the same box on its side with another print, has box 0's
  // size: with box 0, two copies agree on it.
  std::vector<mid::test::BoxSpec> boxes = twoFlatOneOnItsSide();
  boxes[1] = restingBox (kApplePrint, 0.525, -0.12, 0.0);
  const Boxes scene (boxes);
  mid::ObjectModels models = {scene.modelOf ({0, 1})};
  mid::SizeInstanceSearch two_agreeing = searchIn (scene);
  two_agreeing.setMinAgreeing (2);
  expectNothingFound (two_agreeing, models[0]);

  std::size_t found = 0;
  ASSERT_TRUE (searchIn (scene).search (models, found));
  EXPECT_EQ (found, 1u);
  ASSERT_EQ (models[0].instances.size(), 3u);
  const mid::ModelInstance& copy = models[0].instances[2];
  EXPECT_EQ (scene.boxOf (copy.keypoints), 2);
  expectPoseOfTheBoxOnItsSide (scene, copy);

  // With a third copy whole, two agree on the model's size: the box of the one cut by the
  // border is no size of it, and a box of that size (box 2 cut to 0.075 m, as box 1 is
  // measured) is no copy.
  boxes.push_back (restingBox (kApplePrint, -0.3, 0.2, 50.0));
  boxes[2] = restingBox (kSoyPrint, 0.0, 0.12, 70.0, {0.075, 0.04, 0.09});
  const Boxes agreeing (boxes);
  expectNothingFound (searchIn (agreeing), agreeing.modelOf ({0, 1, 3}));
}

TEST (SizeInstanceSearch, RefusesBadInputAndLeavesTheModels)
{
  const Boxes scene (twoFlatOneOnItsSide());
  const mid::ObjectModels models = {scene.modelOf ({0, 1})};
  const auto refuses = [&models] (const mid::SizeInstanceSearch& search) {
    mid::ObjectModels copy = models;
    std::size_t found = 7;
    EXPECT_FALSE (search.search (copy, found));
    EXPECT_EQ (found, 0u);
    ASSERT_EQ (copy.size(), 1u);
    EXPECT_EQ (copy[0].instances.size(), models[0].instances.size());
    EXPECT_EQ (copy[0].landmarks.size(), models[0].landmarks.size());
  };
  mid::SizeInstanceSearch no_keypoints = searchIn (scene);
  no_keypoints.setInputKeypoints (nullptr);
  refuses (no_keypoints);
  mid::SizeInstanceSearch short_descriptors = searchIn (scene);
  auto fewer = pcl::make_shared<mid::SIFTDescriptorCloud> (*scene.descriptors);
  fewer->resize (fewer->size() - 1);
  short_descriptors.setInputDescriptors (fewer);
  refuses (short_descriptors);
  mid::SizeInstanceSearch no_pixels = searchIn (scene);
  mid::KeypointSurface surface = scene.surface;
  surface.keypoint_pixels.pop_back();
  no_pixels.setKeypointSurface (surface);
  refuses (no_pixels);
  mid::SizeInstanceSearch negative = searchIn (scene);
  negative.setSizeTolerance (-0.001f, 0.03f);
  refuses (negative);
  mid::SizeInstanceSearch no_step = searchIn (scene);
  no_step.setMaxStep (0.0f);
  refuses (no_step);
  mid::SizeInstanceSearch nobody = searchIn (scene);
  nobody.setMinKeypoints (0);
  refuses (nobody);
  mid::SizeInstanceSearch crowded = searchIn (scene);
  crowded.setMaxSurroundedShare (1.5f);
  refuses (crowded);
  mid::SizeInstanceSearch no_edge = searchIn (scene);
  no_edge.setMinModelEdge (-0.01f);
  refuses (no_edge);

  mid::ObjectModels outside = models;
  outside[0].instances[0].keypoints.push_back (
      static_cast<pcl::index_t> (scene.keypoints->size()));
  outside[0].instances[0].landmarks.push_back (0);
  std::size_t found = 7;
  EXPECT_FALSE (searchIn (scene).search (outside, found));
  EXPECT_EQ (found, 0u);
}

namespace {

/** Boxes 0 and 1 share a size but not a print; box 2 has the first print and another size. */
std::vector<mid::test::BoxSpec>
twoOfOneSizeOneOfAnother ()
{
  return {restingBox (kApplePrint, -0.16, -0.1, 10.0),
          restingBox (kSoyPrint, 0.16, -0.12, -35.0),
          restingBox (kApplePrint, 0.0, 0.13, 60.0, {0.1, 0.07, 0.05})};
}

/** searchIn(), making models by size too. */
mid::SizeInstanceSearch
discoveringSearchIn (const Boxes& scene)
{
  mid::SizeInstanceSearch search = searchIn (scene);
  search.setDiscoverModels (true);
  return search;
}

/** Search with no model to start from, making models by size. */
mid::ObjectModels
discoverBySize (const mid::SizeInstanceSearch& search, std::size_t& found)
{
  mid::ObjectModels models;
  EXPECT_TRUE (search.search (models, found));
  return models;
}

/** The box that 95 % of `keypoints` at least lie on, -1 if none: a cut between copies
  * touching each other may give one on the seam to the neighbour.
  */
int
mostlyOnBox (const Boxes& scene, const pcl::Indices& keypoints)
{
  std::map<int, std::size_t> count;
  for (const auto k : keypoints)
    ++count[scene.box_of[static_cast<std::size_t> (k)]];
  for (const auto& [box, n] : count)
    if (box >= 0 &&
        static_cast<double> (n) >= 0.95 * static_cast<double> (keypoints.size()))
      return box;
  return -1;
}

/** Each instance of `model` lies on a box of `scene` (mostlyOnBox()), and its pose relative
  * to the first instance is the boxes' own, up to the box's symmetries (3 deg): it moves the
  * first box's centre onto the other's (within `tolerance` metres). Returns the boxes, one per
  * instance, -1 for none.
  */
std::vector<int>
expectPosesRelativeToTheFirst (const Boxes& scene,
                               const mid::ObjectModel& model,
                               float tolerance)
{
  std::vector<int> boxes;
  for (const auto& instance : model.instances)
    boxes.push_back (mostlyOnBox (scene, instance.keypoints));
  if (boxes.empty() || boxes.front() < 0) {
    ADD_FAILURE() << "the first instance lies on no box";
    return boxes;
  }
  const Eigen::Isometry3d& a =
      scene.scene.boxes[static_cast<std::size_t> (boxes.front())].pose;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    if (boxes[i] < 0) {
      ADD_FAILURE() << "instance " << i << " lies on no box";
      continue;
    }
    const Eigen::Isometry3d& b =
        scene.scene.boxes[static_cast<std::size_t> (boxes[i])].pose;
    const Eigen::Matrix4f relative =
        model.instances[i].pose * model.instances[0].pose.inverse();
    EXPECT_LT (rotationErrorModuloBox (relative * a.matrix().cast<float>(), b), 3.0);
    const Eigen::Vector3f moved =
        relative.topLeftCorner<3, 3>() * a.translation().cast<float>() +
        relative.topRightCorner<3, 1>();
    EXPECT_LT ((moved - b.translation().cast<float>()).norm(), tolerance);
  }
  return boxes;
}

/** With no model to start from, `search` makes one model of exactly the boxes `expected` of
  * `scene`, posed relative to the first as the boxes are (expectPosesRelativeToTheFirst()).
  */
void
expectOneModelOfBoxes (const Boxes& scene,
                       const mid::SizeInstanceSearch& search,
                       const std::set<int>& expected,
                       float tolerance = 0.006f)
{
  std::size_t found = 0;
  const mid::ObjectModels models = discoverBySize (search, found);
  ASSERT_EQ (models.size(), 1u);
  EXPECT_EQ (found, expected.size());
  ASSERT_EQ (models[0].instances.size(), expected.size());
  const std::vector<int> boxes =
      expectPosesRelativeToTheFirst (scene, models[0], tolerance);
  EXPECT_EQ (std::set<int> (boxes.begin(), boxes.end()), expected);
}

} // namespace

TEST (SizeInstanceSearch, MakesAModelOfObjectsOfOneSizeStandingAlone)
{
  const Boxes scene (twoOfOneSizeOneOfAnother());
  mid::SizeInstanceSearch search = searchIn (scene);
  std::size_t found = 0;
  EXPECT_TRUE (discoverBySize (search, found).empty()); // not asked for
  EXPECT_EQ (found, 0u);

  search.setDiscoverModels (true);
  expectOneModelOfBoxes (scene, search, {0, 1}, 0.005f);

  // Objects whose shortest edge (0.04 here) is below the smallest a model may have.
  search.setMinModelEdge (0.05f);
  EXPECT_TRUE (discoverBySize (search, found).empty());
}

namespace {

/** discoveringSearchIn(), with the frame's chromaticities, which the looser agreement of two
  * objects' sizes needs; box `tinted` (if >= 0) recoloured blue, its grey levels kept
  * (tintKeepingGreyLevels()): the same keypoints, other colours.
  */
mid::SizeInstanceSearch
discoveringSearchInColour (const Boxes& scene, int tinted = -1)
{
  mid::SizeInstanceSearch search = discoveringSearchIn (scene);
  pcl::PointCloud<pcl::PointXYZRGB> colour;
  pcl::copyPointCloud (*scene.scene.cloud, colour);
  if (tinted >= 0) {
    EXPECT_GT (mid::test::tintKeepingGreyLevels (scene.scene, tinted, colour), 1000u);
  }
  mid::KeypointSurface surface = scene.surface;
  surface.chromaticity = std::make_shared<const std::vector<mid::Chromaticity>> (
      mid::chromaticities (colour));
  search.setKeypointSurface (surface);
  return search;
}

/** Box 0 flat, box 1 of its print `higher` metres higher, and box 2 of another size. */
std::vector<mid::test::BoxSpec>
twoALittleApart (double higher)
{
  return {restingBox (kApplePrint, -0.16, -0.1, 10.0),
          restingBox (kApplePrint, 0.16, -0.12, -35.0, {0.12, 0.09, 0.04 + higher}),
          restingBox (kApplePrint, 0.0, 0.13, 60.0, {0.1, 0.07, 0.05})};
}

} // namespace

TEST (SizeInstanceSearch,
      PairsTwoObjectsThatNoOtherAgreesWithAtALooserToleranceIfTheyLookAlike)
{
  // 7.5 mm higher: beyond the 6 mm tolerance, within 1.5 times it, as a copy measured a
  // little off would be.
  const Boxes scene (twoALittleApart (0.0075));
  expectOneModelOfBoxes (scene, discoveringSearchInColour (scene), {0, 1});

  std::size_t found = 0;
  // Without colours, nothing says that the two look alike.
  EXPECT_TRUE (discoverBySize (discoveringSearchIn (scene), found).empty());
  // 10 mm higher (1.67 times the tolerance), the two are boxes of two sizes.
  const Boxes apart (twoALittleApart (0.01));
  EXPECT_TRUE (discoverBySize (discoveringSearchInColour (apart), found).empty());
  // In other colours, the two are two products.
  EXPECT_TRUE (discoverBySize (discoveringSearchInColour (scene, 1), found).empty());
  EXPECT_EQ (found, 0u);
}

TEST (SizeInstanceSearch, CutsCopiesTouchingFlushByTheSizeOfCopiesStandingAlone)
{
  // Boxes 0 and 1 stand alone and agree on their size; boxes 2 and 3, of that size, touch
  // flush, and their joined top is cut into copies of it. No model to start from.
  const Boxes scene (twoApartTwoTouching());
  expectOneModelOfBoxes (scene, discoveringSearchIn (scene), {0, 1, 2, 3});
  std::size_t found = 0;

  // The boxes standing alone of another size: the touching ones are not cut into them.
  const Boxes other (twoApartTwoTouching ({0.1, 0.1, 0.04}));
  mid::SizeInstanceSearch other_search = discoveringSearchIn (other);
  const mid::ObjectModels alone = discoverBySize (other_search, found);
  ASSERT_EQ (alone.size(), 1u);
  EXPECT_EQ (found, 2u);
  std::set<int> alone_boxes;
  for (const auto& instance : alone[0].instances)
    alone_boxes.insert (other.boxOf (instance.keypoints));
  EXPECT_EQ (alone_boxes, (std::set<int>{0, 1}));
}

TEST (SizeInstanceSearch, MakesNoModelOfObjectsThatDoNotStandAloneWhenAsked)
{
  // The two copies of one size lie on a low tray, which surrounds them: their surfaces could
  // be fragments of a pile or a bin, and a search asked for objects standing alone (at most
  // a quarter of the pixels around them taken) makes no model of them.
  constexpr double kTray = 0.03;
  const auto on_tray = [] (const char* print, double x, double y, double roll) {
    return mid::test::BoxSpec{
        print,
        mid::test::kPrintedBoxSize,
        mid::test::boxPose (x,
                            y,
                            mid::test::kTableDepth - kTray -
                                0.5 * mid::test::kPrintedBoxSize.z(),
                            roll)};
  };
  const Boxes scene ({restingBox (kApplePrint, 0.0, 0.0, 0.0, {0.5, 0.3, kTray}),
                      on_tray (kApplePrint, -0.12, -0.04, 10.0),
                      on_tray (kSoyPrint, 0.12, 0.03, -20.0)});
  mid::SizeInstanceSearch search = discoveringSearchIn (scene);
  search.setMaxSurroundedShare (0.25f);
  std::size_t found = 0;
  EXPECT_TRUE (discoverBySize (search, found).empty());
  EXPECT_EQ (found, 0u);
  // The same copies with the surroundings ignored (the default): one model of the two.
  search.setMaxSurroundedShare (1.0f);
  const mid::ObjectModels models = discoverBySize (search, found);
  ASSERT_EQ (models.size(), 1u);
  ASSERT_EQ (models[0].instances.size(), 2u);
  std::set<int> boxes;
  for (const auto& instance : models[0].instances)
    boxes.insert (scene.boxOf (instance.keypoints));
  EXPECT_EQ (boxes, (std::set<int>{1, 2}));
}

TEST (SizeInstanceSearch, TallObjectsStandAloneThoughTheirSidesShow)
{
  // Two tall boxes of one size, far from the image centre: the camera sees their sides,
  // where the top's surface does not grow. Those points are the boxes' own, not something
  // they stand beside.
  const Eigen::Vector3d tall (0.12, 0.09, 0.12);
  const Boxes scene ({restingBox (kApplePrint, -0.24, -0.15, 10.0, tall),
                      restingBox (kSoyPrint, 0.24, 0.15, -35.0, tall)});
  mid::SizeInstanceSearch search = discoveringSearchIn (scene);
  std::size_t found = 0;
  const mid::ObjectModels models = discoverBySize (search, found);
  ASSERT_EQ (models.size(), 1u);
  EXPECT_EQ (found, 2u);
}

TEST (SizeInstanceSearch, CutsCopiesOfAnUnknownSizeTouchingShiftedByTheirOutline)
{
  // Two boxes of one size and two prints touch side by side, shifted along their length by
  // 5 cm: one object of no size seen elsewhere, whose footprint is no rectangle. No model to
  // start from.
  const Boxes scene ({restingBox (kApplePrint, 0.0, 0.1, 0.0),
                      restingBox (kSoyPrint, 0.05, 0.19, 180.0)});
  expectOneModelOfBoxes (scene, discoveringSearchIn (scene), {0, 1});
  std::size_t found = 0;

  // Not shifted, their footprint is a rectangle that one box could make: left whole.
  const Boxes flush ({restingBox (kApplePrint, 0.0, 0.1, 0.0),
                      restingBox (kSoyPrint, 0.0, 0.19, 180.0)});
  mid::SizeInstanceSearch flush_search = discoveringSearchIn (flush);
  EXPECT_TRUE (discoverBySize (flush_search, found).empty());
  EXPECT_EQ (found, 0u);

  // Shifted, but of two sizes: the parts do not agree.
  const Boxes two_sizes (
      {restingBox (kApplePrint, 0.0, 0.1, 0.0),
       restingBox (kSoyPrint, 0.05, 0.2, 180.0, {0.12, 0.11, 0.04})});
  mid::SizeInstanceSearch two_sizes_search = discoveringSearchIn (two_sizes);
  EXPECT_TRUE (discoverBySize (two_sizes_search, found).empty());
}

TEST (SizeInstanceSearch, CutsCopiesByTheirOutlineAroundAFoundCopy)
{
  // The two shifted copies above, and in the notch their footprint leaves, 1 cm from both, a
  // found copy of another model (a smaller, lower box): the box around the two holds its
  // keypoints,
  // the boxes of the two parts do not.
  const Boxes scene ({restingBox (kApplePrint, 0.0, 0.1, 0.0),
                      restingBox (kSoyPrint, 0.05, 0.19, 180.0),
                      restingBox (kApplePrint, 0.085, 0.1, 90.0, {0.06, 0.03, 0.02})});
  ASSERT_FALSE (scene.on ({2}).empty());
  mid::SizeInstanceSearch search = discoveringSearchIn (scene);
  mid::ObjectModels models = {scene.modelOf ({2})};
  std::size_t found = 0;
  ASSERT_TRUE (search.search (models, found));
  ASSERT_EQ (models.size(), 2u);
  EXPECT_EQ (models[0].instances.size(), 1u);
  EXPECT_EQ (found, 2u);
  ASSERT_EQ (models[1].instances.size(), 2u);
  const std::vector<int> boxes =
      expectPosesRelativeToTheFirst (scene, models[1], 0.006f);
  EXPECT_EQ (std::set<int> (boxes.begin(), boxes.end()), (std::set<int>{0, 1}));
}

TEST (SizeInstanceSearch, CopiesCutByTheirOutlineJoinTheModelOfTheirSize)
{
  // The scene above, and a third copy of the two's box standing apart, found: the two join
  // its model, in which no other model's found copy lies.
  const Boxes scene ({restingBox (kApplePrint, 0.0, 0.1, 0.0),
                      restingBox (kSoyPrint, 0.05, 0.19, 180.0),
                      restingBox (kApplePrint, 0.085, 0.1, 90.0, {0.06, 0.03, 0.02}),
                      restingBox (kApplePrint, -0.2, -0.12, 30.0)});
  mid::SizeInstanceSearch search = discoveringSearchIn (scene);
  mid::ObjectModels models = {scene.modelOf ({2}), scene.modelOf ({3})};
  std::size_t found = 0;
  ASSERT_TRUE (search.search (models, found));
  ASSERT_EQ (models.size(), 2u);
  EXPECT_EQ (found, 2u);
  EXPECT_EQ (models[0].instances.size(), 1u);
  ASSERT_EQ (models[1].instances.size(), 3u);
  const std::vector<int> boxes =
      expectPosesRelativeToTheFirst (scene, models[1], 0.006f);
  EXPECT_EQ (std::set<int> (boxes.begin(), boxes.end()), (std::set<int>{0, 1, 3}));
}

TEST (SizeInstanceSearch, FindsASecondCopyJoinedWithAnotherBoxByItsFlatTop)
{
  // A box standing alone, and a copy of it (another print) flush beside a box of another
  // size, 7 mm taller: the copy and that box grow into one object. Seen once, the first box's
  // size cuts no group of copies, but the copy's top shows at its height in the join.
  const Eigen::Vector3d taller (0.12, 0.07, 0.047);
  const Boxes scene ({restingBox (kApplePrint, -0.15, -0.1, 10.0),
                      restingBox (kSoyPrint, 0.1, 0.0, 0.0),
                      restingBox (kApplePrint, 0.1, 0.08, 0.0, taller)});
  const mid::SizeInstanceSearch search = discoveringSearchIn (scene);
  expectOneModelOfBoxes (scene, search, {0, 1});

  // With the first box found already, the copy joins its model.
  std::size_t found = 0;
  mid::ObjectModels found_first = {scene.modelOf ({0})};
  ASSERT_TRUE (search.search (found_first, found));
  ASSERT_EQ (found_first.size(), 1u);
  EXPECT_EQ (found, 1u);
  ASSERT_EQ (found_first[0].instances.size(), 2u);
  EXPECT_EQ (mostlyOnBox (scene, found_first[0].instances[1].keypoints), 1);

  // Beside a box of its own height, the copy's top runs into the other's: no part, no model.
  const Boxes level ({restingBox (kApplePrint, -0.15, -0.1, 10.0),
                      restingBox (kSoyPrint, 0.1, 0.0, 0.0),
                      restingBox (kApplePrint, 0.1, 0.08, 0.0, {0.12, 0.07, 0.04})});
  mid::SizeInstanceSearch level_search = discoveringSearchIn (level);
  EXPECT_TRUE (discoverBySize (level_search, found).empty());
  EXPECT_EQ (found, 0u);
}

namespace {

/** The table seen at 55 deg above it: the boxes' sides towards the camera show. */
constexpr double kViewTilt = 35.0;

/** Box 0 (50 x 60 x 150 mm) stands, and a box of its size but `lying_depth` deep (60 mm: a
  * copy, with another print) lies on its 50 x 150 face with an end against it, their sides
  * towards the camera in one plane: the standing box's top, their sides and the lying box's
  * top grow into one object, and no copy shows alone. Box 2, of another size, lies apart.
  */
std::vector<mid::test::BoxSpec>
standingAndLyingFlush (double lying_depth)
{
  constexpr double kSide = -0.05; // y of the sides in one plane
  const Eigen::Vector3d standing (0.05, 0.06, 0.15);
  std::vector<mid::test::BoxSpec> boxes = {
      restingBox (kApplePrint, 0.1, kSide + 0.5 * standing.y(), 0.0, standing),
      restingBox (kSoyPrint, 0.0, 0.0, 0.0, {0.05, lying_depth, 0.15}),
      restingBox (kApplePrint, -0.15, -0.1, 30.0, {0.1, 0.07, 0.05})};
  // Box 1 turned about y onto its side: its 150 mm edge along x, 50 mm high.
  boxes[1].pose =
      mid::test::boxPose (
          0.0, kSide + 0.5 * lying_depth, mid::test::kTableDepth - 0.025, 0.0) *
      Eigen::AngleAxisd (0.5 * M_PI, Eigen::Vector3d::UnitY());
  boxes[0].printed_all_around = boxes[1].printed_all_around = true;
  return boxes;
}

} // namespace

TEST (SizeInstanceSearch, FindsTwoCopiesJoinedWithEachOtherByTheirFlatTops)
{
  // Their tops, at two of the box's edges, say what the two boxes are.
  const Boxes scene (standingAndLyingFlush (0.06), mid::test::kTableDepth, kViewTilt);
  expectOneModelOfBoxes (scene, discoveringSearchIn (scene), {0, 1});

  // A lying box 15 mm deeper is no copy of the standing one.
  const Boxes other (standingAndLyingFlush (0.075), mid::test::kTableDepth, kViewTilt);
  std::size_t found = 0;
  EXPECT_TRUE (discoverBySize (discoveringSearchIn (other), found).empty());
  EXPECT_EQ (found, 0u);
}

namespace {

/** Box 0 lies whole; box 1, of its print and size but `length` long (its 0.12 m edge away from
  * the camera), lies behind box 2, a wall of another print 0.08 m high, 15 mm before its near
  * end (if `hiding`; else 0.3 m aside): seen at 55 deg, the wall hides box 1's near end.
  */
std::vector<mid::test::BoxSpec>
oneBehindAWall (double length, bool hiding)
{
  return {
      restingBox (kApplePrint, -0.15, 0.05, 90.0),
      restingBox (kApplePrint, 0.1, 0.11 - 0.5 * length, 90.0, {length, 0.09, 0.04}),
      restingBox (kSoyPrint, hiding ? 0.1 : -0.2, -0.05, 0.0, {0.14, 0.05, 0.08})};
}

} // namespace

TEST (SizeInstanceSearch, PairsACopyThatSomethingInFrontHidesInPart)
{
  // Box 1 measures about 90 of its 120 mm, no size of box 0's; its near end is hidden, and
  // its box completed beyond that end to box 0's length is a copy's, at its true place.
  const Boxes scene (oneBehindAWall (0.12, true), mid::test::kTableDepth, kViewTilt);
  expectOneModelOfBoxes (scene, discoveringSearchInColour (scene), {0, 1});

  std::size_t found = 0;
  // Without colours, nothing says that the two look alike.
  EXPECT_TRUE (discoverBySize (discoveringSearchIn (scene), found).empty());
  // A box 90 mm long in plain view is no copy.
  const Boxes shorter (oneBehindAWall (0.09, false), mid::test::kTableDepth, kViewTilt);
  EXPECT_TRUE (discoverBySize (discoveringSearchInColour (shorter), found).empty());
  EXPECT_EQ (found, 0u);
}

TEST (SizeInstanceSearch, AGroupOfOneSizeTakesACopyHiddenInPart)
{
  // Boxes 0 and 3 lie whole and agree on their size: their group takes box 1, hidden in part
  // behind the wall, with its box completed.
  std::vector<mid::test::BoxSpec> boxes = oneBehindAWall (0.12, true);
  boxes.push_back (restingBox (kApplePrint, -0.15, 0.25, 90.0));
  const Boxes scene (boxes, mid::test::kTableDepth, kViewTilt);
  expectOneModelOfBoxes (scene, discoveringSearchInColour (scene), {0, 1, 3});

  // In other colours, box 1 is left out of the group.
  expectOneModelOfBoxes (scene, discoveringSearchInColour (scene, 1), {0, 3});
}

TEST (SizeInstanceSearch, PairsACopyHiddenAtEitherEndBesideATallBox)
{
  // Seen from above, a box 0.25 m tall between the image centre and a lying copy's inner end
  // hides that end: on the right of the image its left end, on the left its right end.
  for (const double side : {1.0, -1.0}) {
    const Boxes scene (
        {restingBox (kApplePrint, 0.0, 0.15, 0.0),
         restingBox (kApplePrint, 0.2 * side, 0.0, 0.0),
         restingBox (kSoyPrint, 0.1 * side, 0.0, 0.0, {0.05, 0.14, 0.25})});
    SCOPED_TRACE (side);
    expectOneModelOfBoxes (scene, discoveringSearchInColour (scene), {0, 1});
  }
}

namespace {

/** `boxes`, lying along x, and after them a post of another print, 0.06 wide and 0.25 m tall,
  * 10 mm before the middle of a box lying at y = 0.03 (if `hiding`; else 0.35 m aside): seen
  * at 55 deg, the post hides such a box's middle.
  */
std::vector<mid::test::BoxSpec>
withAPost (std::vector<mid::test::BoxSpec> boxes, bool hiding)
{
  boxes.push_back (
      restingBox (kSoyPrint, hiding ? 0.1 : -0.25, -0.05, 0.0, {0.06, 0.05, 0.25}));
  return boxes;
}

} // namespace

TEST (SizeInstanceSearch, MakesNoModelOfTheTwoEndsOfOneBoxHiddenInTheMiddle)
{
  // A box 0.3 m long shows two ends of one print and one size on either side of the post, as
  // two copies lying in a row would: it is one box seen twice.
  const Boxes scene (
      withAPost ({restingBox (kApplePrint, 0.1, 0.03, 0.0, {0.3, 0.09, 0.04})}, true),
      mid::test::kTableDepth,
      kViewTilt);
  std::size_t found = 0;
  EXPECT_TRUE (discoverBySize (discoveringSearchInColour (scene), found).empty());
  EXPECT_EQ (found, 0u);

  // Two copies in the places of its ends are copies: in plain view (the post aside), and
  // behind the post off one line (the second 4 cm farther back).
  const Boxes row (withAPost ({restingBox (kApplePrint, 0.01, 0.03, 0.0),
                               restingBox (kApplePrint, 0.19, 0.03, 0.0)},
                              false),
                   mid::test::kTableDepth,
                   kViewTilt);
  expectOneModelOfBoxes (row, discoveringSearchInColour (row), {0, 1});
  const Boxes apart (withAPost ({restingBox (kApplePrint, 0.01, 0.03, 0.0),
                                 restingBox (kApplePrint, 0.19, 0.07, 0.0)},
                                true),
                     mid::test::kTableDepth,
                     kViewTilt);
  expectOneModelOfBoxes (apart, discoveringSearchInColour (apart), {0, 1});

  // Two copies in one line, their centres 0.48 m apart, each with a post (of two heights)
  // before its inner end, which hides part of it: the table shows between the posts, and the
  // two make a model.
  const Boxes posts ({restingBox (kApplePrint, -0.14, 0.03, 0.0),
                      restingBox (kApplePrint, 0.34, 0.03, 0.0),
                      restingBox (kSoyPrint, -0.06, -0.05, 0.0, {0.06, 0.05, 0.25}),
                      restingBox (kSoyPrint, 0.26, -0.05, 0.0, {0.06, 0.05, 0.22})},
                     mid::test::kTableDepth,
                     kViewTilt);
  const mid::ObjectModels models =
      discoverBySize (discoveringSearchInColour (posts), found);
  ASSERT_EQ (models.size(), 1u);
  ASSERT_EQ (models[0].instances.size(), 2u);
  std::set<int> boxes;
  for (const auto& instance : models[0].instances)
    boxes.insert (mostlyOnBox (posts, instance.keypoints));
  EXPECT_EQ (boxes, (std::set<int>{0, 1}));

  // Three tall copies standing in a row, 17 mm apart: the middle one stands between the outer
  // two, on the box they would make whole, not in front of it.
  const Eigen::Vector3d standing (0.083, 0.085, 0.241);
  const Boxes three ({restingBox (kApplePrint, -0.1, 0.03, 0.0, standing),
                      restingBox (kApplePrint, 0.0, 0.03, 0.0, standing),
                      restingBox (kApplePrint, 0.1, 0.03, 0.0, standing)},
                     mid::test::kTableDepth,
                     kViewTilt);
  expectOneModelOfBoxes (three, discoveringSearchInColour (three), {0, 1, 2});
}
