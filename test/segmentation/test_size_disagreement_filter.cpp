// SizeDisagreementFilter on rendered boxes resting on a table at known poses and sizes: a model
// of three products standing alone goes, a model of three copies of one box stays, and so does
// the model of three products when one of them is not alone or too few copies are judged.
#include "resting_boxes.h"

#include <mid/segmentation/size_disagreement_filter.h>

#include <gtest/gtest.h>

#include <limits>

namespace {

using Boxes = mid::test::RestingBoxes;
using mid::test::kApplePrint;
using mid::test::kSoyPrint;
using mid::test::restingBox;

// Three products that differ on every edge (edges ascending: 40/90/120, 60/80/150 and
// 50/70/200 mm), and a taller block.
const Eigen::Vector3d kSizeA{0.12, 0.09, 0.04};
const Eigen::Vector3d kSizeB{0.15, 0.08, 0.06};
const Eigen::Vector3d kSizeC{0.20, 0.07, 0.05};
const Eigen::Vector3d kBlock{0.20, 0.05, 0.10};

/** Boxes 0, 1, 2: three products (sizes A, B, C) standing alone in a row; boxes 3, 4, 5:
  * three copies of A standing alone in a second row; with `block_beside_2`, box 6, a taller
  * block, touches box 2 along its long side.
  */
std::vector<mid::test::BoxSpec>
twoRows (bool block_beside_2)
{
  std::vector<mid::test::BoxSpec> boxes = {
      restingBox (kApplePrint, -0.26, -0.14, 10.0, kSizeA),
      restingBox (kSoyPrint, 0.0, -0.14, -20.0, kSizeB),
      restingBox (kApplePrint, 0.26, -0.14, 0.0, kSizeC),
      restingBox (kApplePrint, -0.26, 0.14, 100.0, kSizeA),
      restingBox (kApplePrint, 0.0, 0.14, 30.0, kSizeA),
      restingBox (kApplePrint, 0.26, 0.14, -60.0, kSizeA)};
  if (block_beside_2) // flush against box 2's side towards the image's top
    boxes.push_back (restingBox (
        kSoyPrint, 0.26, -0.14 - 0.5 * (kSizeC.y() + kBlock.y()), 0.0, kBlock));
  return boxes;
}

mid::SizeDisagreementFilter
filterFor (const Boxes& scene)
{
  return mid::test::measuringStep<mid::SizeDisagreementFilter> (scene);
}

/** Run `filter` on the model of the three products and the model of the three copies of A;
  * returns the number of models removed and leaves the kept ones in `models`.
  */
std::size_t
filtered (const Boxes& scene,
          const mid::SizeDisagreementFilter& filter,
          mid::ObjectModels& models)
{
  models = {scene.modelOf ({0, 1, 2}), scene.modelOf ({3, 4, 5})};
  std::size_t removed = std::numeric_limits<std::size_t>::max();
  EXPECT_TRUE (filter.filter (models, removed));
  return removed;
}

} // namespace

TEST (SizeDisagreementFilter, RemovesAModelOfThreeProductsStandingAlone)
{
  const Boxes scene (twoRows (false));
  mid::ObjectModels models;
  EXPECT_EQ (filtered (scene, filterFor (scene), models), 1u);
  ASSERT_EQ (models.size(), 1u); // the copies of one box stay, whole
  ASSERT_EQ (models[0].instances.size(), 3u);
  for (int b = 0; b < 3; ++b)
    EXPECT_EQ (
        scene.boxOf (models[0].instances[static_cast<std::size_t> (b)].keypoints),
        b + 3);

  // Judging four copies at least, the three products stay too.
  mid::SizeDisagreementFilter four = filterFor (scene);
  four.setMinCopies (4);
  EXPECT_EQ (filtered (scene, four, models), 0u);
  EXPECT_EQ (models.size(), 2u);

  // Two products of the three: they differ on every edge, but two copies are too few.
  mid::ObjectModels two = {scene.modelOf ({0, 1})};
  std::size_t removed = 1;
  ASSERT_TRUE (filterFor (scene).filter (two, removed));
  EXPECT_EQ (removed, 0u);
  EXPECT_EQ (two.size(), 1u);
  mid::SizeDisagreementFilter judging_two = filterFor (scene);
  judging_two.setMinCopies (2);
  ASSERT_TRUE (judging_two.filter (two, removed));
  EXPECT_EQ (removed, 1u);
  EXPECT_TRUE (two.empty());
}

TEST (SizeDisagreementFilter, KeepsAModelOneOfWhoseCopiesIsNotAlone)
{
  // A taller block touches box 2: something else stands right beside its surface, which may
  // then be a copy joined with a neighbour or partly hidden, so its box proves nothing.
  const Boxes scene (twoRows (true));
  mid::ObjectModels models;
  EXPECT_EQ (filtered (scene, filterFor (scene), models), 0u);
  EXPECT_EQ (models.size(), 2u);
  // Taking any surroundings for standing alone, the model goes.
  mid::SizeDisagreementFilter anything = filterFor (scene);
  anything.setMaxSurroundedShare (1.0f);
  EXPECT_EQ (filtered (scene, anything, models), 1u);
  EXPECT_EQ (models.size(), 1u);
}

TEST (SizeDisagreementFilter, KeepsAModelWhoseBoxesDifferInOneEdgeOnly)
{
  // Three boxes of one cross-section and three lengths: no two agree, but none differs from
  // another on every edge, as one box measured whole, joined end to end or hidden at one end.
  // Box 3, of size B, differs from box 0 on every edge.
  const Boxes scene ({restingBox (kApplePrint, -0.26, -0.14, 10.0, {0.12, 0.09, 0.04}),
                      restingBox (kApplePrint, 0.0, -0.14, -20.0, {0.16, 0.09, 0.04}),
                      restingBox (kApplePrint, 0.26, -0.14, 0.0, {0.20, 0.09, 0.04}),
                      restingBox (kSoyPrint, 0.0, 0.14, 30.0, kSizeB)});
  mid::ObjectModels models = {scene.modelOf ({0, 1, 2})};
  std::size_t removed = 1;
  ASSERT_TRUE (filterFor (scene).filter (models, removed));
  EXPECT_EQ (removed, 0u);
  EXPECT_EQ (models.size(), 1u);
  // The control: with box 3 for box 2 the same copies are judged, and the model goes.
  models = {scene.modelOf ({0, 1, 3})};
  ASSERT_TRUE (filterFor (scene).filter (models, removed));
  EXPECT_EQ (removed, 1u);
  EXPECT_TRUE (models.empty());
}

TEST (SizeDisagreementFilter, KeepsAModelWithAnInstanceWithoutSurface)
{
  // A fourth instance that observes no keypoint has no surface to stand alone on, whatever
  // share of surroundings is allowed.
  const Boxes scene (twoRows (false));
  mid::ObjectModel three = scene.modelOf ({0, 1, 2});
  mid::ModelInstance unobserved = three.instances[0];
  unobserved.keypoints.clear();
  unobserved.landmarks.clear();
  mid::ObjectModel four = three;
  four.instances.push_back (unobserved);
  mid::SizeDisagreementFilter anything = filterFor (scene);
  anything.setMaxSurroundedShare (1.0f);
  std::size_t removed = 1;
  for (const auto& filter : {filterFor (scene), anything}) {
    mid::ObjectModels models = {four};
    ASSERT_TRUE (filter.filter (models, removed));
    EXPECT_EQ (removed, 0u);
    EXPECT_EQ (models.size(), 1u);
  }
  mid::ObjectModels models = {three}; // the control: without it, the model goes
  ASSERT_TRUE (filterFor (scene).filter (models, removed));
  EXPECT_EQ (removed, 1u);
}

TEST (SizeDisagreementFilter, RefusesBadInputAndLeavesTheModels)
{
  const Boxes scene (twoRows (false));
  const mid::ObjectModels original = {scene.modelOf ({0, 1, 2})};
  const auto refuses = [&] (const mid::SizeDisagreementFilter& filter) {
    mid::ObjectModels models = original;
    std::size_t removed = std::numeric_limits<std::size_t>::max();
    EXPECT_FALSE (filter.filter (models, removed));
    EXPECT_EQ (removed, 0u);
    EXPECT_EQ (models.size(), 1u);
  };
  for (const float share : {-0.1f, 1.5f, std::numeric_limits<float>::quiet_NaN()}) {
    mid::SizeDisagreementFilter filter = filterFor (scene);
    filter.setMaxSurroundedShare (share);
    refuses (filter);
  }
  mid::SizeDisagreementFilter one_copy = filterFor (scene);
  one_copy.setMinCopies (1);
  refuses (one_copy);
  mid::SizeDisagreementFilter no_keypoints = filterFor (scene);
  no_keypoints.setInputKeypoints (nullptr);
  refuses (no_keypoints);
  mid::ObjectModel broken = original[0];
  broken.instances[0].keypoints[0] = 100000;
  mid::ObjectModels models = {broken};
  std::size_t removed = 1;
  EXPECT_FALSE (filterFor (scene).filter (models, removed));
  EXPECT_EQ (removed, 0u);
  EXPECT_EQ (models.size(), 1u);
}
