// ModelSizeMerger and the box measurement under it, on rendered boxes resting on a table at
// known poses.
#include "resting_boxes.h"

#include <mid/segmentation/instance_extent.h>
#include <mid/segmentation/model_size_merger.h>
#include <mid/simulation/pinhole_camera.h>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <set>
#include <utility>
#include <vector>

namespace {

using mid::test::boxPose;
using mid::test::kApplePrint;
using mid::test::kPrintedBoxSize;
using mid::test::kSoyPrint;

using mid::test::fourBoxes;
using mid::test::insideBox;
using mid::test::kTableDepth;
using mid::test::restingBox;
using mid::test::rotationErrorModuloBox;
using mid::test::twoApartTwoTouching;
using Boxes = mid::test::RestingBoxes;

mid::ModelSizeMerger
mergerFor (const Boxes& scene)
{
  return mid::test::measuringStep<mid::ModelSizeMerger> (scene);
}

/** The instance's pose is box b's true pose, up to the box's symmetries (3 deg, 4 mm). */
void
expectBoxPose (const Boxes& scene, const mid::ModelInstance& instance, int b)
{
  const Eigen::Isometry3d& truth = scene.scene.boxes[static_cast<std::size_t> (b)].pose;
  EXPECT_LT (rotationErrorModuloBox (instance.pose, truth), 3.0) << "box " << b;
  EXPECT_LT (
      (instance.pose.topRightCorner<3, 1>() - truth.translation().cast<float>()).norm(),
      0.004f)
      << "box " << b;
}

/** The models of boxes {0, 1} and {2, 3}, the second in a model frame of its own. */
mid::ObjectModels
twoModels (const Boxes& scene)
{
  const Eigen::Isometry3f other_frame =
      Eigen::Translation3f (0.02f, -0.01f, 0.005f) *
      Eigen::AngleAxisf (0.7f, Eigen::Vector3f (1.0f, 2.0f, 0.5f).normalized());
  return {scene.modelOf ({0, 1}), scene.modelOf ({2, 3}, other_frame)};
}

/** twoModels() merge into one model of four instances in box 0's frame, in which the boxes
  * `posed` are at their true poses up to the box's symmetries (expectBoxPose()).
  */
void
expectMergedWithPosed (const Boxes& scene, const std::vector<int>& posed)
{
  mid::ObjectModels models = twoModels (scene);
  ASSERT_TRUE (mergerFor (scene).merge (models));
  ASSERT_EQ (models.size(), 1u);
  ASSERT_EQ (models[0].instances.size(), 4u);
  std::size_t checked = 0;
  for (const auto& instance : models[0].instances) {
    const int b = scene.boxOf (instance.keypoints);
    ASSERT_GE (b, 0);
    if (std::find (posed.begin(), posed.end(), b) != posed.end()) {
      ++checked;
      expectBoxPose (scene, instance, b);
    }
  }
  EXPECT_EQ (checked, posed.size());
}

TEST (InstanceExtent, MeasuresABoxRestingOnTheTable)
{
  const Boxes scene (fourBoxes());
  Eigen::Vector4f plane;
  ASSERT_TRUE (mid::fitSupportPlane (*scene.surface.organized, 0.01f, 0.2f, plane));
  EXPECT_NEAR (plane[2], -1.0f, 1e-3f) << "the normal points towards the camera";
  EXPECT_NEAR (plane[3], static_cast<float> (kTableDepth), 1e-3f);

  for (int b = 0; b < 4; ++b) {
    mid::InstanceExtent extent;
    ASSERT_TRUE (mid::measureInstanceExtent (*scene.surface.organized,
                                             plane,
                                             scene.seedsOn (b),
                                             0.008f,
                                             0.3f,
                                             0.01f,
                                             extent))
        << "box " << b;
    // Edges ascending: 0.04 (the height above the table), 0.09, 0.12.
    EXPECT_NEAR (extent.size[0], 0.04f, 0.004f) << "box " << b;
    EXPECT_NEAR (extent.size[1], 0.09f, 0.004f) << "box " << b;
    EXPECT_NEAR (extent.size[2], 0.12f, 0.004f) << "box " << b;
    const Eigen::Isometry3d& truth =
        scene.scene.boxes[static_cast<std::size_t> (b)].pose;
    EXPECT_LT (
        (extent.pose.topRightCorner<3, 1>() - truth.translation().cast<float>()).norm(),
        0.004f)
        << "box " << b;
    // The longest edge runs along the box's x axis, the shortest along its z axis.
    EXPECT_GT (std::abs (extent.pose.col (2).head<3>().dot (
                   truth.linear().col (0).cast<float>())),
               std::cos (3.0f * static_cast<float> (M_PI) / 180.0f))
        << "box " << b;
    EXPECT_GT (std::abs (extent.pose.col (0).head<3>().dot (
                   truth.linear().col (2).cast<float>())),
               std::cos (3.0f * static_cast<float> (M_PI) / 180.0f))
        << "box " << b;
  }
}

TEST (InstanceExtent, FindsNothingOffThePlaneFromATableSeed)
{
  const Boxes scene (fourBoxes());
  Eigen::Vector4f plane;
  ASSERT_TRUE (mid::fitSupportPlane (*scene.surface.organized, 0.01f, 0.2f, plane));
  const auto& organized = *scene.surface.organized;
  const pcl::Indices table_corner = {
      static_cast<pcl::index_t> (5 * organized.width + 5)};
  mid::InstanceExtent extent;
  EXPECT_FALSE (mid::measureInstanceExtent (
      organized, plane, table_corner, 0.008f, 0.3f, 0.01f, extent));
  EXPECT_TRUE (extent.surface.empty());
}

/** The frame of the surface z = depth (x, y) (metres, all between 0.85 and 1.1) seen by the
  * default camera.
  */
pcl::PointCloud<pcl::PointXYZ>
heightField (const std::function<double (double, double)>& depth)
{
  const mid::simulation::PinholeCamera camera;
  pcl::PointCloud<pcl::PointXYZ> cloud (static_cast<std::uint32_t> (camera.width),
                                        static_cast<std::uint32_t> (camera.height));
  for (int v = 0; v < camera.height; ++v)
    for (int u = 0; u < camera.width; ++u) {
      const double rx = (u - camera.cx) / camera.fx, ry = (v - camera.cy) / camera.fy;
      // The ray first meets the surface where z >= depth (rx z, ry z): marched in 2 mm
      // steps, then bisected.
      const auto behind = [&] (double z) { return z >= depth (rx * z, ry * z); };
      double far = 0.85;
      while (!behind (far) && far < 1.1)
        far += 0.002;
      double near = far - 0.002;
      for (int i = 0; i < 20; ++i) {
        const double middle = 0.5 * (near + far);
        (behind (middle) ? far : near) = middle;
      }
      const double z = far;
      cloud.at (u, v) = pcl::PointXYZ (static_cast<float> (rx * z),
                                       static_cast<float> (ry * z),
                                       static_cast<float> (z));
    }
  return cloud;
}

TEST (InstanceExtent, StopsAtTheCreaseWhereTwoObjectsMeet)
{
  // A table at 1 m; on it a box 0.12 x 0.09 x 0.04 around the optical axis, and against its
  // far long side a roof whose slopes (2 in 1) rise from the box's top to a ridge 0.06 above
  // it. Box top and roof meet in a crease without a depth step.
  const auto depth = [] (double x, double y) {
    double z = 1.0;
    if (std::abs (x) < 0.06 && std::abs (y) < 0.045)
      z = 0.96;
    if (std::abs (x) < 0.06 && y >= 0.045 && y < 0.105)
      z = std::min (z, 0.96 - 2.0 * std::min (y - 0.045, 0.105 - y));
    return z;
  };
  const auto cloud = heightField (depth);
  Eigen::Vector4f plane;
  ASSERT_TRUE (mid::fitSupportPlane (cloud, 0.01f, 0.2f, plane));
  const auto centre = static_cast<pcl::index_t> (240 * cloud.width + 320);
  const pcl::Indices seeds = {centre - 10, centre, centre + 10};
  mid::InstanceExtent extent;
  ASSERT_TRUE (
      mid::measureInstanceExtent (cloud, plane, seeds, 0.008f, 0.3f, 0.01f, extent));
  // Over the crease, the surface would climb the roof: 0.12 x 0.15 x 0.1. The few pixels
  // next to the crease, behind their chords too, are lost to the box's width.
  EXPECT_NEAR (extent.size[0], 0.04f, 0.003f);
  EXPECT_GT (extent.size[1], 0.08f);
  EXPECT_LT (extent.size[1], 0.092f);
  EXPECT_NEAR (extent.size[2], 0.12f, 0.004f);
}

TEST (ModelSizeMerger, MergesTwoModelsOfOneBoxSizeIntoTheBoxFrame)
{
  const Boxes scene (fourBoxes());
  // The merged model keeps box 0's frame: every instance's pose is its box's true pose, up to
  // the box's symmetries.
  ASSERT_NO_FATAL_FAILURE (expectMergedWithPosed (scene, {0, 1, 2, 3}));
  mid::ObjectModels models = twoModels (scene);
  const std::size_t landmarks = models[0].landmarks.size() + models[1].landmarks.size();
  ASSERT_TRUE (mergerFor (scene).merge (models));
  ASSERT_EQ (models.size(), 1u);
  EXPECT_EQ (models[0].landmarks.size(), landmarks);
}

TEST (ModelSizeMerger, KeepsModelsOfDifferentSizesApart)
{
  const Boxes scene (fourBoxes ({0.1, 0.09, 0.04}));
  mid::ObjectModels models = {scene.modelOf ({0, 1}), scene.modelOf ({2, 3})};
  ASSERT_TRUE (mergerFor (scene).merge (models));
  ASSERT_EQ (models.size(), 2u);
  EXPECT_EQ (models[0].instances.size(), 2u);
  EXPECT_EQ (models[1].instances.size(), 2u);
}

TEST (InstanceExtent, SplitsTheJoinedSurfaceOfTouchingCopies)
{
  const Boxes scene (twoApartTwoTouching());
  const auto& organized = *scene.surface.organized;
  Eigen::Vector4f plane;
  ASSERT_TRUE (mid::fitSupportPlane (organized, 0.01f, 0.2f, plane));
  std::vector<pcl::Indices> surfaces;
  ASSERT_TRUE (mid::growInstanceSurfaces (organized,
                                          plane,
                                          {scene.seedsOn (2), scene.seedsOn (3)},
                                          0.008f,
                                          0.3f,
                                          0.01f,
                                          surfaces));
  ASSERT_EQ (surfaces.size(), 2u);
  // Where the tops join, the pixels go to the box whose keypoints reach them first: the
  // split follows the keypoints, not the seam, but each surface lies mostly on its own box,
  // and together they hold both boxes' tops. Grown as one, either surface would hold both.
  std::size_t total = 0;
  for (std::size_t s = 0; s < 2; ++s) {
    const auto& box = scene.scene.boxes[2 + s];
    std::size_t own = 0;
    for (const auto pixel : surfaces[s])
      if (insideBox (box, organized[pixel].getVector3fMap()))
        ++own;
    EXPECT_GT (own, surfaces[s].size() * 8 / 10) << "box " << 2 + s;
    total += surfaces[s].size();
  }
  const double top = kPrintedBoxSize.x() * kPrintedBoxSize.y();
  const double pixel =
      (kTableDepth - kPrintedBoxSize.z()) / mid::simulation::PinholeCamera().fx;
  EXPECT_GT (static_cast<double> (total), 0.9 * 2.0 * top / (pixel * pixel));
}

TEST (ModelSizeMerger, KeepsTouchingCopiesApartFromABoxOfTheirJoinedSize)
{
  // Boxes 0 and 1 are as wide as boxes 2 and 3 side by side: measured as one, the joined tops
  // of 2 and 3 would give their model the size of the other.
  const Boxes scene (twoApartTwoTouching ({0.12, 0.18, 0.04}));
  mid::ObjectModels models = {scene.modelOf ({0, 1}), scene.modelOf ({2, 3})};
  ASSERT_TRUE (mergerFor (scene).merge (models));
  EXPECT_EQ (models.size(), 2u);
}

TEST (ModelSizeMerger, MergesCopiesShowingAnotherFaceUp)
{
  // Boxes 2 to 4 are boxes 0 and 1 (edges 0.04, 0.09, 0.12) lying on a 0.12 x 0.04 face, their
  // frames' axes in another order: their model's size is found on other axes. It has more
  // instances, so boxes 0 and 1's model is merged into it.
  const Eigen::Vector3d on_side (0.12, 0.04, 0.09);
  const Boxes scene ({restingBox (kApplePrint, -0.17, -0.12, 10.0),
                      restingBox (kApplePrint, 0.16, -0.12, -35.0),
                      restingBox (kSoyPrint, -0.15, 0.12, 70.0, on_side),
                      restingBox (kSoyPrint, 0.17, 0.11, 160.0, on_side),
                      restingBox (kSoyPrint, 0.0, 0.0, 95.0, on_side)});
  mid::ObjectModels models = {scene.modelOf ({0, 1}), scene.modelOf ({2, 3, 4})};
  ASSERT_TRUE (mergerFor (scene).merge (models));
  ASSERT_EQ (models.size(), 1u);
  ASSERT_EQ (models[0].instances.size(), 5u);
  // The merged model keeps box 2's frame. Box 0's axes x (0.12), y (0.09), z (0.04) are box 2's
  // x, z and -y.
  Eigen::Matrix3d flat_in_side;
  flat_in_side << 1, 0, 0, 0, 0, -1, 0, 1, 0;
  for (const auto& instance : models[0].instances) {
    const int b = scene.boxOf (instance.keypoints);
    ASSERT_GE (b, 0);
    Eigen::Isometry3d truth = scene.scene.boxes[static_cast<std::size_t> (b)].pose;
    if (b < 2)
      truth.linear() = truth.linear() * flat_in_side.transpose();
    EXPECT_LT (rotationErrorModuloBox (instance.pose, truth), 3.0) << "box " << b;
    EXPECT_LT (
        (instance.pose.topRightCorner<3, 1>() - truth.translation().cast<float>())
            .norm(),
        0.004f)
        << "box " << b;
  }
}

TEST (ModelSizeMerger, MergesAModelOneOfWhoseCopiesHasTheOthersSize)
{
  // Boxes 0 to 2 have one size; box 3 is smaller. The second model (boxes 2 and 3) has no size
  // most of its copies agree on, and takes the smaller surface's (box 3's): it agrees with the
  // first model's size only through box 2.
  const Boxes scene ({restingBox (kApplePrint, -0.16, -0.1, 10.0),
                      restingBox (kApplePrint, 0.16, -0.12, -35.0),
                      restingBox (kSoyPrint, -0.1, 0.13, 20.0),
                      restingBox (kSoyPrint, 0.17, 0.12, 60.0, {0.1, 0.07, 0.04})});
  // Box 2 is posed in box 0's frame by its own box: its true pose, up to the box's symmetries.
  ASSERT_NO_FATAL_FAILURE (expectMergedWithPosed (scene, {0, 1, 2}));
}

TEST (ModelSizeMerger, MergesModelsThroughOneCopyOfEachMeasuredWhole)
{
  // Boxes 0 and 2 have one size; box 1 and box 3 are smaller, each in its own way. Each model
  // takes the size of its smaller surface (box 1's, box 3's), which neither the other model's
  // size nor any of its copies has: the two agree only through box 0 and box 2.
  const Boxes scene ({restingBox (kApplePrint, -0.16, -0.1, 10.0),
                      restingBox (kApplePrint, 0.16, -0.12, -35.0, {0.1, 0.07, 0.04}),
                      restingBox (kSoyPrint, -0.1, 0.13, 20.0),
                      restingBox (kSoyPrint, 0.17, 0.12, 60.0, {0.1, 0.055, 0.04})});
  // Box 2 is posed in box 0's frame by its own box: its true pose, up to the box's symmetries.
  ASSERT_NO_FATAL_FAILURE (expectMergedWithPosed (scene, {0, 2}));

  // Asked for two copies agreeing on a size, the pair is enough; asked for three, it is not.
  mid::ModelSizeMerger strict = mergerFor (scene);
  for (const int min_agreeing : {2, 3}) {
    mid::ObjectModels models = twoModels (scene);
    strict.setMinAgreeing (min_agreeing);
    ASSERT_TRUE (strict.merge (models));
    EXPECT_EQ (models.size(), min_agreeing == 2 ? 1u : 2u)
        << "min_agreeing " << min_agreeing;
  }

  // With two copies asked, neither model has a size, and the merged one takes the pair's (box
  // 0's): a third model, of two copies of that size, joins it by that size.
  std::vector<mid::test::BoxSpec> six = scene.scene.boxes;
  six.push_back (restingBox (kApplePrint, 0.0, 0.0, 45.0));
  six.push_back (restingBox (kSoyPrint, 0.33, 0.0, 0.0));
  const Boxes three_models (six);
  mid::ObjectModels models = twoModels (three_models);
  models.push_back (three_models.modelOf (
      {4, 5},
      Eigen::Translation3f (-0.03f, 0.02f, 0.01f) *
          Eigen::AngleAxisf (-1.1f, Eigen::Vector3f (0.3f, 1.0f, 2.0f).normalized())));
  mid::ModelSizeMerger pairs = mergerFor (three_models);
  pairs.setMinAgreeing (2);
  ASSERT_TRUE (pairs.merge (models));
  ASSERT_EQ (models.size(), 1u);
  EXPECT_EQ (models[0].instances.size(), 6u);

  // Box 2 of the smaller size of box 3: no copy of the second model has the size of any copy
  // of the first.
  const Boxes apart ({restingBox (kApplePrint, -0.16, -0.1, 10.0),
                      restingBox (kApplePrint, 0.16, -0.12, -35.0, {0.1, 0.07, 0.04}),
                      restingBox (kSoyPrint, -0.1, 0.13, 20.0, {0.1, 0.055, 0.04}),
                      restingBox (kSoyPrint, 0.17, 0.12, 60.0, {0.1, 0.055, 0.04})});
  models = twoModels (apart);
  ASSERT_TRUE (mergerFor (apart).merge (models));
  EXPECT_EQ (models.size(), 2u);
}

TEST (ModelSizeMerger, MergesAModelWhoseCopiesEachLieFlushWithANeighbour)
{
  // Boxes 0 and 1 each lie flush with a neighbour of their height (boxes 4 and 5, in no
  // model), in a different place: measured on its own, neither copy has the size of boxes 2
  // and 3, and no way but the consensus boxes joins the two models.
  const Boxes scene (mid::test::twoJoinedTwoApart());
  ASSERT_NO_FATAL_FAILURE (expectMergedWithPosed (scene, {0, 1, 2, 3}));
  // In the other order, the whole boxes' size is looked for among the joined ones' consensus
  // boxes from the other side.
  mid::ObjectModels swapped = twoModels (scene);
  std::swap (swapped[0], swapped[1]);
  ASSERT_TRUE (mergerFor (scene).merge (swapped));
  ASSERT_EQ (swapped.size(), 1u);
  EXPECT_EQ (swapped[0].instances.size(), 4u);

  mid::ModelSizeMerger without = mergerFor (scene);
  without.setConsensusRadius (0.0f);
  mid::ObjectModels models = twoModels (scene);
  ASSERT_TRUE (without.merge (models));
  EXPECT_EQ (models.size(), 2u);

  // Boxes 2 and 3 of another size: the consensus boxes do not join them either.
  const Boxes other_size (mid::test::twoJoinedTwoApart ({0.1, 0.07, 0.04}));
  models = twoModels (other_size);
  ASSERT_TRUE (mergerFor (other_size).merge (models));
  EXPECT_EQ (models.size(), 2u);
}

TEST (ModelSizeMerger, MergesModelsOfTwoEndsOfTheSameCopiesAtTheCopiesPoses)
{
  // Both models see all four boxes, the first the halves at negative x (in the box's frame),
  // the second, in a frame of its own, the other halves: no landmark is shared, and the two
  // instances on a box split its surface, so each model takes the size of half a box. Those
  // sizes agree, but the boxes' frames place the second model's half on the first's (up to a
  // half turn), which would leave two instances on every box. The copies' poses place it
  // beside it, where it lies on each box.
  const Boxes scene (fourBoxes());
  const auto negative_x = [] (const Eigen::Vector3f& p) { return p.x() < 0.0f; };
  const auto positive_x = [] (const Eigen::Vector3f& p) { return p.x() >= 0.0f; };
  const Eigen::Isometry3f other_frame =
      Eigen::Translation3f (0.02f, -0.01f, 0.005f) *
      Eigen::AngleAxisf (0.7f, Eigen::Vector3f (1.0f, 2.0f, 0.5f).normalized());
  mid::ObjectModels models = {
      scene.modelOf ({0, 1, 2, 3}, Eigen::Isometry3f::Identity(), negative_x),
      scene.modelOf ({0, 1, 2, 3}, other_frame, positive_x)};
  ASSERT_TRUE (mergerFor (scene).merge (models));
  ASSERT_EQ (models.size(), 1u);
  ASSERT_EQ (models[0].instances.size(), 4u);
  std::set<int> boxes;
  for (const auto& instance : models[0].instances) {
    const int b = scene.boxOf (instance.keypoints);
    ASSERT_GE (b, 0);
    boxes.insert (b);
    // The whole box is one instance, at the box's true pose (the first model's frame is box
    // 0's), not merely up to a symmetry of the box.
    EXPECT_EQ (instance.keypoints.size(), scene.on ({b}).size()) << "box " << b;
    const Eigen::Isometry3d& truth =
        scene.scene.boxes[static_cast<std::size_t> (b)].pose;
    const Eigen::AngleAxisf error (truth.linear().cast<float>().transpose() *
                                   instance.pose.topLeftCorner<3, 3>());
    EXPECT_LT (error.angle(), 3.0f * static_cast<float> (M_PI) / 180.0f) << "box " << b;
    EXPECT_LT (
        (instance.pose.topRightCorner<3, 1>() - truth.translation().cast<float>())
            .norm(),
        0.004f)
        << "box " << b;
  }
  EXPECT_EQ (boxes.size(), 4u);
}

TEST (InstanceExtent, RefusesPixelsOutsideTheFrameOrWithoutAPoint)
{
  const Boxes scene (fourBoxes());
  const auto& organized = *scene.surface.organized;
  Eigen::Vector4f plane;
  ASSERT_TRUE (mid::fitSupportPlane (organized, 0.01f, 0.2f, plane));
  std::vector<pcl::Indices> surfaces;
  const auto outside = static_cast<pcl::index_t> (organized.size());
  EXPECT_FALSE (mid::growInstanceSurfaces (
      organized, plane, {scene.seedsOn (0), {outside}}, 0.008f, 0.3f, 0.01f, surfaces));
  ASSERT_EQ (surfaces.size(), 2u);
  EXPECT_TRUE (surfaces[0].empty());

  pcl::PointCloud<pcl::PointXYZ> holed = organized;
  ASSERT_TRUE (mid::growInstanceSurfaces (
      holed, plane, {scene.seedsOn (0)}, 0.008f, 0.3f, 0.01f, surfaces));
  const auto hole = static_cast<std::size_t> (surfaces[0][surfaces[0].size() / 2]);
  holed[hole].z = std::numeric_limits<float>::quiet_NaN();
  mid::InstanceExtent extent;
  EXPECT_FALSE (mid::fitInstanceBox (holed, plane, surfaces[0], extent));
  EXPECT_TRUE (extent.surface.empty());

  pcl::PointCloud<pcl::PointXYZ> unorganized = organized;
  unorganized.height = 2;
  EXPECT_FALSE (mid::fitSupportPlane (unorganized, 0.01f, 0.2f, plane));
}

TEST (InstanceExtent, FindsNoSupportPlaneBelowTheShareAskedFor)
{
  // The table holds about 95 % of the frame's points, the boxes' faces the rest.
  const Boxes scene (fourBoxes());
  Eigen::Vector4f plane;
  EXPECT_FALSE (mid::fitSupportPlane (*scene.surface.organized, 0.01f, 0.99f, plane));
  EXPECT_TRUE (plane.isZero());
  EXPECT_TRUE (mid::fitSupportPlane (*scene.surface.organized, 0.01f, 0.9f, plane));
}

TEST (ModelSizeMerger, RefusesBadInputAndLeavesTheModels)
{
  const Boxes scene (fourBoxes());
  const mid::ObjectModels original = {scene.modelOf ({0, 1}), scene.modelOf ({2, 3})};

  const auto refuses = [&] (const mid::ModelSizeMerger& merger,
                            mid::ObjectModels models) {
    EXPECT_FALSE (merger.merge (models));
    EXPECT_EQ (models.size(), original.size());
  };
  mid::ModelSizeMerger no_keypoints = mergerFor (scene);
  no_keypoints.setInputKeypoints (nullptr);
  refuses (no_keypoints, original);

  mid::ModelSizeMerger no_pixels = mergerFor (scene);
  mid::KeypointSurface without_pixels = scene.surface;
  without_pixels.keypoint_pixels.clear();
  no_pixels.setKeypointSurface (without_pixels);
  refuses (no_pixels, original);

  mid::ModelSizeMerger negative = mergerFor (scene);
  negative.setSizeTolerance (-0.001f, 0.03f);
  refuses (negative, original);

  mid::ModelSizeMerger no_step = mergerFor (scene);
  no_step.setMaxStep (0.0f);
  refuses (no_step, original);

  for (const float radius : {-0.005f,
                             std::numeric_limits<float>::quiet_NaN(),
                             std::numeric_limits<float>::infinity()}) {
    mid::ModelSizeMerger no_radius = mergerFor (scene);
    no_radius.setConsensusRadius (radius);
    refuses (no_radius, original);
  }

  mid::ModelSizeMerger nobody = mergerFor (scene);
  nobody.setMinAgreeing (0);
  refuses (nobody, original);

  mid::ObjectModels outside = original;
  outside[1].instances[0].keypoints[0] =
      static_cast<pcl::index_t> (scene.keypoints->size());
  refuses (mergerFor (scene), outside);
}

} // namespace
