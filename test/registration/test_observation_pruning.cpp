// pruneUnexplainedObservations on a model with exact poses: which observations an instance's
// pose explains is known by construction.
#include "numbered_descriptors.h"
#include "rigid_motion.h"

#include <mid/registration/observation_pruning.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using mid::test::rigidMotion;

/** How far the stray landmark lies beyond the grid's end (metres). The landmark box spans the
  * 5th to 95th percentiles, here the grid without its outer columns and rows (5 mm in): the
  * stray landmark lies 55 mm outside the box, the grid's corners 5.4 mm.
  */
constexpr float kOffTheBox = 0.05f;

/** The default bounds of the pipeline (DiscoveryParameters). */
constexpr float kResidual = 0.005f;
constexpr float kMargin = 0.02f;

/** Landmark indices of the scene below. */
constexpr int kStray = 0, kFirstOnGrid = 1, kOnGrid = 189, kOwn = 190, kUnseen = 191;

/** Each landmark and keypoint carries in its curvature field the index of the landmark it was
  * made as (and each descriptor in its first bin), so that renumbering can be checked.
  */
struct PruningScene
{
  mid::ObjectModel model;
  mid::KeypointCloud keypoints;
};

pcl::PointNormal
pointAt (const Eigen::Vector3f& position, int id)
{
  pcl::PointNormal point;
  point.getVector3fMap() = position;
  point.getNormalVector3fMap() = Eigen::Vector3f::UnitZ();
  point.curvature = static_cast<float> (id);
  return point;
}

void
observe (PruningScene& scene,
         std::size_t instance,
         int landmark,
         const Eigen::Vector3f& offset = Eigen::Vector3f::Zero())
{
  auto& observer = scene.model.instances[instance];
  const Eigen::Vector3f at =
      scene.model.landmarks[static_cast<std::size_t> (landmark)].getVector3fMap() +
      offset;
  const Eigen::Vector3f camera =
      observer.pose.topLeftCorner<3, 3>() * at + observer.pose.topRightCorner<3, 1>();
  observer.keypoints.push_back (static_cast<pcl::index_t> (scene.keypoints.size()));
  observer.landmarks.push_back (landmark);
  scene.keypoints.push_back (pointAt (camera, landmark));
}

/** A model and the keypoints its instances observe:
  * - landmark 0 ("stray"): kOffTheBox beyond the grid's end, observed at its place by
  *   instances 0 and 1 (a keypoint of a neighbouring copy that a cluster spanning two copies
  *   brought into both); first, so that removing it renumbers every other landmark;
  * - landmarks 1..189: a 21 x 9 grid over a 100 x 40 mm rectangle (z = 0);
  * - landmark 190 ("own"): 30 mm beyond the grid's long side (35 mm outside the box),
  *   observed at its place by instance 1 alone (a face only that copy shows);
  * - landmark 191 ("unseen"): inside the rectangle, observed by no instance;
  * - one descriptor per landmark;
  * - instance 0 observes the grid exactly; instance 1 too, except landmark 8, which it
  *   observes 20 mm away from where its pose puts it (along the grid, inside the box);
  *   instance 2 observes the grid 30 mm above it everywhere (a pose that rests on other
  *   evidence).
  */
PruningScene
pruningScene ()
{
  PruningScene scene;
  scene.model.landmarks.push_back (
      pointAt (Eigen::Vector3f (0.05f + kOffTheBox, 0.0f, 0.0f), kStray));
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j <= 8; ++j)
      scene.model.landmarks.push_back (
          pointAt (Eigen::Vector3f (-0.05f + 0.005f * static_cast<float> (i),
                                    -0.02f + 0.005f * static_cast<float> (j),
                                    0.0f),
                   static_cast<int> (scene.model.landmarks.size())));
  scene.model.landmarks.push_back (pointAt (Eigen::Vector3f (0.0f, 0.05f, 0.0f), kOwn));
  scene.model.landmarks.push_back (
      pointAt (Eigen::Vector3f (0.0f, 0.01f, 0.0f), kUnseen));
  mid::test::describeLandmarksByNumber (scene.model);
  for (int n = 0; n < 3; ++n) {
    mid::ModelInstance instance;
    instance.pose =
        rigidMotion (Eigen::Vector3f (0.2f * static_cast<float> (n), 0.05f, 0.8f),
                     0.5f + 0.7f * static_cast<float> (n),
                     Eigen::Vector3f (1.0f, 2.0f, 3.0f))
            .matrix();
    scene.model.instances.push_back (instance);
  }
  const Eigen::Vector3f along (0.02f, 0.0f, 0.0f);
  const Eigen::Vector3f above (0.0f, 0.0f, 0.03f);
  for (int l = kFirstOnGrid; l < kFirstOnGrid + kOnGrid; ++l) {
    observe (scene, 0, l);
    observe (scene, 1, l, l == 8 ? along : Eigen::Vector3f::Zero());
    observe (scene, 2, l, above);
  }
  observe (scene, 0, kStray);
  observe (scene, 1, kStray);
  observe (scene, 1, kOwn);
  mid::updateModelDiameter (scene.model);
  return scene;
}

} // namespace

TEST (ObservationPruning, DropsWhatThePoseDoesNotExplainAndTheLandmarksOnlyThatHeld)
{
  PruningScene scene = pruningScene();
  std::size_t dropped = 0;
  ASSERT_TRUE (mid::pruneUnexplainedObservations (
      scene.keypoints, kResidual, kMargin, scene.model, dropped));
  // Both observations of the stray landmark (55 mm outside the box) and instance 1's of
  // landmark 8 (20 mm off); instance 1's own landmark stays, however far outside the box;
  // instance 2, which explains none of its observations, keeps them all; the grid's corners,
  // just outside the trimmed box, stay.
  EXPECT_EQ (dropped, 3u);
  const auto& model = scene.model;
  ASSERT_EQ (model.instances.size(), 3u);
  const auto grid = static_cast<std::size_t> (kOnGrid);
  EXPECT_EQ (model.instances[0].keypoints.size(), grid);
  EXPECT_EQ (model.instances[1].keypoints.size(), grid);
  EXPECT_EQ (model.instances[2].keypoints.size(), grid);
  EXPECT_NEAR (model.instances[0].rms_error, 0.0f, 1e-5f);
  EXPECT_NEAR (model.instances[1].rms_error, 0.0f, 1e-5f);

  // The stray landmark lost every observation and goes with its descriptor; landmark 8
  // (still observed by instances 0 and 2), the own and the unseen landmarks stay, every one
  // renumbered.
  ASSERT_EQ (model.landmarks.size(), 191u);
  ASSERT_EQ (model.descriptors.size(), 191u);
  ASSERT_EQ (model.descriptor_landmarks.size(), 191u);
  EXPECT_FLOAT_EQ (model.landmarks.front().curvature, 1.0f);
  EXPECT_FLOAT_EQ (model.landmarks.back().curvature, static_cast<float> (kUnseen));
  for (std::size_t d = 0; d < model.descriptors.size(); ++d)
    EXPECT_FLOAT_EQ (
        model.landmarks[static_cast<std::size_t> (model.descriptor_landmarks[d])]
            .curvature,
        model.descriptors[d].histogram[0]);
  // Every observation still names the landmark its keypoint was made from, and the first two
  // instances place each of theirs on its keypoint.
  for (std::size_t n = 0; n < model.instances.size(); ++n) {
    const auto& instance = model.instances[n];
    ASSERT_EQ (instance.keypoints.size(), instance.landmarks.size());
    for (std::size_t o = 0; o < instance.keypoints.size(); ++o) {
      const auto& keypoint =
          scene.keypoints[static_cast<std::size_t> (instance.keypoints[o])];
      const auto& landmark =
          model.landmarks[static_cast<std::size_t> (instance.landmarks[o])];
      EXPECT_FLOAT_EQ (landmark.curvature, keypoint.curvature);
      if (n < 2) {
        EXPECT_LT ((instance.pose.topLeftCorner<3, 3>() * landmark.getVector3fMap() +
                    instance.pose.topRightCorner<3, 1>() - keypoint.getVector3fMap())
                       .norm(),
                   1e-5f);
      }
    }
  }
  // The diameter is the rectangle's diagonal again (the own landmark lies nearer to every
  // corner), no longer reaching the stray landmark 0.15 m from the far corner.
  EXPECT_GT (pruningScene().model.diameter, 0.15f);
  EXPECT_NEAR (model.diameter, std::hypot (0.1f, 0.04f), 1e-4f);
}

TEST (ObservationPruning, LooserBoundsKeepMore)
{
  // A residual bound above 20 mm keeps landmark 8's far observation; a box margin above
  // 55 mm keeps the stray landmark's two.
  PruningScene residual = pruningScene();
  std::size_t dropped = 0;
  ASSERT_TRUE (mid::pruneUnexplainedObservations (
      residual.keypoints, 0.021f, kMargin, residual.model, dropped));
  EXPECT_EQ (dropped, 2u);
  EXPECT_EQ (residual.model.instances[1].keypoints.size(), 190u);
  EXPECT_EQ (residual.model.landmarks.size(), 191u);

  PruningScene margin = pruningScene();
  ASSERT_TRUE (mid::pruneUnexplainedObservations (
      margin.keypoints, kResidual, kOffTheBox + 0.006f, margin.model, dropped));
  EXPECT_EQ (dropped, 1u);
  EXPECT_EQ (margin.model.landmarks.size(), 192u);
}

TEST (ObservationPruning, AnInstanceWithoutAFinitePoseKeepsItsObservations)
{
  // Instance 1 has no pose to judge by: it keeps all of its observations, among them the
  // stray landmark's, which therefore stays; instance 0 still drops its own.
  PruningScene scene = pruningScene();
  scene.model.instances[1].pose (0, 3) = std::numeric_limits<float>::quiet_NaN();
  const pcl::Indices before = scene.model.instances[1].keypoints;
  std::size_t dropped = 0;
  ASSERT_TRUE (mid::pruneUnexplainedObservations (
      scene.keypoints, kResidual, kMargin, scene.model, dropped));
  EXPECT_EQ (dropped, 1u);
  EXPECT_EQ (scene.model.instances[1].keypoints, before);
  EXPECT_EQ (scene.model.landmarks.size(), 192u);
}

TEST (ObservationPruning, RefusesBadBoundsAndObservationsLeavingTheModelAsItWas)
{
  const PruningScene original = pruningScene();
  const auto expectRefused = [] (PruningScene scene, float residual, float margin) {
    const PruningScene before = scene;
    std::size_t dropped = 7;
    EXPECT_FALSE (mid::pruneUnexplainedObservations (
        scene.keypoints, residual, margin, scene.model, dropped));
    EXPECT_EQ (dropped, 0u);
    EXPECT_EQ (scene.model.landmarks.size(), before.model.landmarks.size());
    EXPECT_EQ (scene.model.descriptor_landmarks, before.model.descriptor_landmarks);
    for (std::size_t n = 0; n < scene.model.instances.size(); ++n) {
      EXPECT_EQ (scene.model.instances[n].keypoints,
                 before.model.instances[n].keypoints);
      EXPECT_EQ (scene.model.instances[n].landmarks,
                 before.model.instances[n].landmarks);
    }
  };
  expectRefused (original, 0.0f, kMargin);
  expectRefused (original, std::numeric_limits<float>::quiet_NaN(), kMargin);
  expectRefused (original, kResidual, -0.001f);
  PruningScene missing_keypoint = original;
  missing_keypoint.model.instances[1].keypoints[3] =
      static_cast<pcl::index_t> (original.keypoints.size());
  expectRefused (missing_keypoint, kResidual, kMargin);
  PruningScene missing_landmark = original;
  missing_landmark.model.instances[0].landmarks[0] = 500;
  expectRefused (missing_landmark, kResidual, kMargin);
  PruningScene bad_descriptor = original;
  bad_descriptor.model.descriptor_landmarks[0] = -1;
  expectRefused (bad_descriptor, kResidual, kMargin);
}
