// ModelSizeMerger and the box measurement under it, on rendered boxes resting on a table at
// known poses.
#include "rendered_keypoints.h"

#include <mid/segmentation/instance_extent.h>
#include <mid/segmentation/model_size_merger.h>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <array>

namespace {

using mid::test::boxPose;
using mid::test::kApplePrint;
using mid::test::kPrintedBoxSize;
using mid::test::kSoyPrint;

/** The table the boxes rest on, facing the camera (metres). */
constexpr double kTableDepth = 0.95;

/** A box of the given size lying on the table at (x, y), turned by `roll` degrees. */
mid::test::BoxSpec
restingBox (const char* print,
            double x,
            double y,
            double roll,
            const Eigen::Vector3d& size = kPrintedBoxSize)
{
  return {print, size, boxPose (x, y, kTableDepth - 0.5 * size.z(), roll)};
}

/** Four boxes apart on the table: 0 and 1 with one print, 2 and 3 with another. */
std::vector<mid::test::BoxSpec>
fourBoxes (const Eigen::Vector3d& size_of_2_and_3 = kPrintedBoxSize)
{
  return {restingBox (kApplePrint, -0.16, -0.1, 10.0),
          restingBox (kApplePrint, 0.16, -0.12, -35.0),
          restingBox (kSoyPrint, -0.15, 0.12, 70.0, size_of_2_and_3),
          restingBox (kSoyPrint, 0.17, 0.11, 160.0, size_of_2_and_3)};
}

/** The proper rotations that map a box with three different edges onto itself. */
std::array<Eigen::Matrix3f, 4>
boxSymmetries ()
{
  return {Eigen::Matrix3f::Identity(),
          Eigen::Matrix3f (
              Eigen::AngleAxisf (static_cast<float> (M_PI), Eigen::Vector3f::UnitX())),
          Eigen::Matrix3f (
              Eigen::AngleAxisf (static_cast<float> (M_PI), Eigen::Vector3f::UnitY())),
          Eigen::Matrix3f (
              Eigen::AngleAxisf (static_cast<float> (M_PI), Eigen::Vector3f::UnitZ()))};
}

/** Rotation error (degrees) of `pose` against the box's true pose, modulo the box's
  * symmetries (the model frame is the box's own frame).
  */
double
rotationErrorModuloBox (const Eigen::Matrix4f& pose, const Eigen::Isometry3d& truth)
{
  double best = 180.0;
  for (const auto& s : boxSymmetries()) {
    const Eigen::Matrix3f expected = truth.linear().cast<float>() * s;
    const Eigen::AngleAxisf error (expected.transpose() * pose.topLeftCorner<3, 3>());
    best = std::min (best, static_cast<double> (error.angle()) * 180.0 / M_PI);
  }
  return best;
}

struct Boxes : mid::test::RenderedKeypoints
{
  explicit Boxes (const std::vector<mid::test::BoxSpec>& boxes,
                  double table = kTableDepth)
  : RenderedKeypoints (mid::test::renderBoxes (boxes, table))
  {}

  /** A model of the given boxes at their true poses, in the frame of the first box moved by
    * `frame` (model -> box), so that two models' frames differ.
    */
  mid::ObjectModel
  modelOf (const std::vector<std::size_t>& boxes,
           const Eigen::Isometry3f& frame = Eigen::Isometry3f::Identity()) const
  {
    mid::ObjectModel model;
    for (const auto b : boxes)
      addTruthInstance (b, model);
    for (auto& instance : model.instances)
      instance.pose = instance.pose * frame.matrix();
    const Eigen::Isometry3f to_model = frame.inverse();
    for (auto& landmark : model.landmarks) {
      landmark.getVector3fMap() = to_model * landmark.getVector3fMap();
      landmark.getNormalVector3fMap() =
          to_model.linear() * landmark.getNormalVector3fMap();
    }
    return model;
  }

  mid::ModelSizeMerger
  merger () const
  {
    mid::ModelSizeMerger merger;
    merger.setInputKeypoints (keypoints);
    merger.setKeypointSurface (surface);
    return merger;
  }

  /** The pixels of the keypoints on box b. */
  pcl::Indices
  seedsOn (int b) const
  {
    pcl::Indices seeds;
    for (const auto k : on ({b}))
      seeds.push_back (surface.keypoint_pixels[static_cast<std::size_t> (k)]);
    return seeds;
  }
};

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

TEST (ModelSizeMerger, MergesTwoModelsOfOneBoxSizeIntoTheBoxFrame)
{
  const Boxes scene (fourBoxes());
  const Eigen::Isometry3f other_frame =
      Eigen::Translation3f (0.02f, -0.01f, 0.005f) *
      Eigen::AngleAxisf (0.7f, Eigen::Vector3f (1.0f, 2.0f, 0.5f).normalized());
  mid::ObjectModels models = {scene.modelOf ({0, 1}),
                              scene.modelOf ({2, 3}, other_frame)};
  const std::size_t landmarks = models[0].landmarks.size() + models[1].landmarks.size();

  ASSERT_TRUE (scene.merger().merge (models));
  ASSERT_EQ (models.size(), 1u);
  ASSERT_EQ (models[0].instances.size(), 4u);
  EXPECT_EQ (models[0].landmarks.size(), landmarks);
  // The merged model keeps box 0's frame: every instance's pose is its box's true pose, up to
  // the box's symmetries.
  for (const auto& instance : models[0].instances) {
    const int b = scene.boxOf (instance.keypoints);
    ASSERT_GE (b, 0);
    const Eigen::Isometry3d& truth =
        scene.scene.boxes[static_cast<std::size_t> (b)].pose;
    EXPECT_LT (rotationErrorModuloBox (instance.pose, truth), 3.0) << "box " << b;
    EXPECT_LT (
        (instance.pose.topRightCorner<3, 1>() - truth.translation().cast<float>())
            .norm(),
        0.004f)
        << "box " << b;
  }
}

TEST (ModelSizeMerger, KeepsModelsOfDifferentSizesApart)
{
  const Boxes scene (fourBoxes ({0.1, 0.09, 0.04}));
  mid::ObjectModels models = {scene.modelOf ({0, 1}), scene.modelOf ({2, 3})};
  ASSERT_TRUE (scene.merger().merge (models));
  ASSERT_EQ (models.size(), 2u);
  EXPECT_EQ (models[0].instances.size(), 2u);
  EXPECT_EQ (models[1].instances.size(), 2u);
}

TEST (ModelSizeMerger, DoesNotMeasureTouchingCopies)
{
  // Boxes 2 and 3 touch along their long edges: their surfaces join, and each holds the
  // other's keypoints, so their model has no size.
  const Boxes scene ({restingBox (kApplePrint, -0.16, -0.1, 10.0),
                      restingBox (kApplePrint, 0.16, -0.12, -35.0),
                      restingBox (kSoyPrint, 0.0, 0.1, 0.0),
                      restingBox (kSoyPrint, 0.0, 0.19, 180.0)});
  mid::ObjectModels models = {scene.modelOf ({0, 1}), scene.modelOf ({2, 3})};
  ASSERT_TRUE (scene.merger().merge (models));
  EXPECT_EQ (models.size(), 2u);
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
  mid::ModelSizeMerger no_keypoints = scene.merger();
  no_keypoints.setInputKeypoints (nullptr);
  refuses (no_keypoints, original);

  mid::ModelSizeMerger no_pixels = scene.merger();
  mid::KeypointSurface without_pixels = scene.surface;
  without_pixels.keypoint_pixels.clear();
  no_pixels.setKeypointSurface (without_pixels);
  refuses (no_pixels, original);

  mid::ModelSizeMerger negative = scene.merger();
  negative.setSizeTolerance (-0.001f, 0.03f);
  refuses (negative, original);

  mid::ModelSizeMerger no_step = scene.merger();
  no_step.setMaxStep (0.0f);
  refuses (no_step, original);

  mid::ModelSizeMerger nobody = scene.merger();
  nobody.setMinAgreeing (0);
  refuses (nobody, original);

  mid::ObjectModels outside = original;
  outside[1].instances[0].keypoints[0] =
      static_cast<pcl::index_t> (scene.keypoints->size());
  refuses (scene.merger(), outside);
}

} // namespace
