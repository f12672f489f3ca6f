// pruneObservationsOnOtherCopies on copies of a printed face lying in a row at known poses:
// which keypoint lies on which copy is known by construction.
#include "numbered_descriptors.h"
#include "rigid_motion.h"

#include <mid/registration/observation_pruning.h>

#include <gtest/gtest.h>

#include <limits>
#include <vector>

namespace {

using mid::test::rigidMotion;

/** Side of the square face the landmarks cover, and their spacing (metres). */
constexpr float kFace = 0.04f;
constexpr float kStep = 0.005f;
/** Where a copy's keypoint lies on its right-hand neighbour, seen from the copy's own frame:
  * on the neighbour's face, 2 mm right of and 1 mm above its centre (`row` copies apart).
  */
Eigen::Vector3f
onNeighbour (float row)
{
  return {row + 0.002f, 0.001f, 0.0f};
}

/** A row of copies of one face and the keypoints their instances observe. */
struct RowScene
{
  mid::ObjectModel model;
  mid::KeypointCloud keypoints;
  /** Which copy each keypoint lies on. */
  std::vector<int> copy_of;
};

/** Keypoint of `instance` observing `landmark`, at `at` in the model frame; it lies on `copy`. */
void
observe (RowScene& scene,
         std::size_t instance,
         int landmark,
         const Eigen::Vector3f& at,
         int copy)
{
  auto& observer = scene.model.instances[instance];
  pcl::PointNormal point;
  point.getVector3fMap() =
      observer.pose.topLeftCorner<3, 3>() * at + observer.pose.topRightCorner<3, 1>();
  point.getNormalVector3fMap() = observer.pose.col (2).head<3>();
  observer.keypoints.push_back (static_cast<pcl::index_t> (scene.keypoints.size()));
  observer.landmarks.push_back (landmark);
  scene.keypoints.push_back (point);
  scene.copy_of.push_back (copy);
}

/** Three copies of a 40 mm face in a row, `row` metres apart (centre to centre), on a slanted
  * table: landmarks on a 9 x 9 grid over the face, and one more (the last) where a copy's
  * right-hand neighbour lies (onNeighbour()): the model holds it because two copies show it,
  * each on its neighbour. Instance n is copy n: it observes the whole grid; instances 0 and 1
  * also observe the neighbour's landmark, a keypoint on copy 1 and copy 2.
  */
RowScene
rowScene (float row)
{
  RowScene scene;
  for (int i = 0; i <= 8; ++i)
    for (int j = 0; j <= 8; ++j) {
      pcl::PointNormal landmark;
      landmark.getVector3fMap() =
          Eigen::Vector3f (-0.5f * kFace + kStep * static_cast<float> (i),
                           -0.5f * kFace + kStep * static_cast<float> (j),
                           0.0f);
      scene.model.landmarks.push_back (landmark);
    }
  pcl::PointNormal neighbour;
  neighbour.getVector3fMap() = onNeighbour (row);
  scene.model.landmarks.push_back (neighbour);
  mid::test::describeLandmarksByNumber (scene.model);
  const Eigen::Isometry3f table = rigidMotion (
      Eigen::Vector3f (-0.1f, 0.05f, 0.8f), 0.6f, Eigen::Vector3f (1.0f, 0.2f, 0.1f));
  for (int n = 0; n < 3; ++n) {
    mid::ModelInstance instance;
    instance.pose =
        (table * Eigen::Translation3f (row * static_cast<float> (n), 0.0f, 0.0f))
            .matrix();
    scene.model.instances.push_back (instance);
  }
  const int stray = static_cast<int> (scene.model.landmarks.size()) - 1;
  for (std::size_t n = 0; n < 3; ++n) {
    for (int l = 0; l < stray; ++l)
      observe (scene,
               n,
               l,
               scene.model.landmarks[static_cast<std::size_t> (l)].getVector3fMap(),
               static_cast<int> (n));
    if (n < 2)
      observe (scene, n, stray, onNeighbour (row), static_cast<int> (n) + 1);
  }
  mid::updateModelDiameter (scene.model);
  return scene;
}

/** Every kept observation of instance n lies on copy n. */
void
expectOnOwnCopies (const RowScene& scene)
{
  for (std::size_t n = 0; n < scene.model.instances.size(); ++n)
    for (const auto k : scene.model.instances[n].keypoints)
      EXPECT_EQ (scene.copy_of[static_cast<std::size_t> (k)], static_cast<int> (n))
          << "instance " << n << ", keypoint " << k;
}

} // namespace

TEST (ObservationsOnOtherCopies, DropsAKeypointAmidAnotherCopysKeypoints)
{
  // Copies 5 cm apart, a 1 cm gap between their faces.
  RowScene scene = rowScene (0.05f);
  const std::size_t landmarks = scene.model.landmarks.size();
  std::size_t dropped = 0;
  ASSERT_TRUE (
      mid::pruneObservationsOnOtherCopies (scene.keypoints, scene.model, dropped));
  EXPECT_EQ (dropped, 2u);
  ASSERT_EQ (scene.model.instances.size(), 3u);
  for (const auto& instance : scene.model.instances)
    EXPECT_EQ (instance.keypoints.size(), 81u);
  expectOnOwnCopies (scene);
  // The neighbour's landmark lost both its observations and goes with its descriptor.
  EXPECT_EQ (scene.model.landmarks.size(), landmarks - 1);
  EXPECT_EQ (scene.model.descriptors.size(), landmarks - 1);
  EXPECT_NEAR (scene.model.diameter, std::sqrt (2.0f) * kFace, 1e-4f);
  // The poses are not changed: the copies are still 5 cm apart.
  EXPECT_NEAR ((scene.model.instances[1].pose.topRightCorner<3, 1>() -
                scene.model.instances[0].pose.topRightCorner<3, 1>())
                   .norm(),
               0.05f,
               1e-5f);
}

TEST (ObservationsOnOtherCopies, KeepsTheBordersOfCopiesTouchingInARow)
{
  // Faces 1 mm apart: each border keypoint lies 1 mm from the neighbour's border, nearer than
  // its own copy's next keypoint (5 mm), but outside the neighbour's radius: kept. The keypoint
  // on the neighbour's face goes.
  RowScene scene = rowScene (kFace + 0.001f);
  std::size_t dropped = 0;
  ASSERT_TRUE (
      mid::pruneObservationsOnOtherCopies (scene.keypoints, scene.model, dropped));
  EXPECT_EQ (dropped, 2u);
  for (const auto& instance : scene.model.instances)
    EXPECT_EQ (instance.keypoints.size(), 81u);
  expectOnOwnCopies (scene);
}

TEST (ObservationsOnOtherCopies, NeedsTheOtherCopyToShowThreePlaces)
{
  // Copy 1's instance keeps three keypoints at its face's centre, two of them at one place
  // (SIFT gives one keypoint two orientations): two places judge nothing, and instance 0 keeps
  // its keypoint on copy 1.
  const auto keepOnSecond = [] (RowScene& scene, const std::vector<int>& landmarks) {
    auto& second = scene.model.instances[1];
    pcl::Indices keypoints;
    for (const int l : landmarks)
      keypoints.push_back (second.keypoints[static_cast<std::size_t> (l)]);
    second.keypoints = keypoints;
    second.landmarks = landmarks;
  };
  RowScene two = rowScene (0.05f);
  keepOnSecond (two, {40, 40, 41});
  std::size_t dropped = 0;
  ASSERT_TRUE (mid::pruneObservationsOnOtherCopies (two.keypoints, two.model, dropped));
  EXPECT_EQ (dropped, 0u);
  EXPECT_EQ (two.model.instances[0].keypoints.size(), 82u);

  // A third place makes copy 1 a judge again.
  RowScene three = rowScene (0.05f);
  keepOnSecond (three, {40, 41, 49});
  ASSERT_TRUE (
      mid::pruneObservationsOnOtherCopies (three.keypoints, three.model, dropped));
  EXPECT_EQ (dropped, 1u);
  EXPECT_EQ (three.model.instances[0].keypoints.size(), 81u);
  expectOnOwnCopies (three);
}

TEST (ObservationsOnOtherCopies, AnInstanceAllOnAnotherCopyKeepsItsObservations)
{
  // An instance whose every keypoint lies amid copy 1's keeps them all (its pose rests on
  // other evidence); copy 2 still takes its keypoint from instance 1.
  RowScene scene = rowScene (0.05f);
  auto& first = scene.model.instances[0];
  first.keypoints = {first.keypoints.back()};
  first.landmarks = {first.landmarks.back()};
  std::size_t dropped = 0;
  ASSERT_TRUE (
      mid::pruneObservationsOnOtherCopies (scene.keypoints, scene.model, dropped));
  EXPECT_EQ (dropped, 1u);
  EXPECT_EQ (scene.model.instances[0].keypoints.size(), 1u);
}

TEST (ObservationsOnOtherCopies, RefusesBadObservationsLeavingTheModelAsItWas)
{
  const RowScene original = rowScene (0.05f);
  const auto expectRefused = [] (RowScene scene) {
    const RowScene before = scene;
    std::size_t dropped = 7;
    EXPECT_FALSE (
        mid::pruneObservationsOnOtherCopies (scene.keypoints, scene.model, dropped));
    EXPECT_EQ (dropped, 0u);
    EXPECT_EQ (scene.model.landmarks.size(), before.model.landmarks.size());
    for (std::size_t n = 0; n < scene.model.instances.size(); ++n)
      EXPECT_EQ (scene.model.instances[n].keypoints,
                 before.model.instances[n].keypoints);
  };
  RowScene missing_keypoint = original;
  missing_keypoint.model.instances[1].keypoints[3] =
      static_cast<pcl::index_t> (original.keypoints.size());
  expectRefused (missing_keypoint);
  RowScene missing_landmark = original;
  missing_landmark.model.instances[0].landmarks[0] = 500;
  expectRefused (missing_landmark);
  RowScene unequal = original;
  unequal.model.instances[2].landmarks.pop_back();
  expectRefused (unequal);
  RowScene bad_descriptor = original;
  bad_descriptor.model.descriptor_landmarks[0] = -1;
  expectRefused (bad_descriptor);
}
