// largestSizeGroup(): which of a model's measured boxes gives its size, on boxes of known size;
// ModelSizeMeasurement::measure() on rendered boxes resting on a table at known poses.
#include "resting_boxes.h"

#include <mid/segmentation/model_size.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace {

using mid::test::kApplePrint;
using mid::test::restingBox;
using Boxes = mid::test::RestingBoxes;

/** A box of edges `size` (metres, ascending) fitted to a surface of `pixels` pixels. */
mid::InstanceExtent
measured (const Eigen::Vector3f& size, int pixels)
{
  mid::InstanceExtent extent;
  extent.size = size;
  extent.surface.assign (static_cast<std::size_t> (pixels), 0);
  return extent;
}

const mid::SizeAgreement kAgree (0.006f, 0.03f);

} // namespace

TEST (LargestSizeGroup, PrefersTheBoxAnotherNearlyAgreesWithToTheSmallestSurface)
{
  // A carton of 84 x 87 x 240 mm measured whole twice (the second 6 mm too long: just outside
  // the tolerances), and once hidden in part (the smallest surface). No two agree, so each
  // box is a group of one; a whole one must win.
  const mid::InstanceExtents extents = {measured ({0.084f, 0.087f, 0.240f}, 9000),
                                        measured ({0.087f, 0.087f, 0.248f}, 9500),
                                        measured ({0.048f, 0.087f, 0.132f}, 3000)};
  ASSERT_FALSE (kAgree (extents[0].size, extents[1].size));
  std::size_t representative = 99;
  const std::vector<std::size_t> group =
      mid::largestSizeGroup (extents, {0, 1, 2}, kAgree, representative);
  EXPECT_EQ (representative, 0u); // the smaller surface of the two whole ones
  EXPECT_EQ (group, (std::vector<std::size_t>{0}));
}

TEST (LargestSizeGroup, PrefersTheMostAgreeingThenTheSmallestSurface)
{
  // Two copies agree on the true size; the box of one joined with a neighbour is larger. The
  // group of two wins, represented by its smaller surface.
  const mid::InstanceExtents extents = {measured ({0.087f, 0.198f, 0.351f}, 20000),
                                        measured ({0.084f, 0.087f, 0.240f}, 9000),
                                        measured ({0.085f, 0.086f, 0.238f}, 8000)};
  std::size_t representative = 99;
  const std::vector<std::size_t> group =
      mid::largestSizeGroup (extents, {0, 1, 2}, kAgree, representative);
  EXPECT_EQ (representative, 2u);
  EXPECT_EQ (group, (std::vector<std::size_t>{1, 2}));

  // Among boxes that agree with nothing, even loosely, the smallest surface wins (a surface is
  // more often joined with something than hidden).
  const mid::InstanceExtents apart = {measured ({0.05f, 0.10f, 0.20f}, 9000),
                                      measured ({0.10f, 0.15f, 0.30f}, 12000),
                                      measured ({0.02f, 0.03f, 0.04f}, 500)};
  mid::largestSizeGroup (apart, {0, 1}, kAgree, representative);
  EXPECT_EQ (representative, 0u);
  representative = 99;
  EXPECT_TRUE (mid::largestSizeGroup (apart, {}, kAgree, representative).empty());
  EXPECT_EQ (representative, 99u);
}

namespace {

/** Edges of `size` (metres) in ascending order. */
Eigen::Vector3f
ascending (const Eigen::Vector3d& size)
{
  Eigen::Vector3f edges = size.cast<float>();
  std::sort (edges.data(), edges.data() + 3);
  return edges;
}

/** Two models of two boxes each, apart on the table: boxes 0 and 1 (0.12 x 0.09 x 0.04), and
  * boxes 2 and 3 (0.10 x 0.06 x 0.05), each model in a frame of its own (not a box's).
  */
const Eigen::Vector3d kOtherSize (0.10, 0.06, 0.05);

std::vector<mid::test::BoxSpec>
twoPairs ()
{
  return mid::test::fourBoxes (kOtherSize);
}

mid::ObjectModels
pairModels (const Boxes& scene)
{
  const Eigen::Isometry3f frame (
      Eigen::Translation3f (0.01f, -0.02f, 0.005f) *
      Eigen::AngleAxisf (0.4f, Eigen::Vector3f (1, 2, 3).normalized()));
  return {scene.modelOf ({0, 1}, frame), scene.modelOf ({2, 3}, frame.inverse())};
}

} // namespace

TEST (ModelSizeMeasurement, MeasuresTheBoxEachModelsCopiesOccupyOnTheTable)
{
  const Boxes scene (twoPairs());
  const mid::ObjectModels models = pairModels (scene);
  mid::ModelSizes sizes;
  ASSERT_TRUE (mid::test::measuringStep<mid::ModelSizeMeasurement> (scene).measure (
      models, sizes));
  ASSERT_EQ (sizes.size(), 2u);
  const Eigen::Vector3d truth[2] = {mid::test::kPrintedBoxSize, kOtherSize};
  for (std::size_t m = 0; m < 2; ++m) {
    ASSERT_TRUE (sizes[m].valid) << m;
    EXPECT_EQ (sizes[m].agreeing, 2) << m;
    EXPECT_LT ((sizes[m].size - ascending (truth[m])).cwiseAbs().maxCoeff(), 0.006f)
        << m;
    // The box in the model frame, placed at each copy's pose, is that copy's box: its centre
    // within 5 mm of the true centre, its longest edge along the true box's longest (x).
    for (std::size_t i = 0; i < 2; ++i) {
      const Eigen::Matrix4f placed =
          models[m].instances[i].pose * sizes[m].box_in_model;
      const Eigen::Isometry3f box = scene.scene.boxes[2 * m + i].pose.cast<float>();
      EXPECT_LT ((placed.topRightCorner<3, 1>() - box.translation()).norm(), 0.005f)
          << m << " " << i;
      EXPECT_GT (std::abs (placed.block<3, 1> (0, 2).dot (box.linear().col (0))),
                 std::cos (5.0f * static_cast<float> (M_PI) / 180.0f))
          << m << " " << i;
    }
  }
}

TEST (ModelSizeMeasurement, GivesNoSizeWithoutASupportPlane)
{
  const Boxes scene (twoPairs());
  auto measurement = mid::test::measuringStep<mid::ModelSizeMeasurement> (scene);
  measurement.setSupportPlane (Eigen::Vector4f::Zero()); // a frame without a table
  mid::ModelSizes sizes;
  ASSERT_TRUE (measurement.measure (pairModels (scene), sizes));
  ASSERT_EQ (sizes.size(), 2u);
  EXPECT_FALSE (sizes[0].valid);
  EXPECT_FALSE (sizes[1].valid);
}

TEST (ModelSizeMeasurement, RefusesBadInputWithNoSizes)
{
  const Boxes scene (twoPairs());
  const mid::ObjectModels models = pairModels (scene);
  const auto refused = [&models] (const mid::ModelSizeMeasurement& measurement) {
    mid::ModelSizes sizes (3);
    EXPECT_FALSE (measurement.measure (models, sizes));
    EXPECT_TRUE (sizes.empty());
  };
  refused (mid::ModelSizeMeasurement()); // no keypoints, no surface
  auto none_agreeing = mid::test::measuringStep<mid::ModelSizeMeasurement> (scene);
  none_agreeing.setMinAgreeing (0);
  refused (none_agreeing);
  auto negative = mid::test::measuringStep<mid::ModelSizeMeasurement> (scene);
  negative.setSizeTolerance (-0.001f, 0.03f);
  refused (negative);
  mid::ObjectModels outside = models;
  outside[1].instances[0].keypoints.push_back (
      static_cast<pcl::index_t> (scene.keypoints->size()));
  outside[1].instances[0].landmarks.push_back (0);
  mid::ModelSizes sizes;
  EXPECT_FALSE (mid::test::measuringStep<mid::ModelSizeMeasurement> (scene).measure (
      outside, sizes));
  EXPECT_TRUE (sizes.empty());
}
