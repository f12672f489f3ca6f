#include "rigid_motion.h"

#include <mid/registration/instance_overlap.h>

#include <gtest/gtest.h>

#include <limits>
#include <random>

namespace {

using mid::test::poseError;
using mid::test::rigidMotion;

/** Points on the object's top face (landmarks 0-19); landmarks 20-39 lie on a side face. */
constexpr int kFace = 20;
constexpr int kLandmarks = 2 * kFace;

/** Three copies of one box at known poses, 20 cm apart: 20 points with their normals on its
  * 10 x 8 cm top face (facing the camera), 20 on a 10 x 6 cm side face perpendicular to it.
  */
class InstanceOverlap : public ::testing::Test
{
protected:
  void
  SetUp () override
  {
    std::mt19937 rng (5);
    std::uniform_real_distribution<float> x (-0.05f, 0.05f), y (-0.04f, 0.04f),
        z (0.0f, 0.06f);
    for (int l = 0; l < kFace; ++l) {
      const float px = x (rng), py = y (rng);
      object_.emplace_back (px, py, 0.0f);
      normals_.emplace_back (0.0f, 0.0f, -1.0f);
    }
    for (int l = 0; l < kFace; ++l) {
      const float px = x (rng), pz = z (rng);
      object_.emplace_back (px, 0.04f, pz);
      normals_.emplace_back (0.0f, 1.0f, 0.0f);
    }
    poses_ = {rigidMotion (Eigen::Vector3f (-0.2f, 0.0f, 0.8f), 0.3f).matrix(),
              rigidMotion (Eigen::Vector3f (0.0f, 0.05f, 0.85f), -0.8f).matrix(),
              rigidMotion (Eigen::Vector3f (0.2f, 0.0f, 0.8f), 1.9f).matrix()};
    for (const auto& pose : poses_)
      for (std::size_t l = 0; l < object_.size(); ++l) {
        pcl::PointNormal k;
        k.getVector3fMap() =
            pose.topLeftCorner<3, 3>() * object_[l] + pose.topRightCorner<3, 1>();
        k.getNormalVector3fMap() = pose.topLeftCorner<3, 3>() * normals_[l];
        keypoints_.push_back (k);
      }
  }

  /** Expect one instance on each copy, each pose mapping every landmark it observes exactly
    * onto its keypoint, and the instance on copy `full` observing all of `full_size` keypoints.
    */
  void
  expectExactInstances (const mid::ObjectModel& model,
                        int full,
                        std::size_t full_size) const
  {
    ASSERT_EQ (model.instances.size(), poses_.size());
    std::vector<bool> found (poses_.size(), false);
    for (const auto& instance : model.instances) {
      for (std::size_t o = 0; o < instance.keypoints.size(); ++o) {
        const Eigen::Vector3f landmark =
            model.landmarks[static_cast<std::size_t> (instance.landmarks[o])]
                .getVector3fMap();
        const Eigen::Vector3f moved = instance.pose.topLeftCorner<3, 3>() * landmark +
                                      instance.pose.topRightCorner<3, 1>();
        EXPECT_LT ((moved - keypoints_[static_cast<std::size_t> (instance.keypoints[o])]
                                .getVector3fMap())
                       .norm(),
                   1e-5f);
      }
      const int copy = instance.keypoints.front() / kLandmarks;
      found[static_cast<std::size_t> (copy)] = true;
      if (copy == full) {
        EXPECT_EQ (instance.keypoints.size(), full_size);
      }
    }
    EXPECT_EQ (found, std::vector<bool> (poses_.size(), true));
  }

  /** A model of landmarks [first, last) in a frame moved by `frame` from the object's, with
    * instances on the given copies.
    */
  mid::ObjectModel
  modelOf (int first,
           int last,
           const Eigen::Matrix4f& frame,
           const std::vector<int>& copies) const
  {
    mid::ObjectModel model;
    for (int l = first; l < last; ++l) {
      pcl::PointNormal landmark;
      landmark.getVector3fMap() =
          frame.topLeftCorner<3, 3>() * object_[l] + frame.topRightCorner<3, 1>();
      model.landmarks.push_back (landmark);
      model.descriptors.push_back (mid::SIFTDescriptor());
      model.descriptor_landmarks.push_back (l - first);
    }
    for (const int copy : copies) {
      mid::ModelInstance instance;
      instance.pose = poses_[static_cast<std::size_t> (copy)] * frame.inverse();
      for (int l = first; l < last; ++l) {
        instance.keypoints.push_back (copy * kLandmarks + l);
        instance.landmarks.push_back (l - first);
      }
      model.instances.push_back (instance);
    }
    mid::updateModelDiameter (model);
    return model;
  }

  std::vector<Eigen::Vector3f> object_;
  std::vector<Eigen::Vector3f> normals_;
  std::vector<Eigen::Matrix4f> poses_;
  mid::KeypointCloud keypoints_;
};

mid::ModelInstance
instanceOn (int copy, int first, int last)
{
  mid::ModelInstance instance;
  for (int l = first; l < last; ++l) {
    instance.keypoints.push_back (copy * kLandmarks + l);
    instance.landmarks.push_back (l);
  }
  return instance;
}

} // namespace

TEST_F (InstanceOverlap, KeypointsOfOneCopyOverlapThoseOfAnotherDoNot)
{
  // Two halves of one face's keypoints overlap; the same halves on two copies do not.
  EXPECT_TRUE (mid::instancesOverlap (
      keypoints_, instanceOn (1, 0, 10), instanceOn (1, 10, 20)));
  EXPECT_FALSE (mid::instancesOverlap (
      keypoints_, instanceOn (0, 0, 10), instanceOn (1, 10, 20)));
  EXPECT_FALSE (
      mid::instancesOverlap (keypoints_, instanceOn (0, 0, 20), instanceOn (2, 0, 20)));
  EXPECT_FALSE (
      mid::instancesOverlap (keypoints_, mid::ModelInstance(), instanceOn (0, 0, 20)));
}

TEST_F (InstanceOverlap, TwoFacesOfOneCopyAdjoinDistantOnesDoNot)
{
  const auto top = [] (int copy) { return instanceOn (copy, 0, kFace); };
  const auto side = [] (int copy) { return instanceOn (copy, kFace, kLandmarks); };
  // The top and the side of one copy meet at an edge without intermixing.
  EXPECT_TRUE (mid::instancesAdjoin (keypoints_, top (1), side (1)));
  EXPECT_FALSE (mid::instancesOverlap (keypoints_, top (1), side (1)));
  // Faces of two copies 20 cm apart are too far.
  EXPECT_FALSE (mid::instancesAdjoin (keypoints_, top (0), side (1)));
  EXPECT_FALSE (mid::instancesAdjoin (keypoints_, side (1), top (2)));
  // The faces are 90 deg apart.
  EXPECT_TRUE (mid::instancesAdjoin (keypoints_, top (1), side (1), 1.5f));
  EXPECT_FALSE (mid::instancesAdjoin (keypoints_, top (1), side (1), 1.6f));
  EXPECT_FALSE (mid::instancesAdjoin (keypoints_, mid::ModelInstance(), side (1)));
}

TEST (InstanceAdjoin, CopiesTouchingAlongTheirLongSidesDoNotAdjoin)
{
  // Two copies of a 10 x 5 cm face, resting the same way up and touching along their long
  // sides: their footprints meet (centroids 0.77 sums of RMS radii apart), their normals are
  // parallel.
  mid::KeypointCloud keypoints;
  mid::ModelInstance copies[2];
  for (int copy = 0; copy < 2; ++copy)
    for (int i = 0; i < 10; ++i)
      for (int j = 0; j < 5; ++j) {
        pcl::PointNormal k;
        k.getVector3fMap() = Eigen::Vector3f (-0.045f + 0.01f * static_cast<float> (i),
                                              -0.02f + 0.01f * static_cast<float> (j) +
                                                  0.05f * static_cast<float> (copy),
                                              0.8f);
        k.getNormalVector3fMap() = Eigen::Vector3f (0.0f, 0.0f, -1.0f);
        copies[copy].keypoints.push_back (static_cast<pcl::index_t> (keypoints.size()));
        copies[copy].landmarks.push_back (i * 5 + j);
        keypoints.push_back (k);
      }
  EXPECT_FALSE (mid::instancesOverlap (keypoints, copies[0], copies[1]));
  EXPECT_FALSE (mid::instancesAdjoin (keypoints, copies[0], copies[1]));
  // Only the angle keeps them apart.
  EXPECT_TRUE (mid::instancesAdjoin (keypoints, copies[0], copies[1], 0.0f));
  // Tilt copy 1 by 90 deg (a side face): they adjoin; a non-finite normal is skipped.
  for (const auto k : copies[1].keypoints)
    keypoints[static_cast<std::size_t> (k)].getNormalVector3fMap() =
        Eigen::Vector3f (0.0f, 1.0f, 0.0f);
  keypoints[static_cast<std::size_t> (copies[1].keypoints.front())].normal_x =
      std::numeric_limits<float>::quiet_NaN();
  EXPECT_TRUE (mid::instancesAdjoin (keypoints, copies[0], copies[1]));
  // Normals that point every way (half up, half down) have no mean direction.
  for (std::size_t o = 0; o < copies[1].keypoints.size(); ++o)
    keypoints[static_cast<std::size_t> (copies[1].keypoints[o])]
        .getNormalVector3fMap() =
        Eigen::Vector3f (0.0f, o % 2 == 0 ? 1.0f : -1.0f, 0.0f);
  EXPECT_FALSE (mid::instancesAdjoin (keypoints, copies[0], copies[1], 0.0f));
}

TEST_F (InstanceOverlap, KeepsTheLargerOfTwoInstancesOnOneCopy)
{
  mid::ObjectModel model =
      modelOf (0, kLandmarks, Eigen::Matrix4f::Identity(), {0, 1, 2});
  // A fourth instance made of a few keypoints of copy 1 (a repeated pattern on its face).
  mid::ModelInstance echo = instanceOn (1, 0, 6);
  echo.pose = rigidMotion (Eigen::Vector3f (0.01f, 0.0f, 0.0f)).matrix() * poses_[1];
  model.instances.insert (model.instances.begin(), echo);
  EXPECT_EQ (mid::removeOverlappingInstances (keypoints_, model), 1u);
  ASSERT_EQ (model.instances.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i)
    EXPECT_LT (poseError (model.instances[i].pose, poses_[i]).second, 1e-6);
}

TEST_F (InstanceOverlap, MergesTwoModelsOfOneObjectIntoTheTruePoses)
{
  // Model A knows landmarks 0-11 of the top face on copies 0 and 1; model B, in another frame,
  // knows landmarks 8-19 on copies 1 and 2. They share copy 1 (and landmarks 8-11).
  const Eigen::Matrix4f frame_b = rigidMotion (Eigen::Vector3f (0.3f, -0.1f, 0.02f),
                                               1.1f,
                                               Eigen::Vector3f (1, 2, 3))
                                      .matrix();
  mid::ObjectModels models{modelOf (0, 12, Eigen::Matrix4f::Identity(), {0, 1}),
                           modelOf (8, kFace, frame_b, {1, 2})};
  EXPECT_EQ (mid::mergeOverlappingModels (keypoints_, models), 1u);
  ASSERT_EQ (models.size(), 1u);
  EXPECT_EQ (models.front().landmarks.size(), static_cast<std::size_t> (kFace));
  // The instance on copy 1 holds the observations of both models.
  expectExactInstances (models.front(), 1, kFace);
}

TEST_F (InstanceOverlap, MergesModelsOfTwoFacesThroughTheCopyThatShowsBoth)
{
  // Model A knows the top face on copies 0 and 1; model B, in another frame, the side face on
  // copies 1 and 2. No keypoint or descriptor links them, only copy 1, which shows both.
  const Eigen::Matrix4f frame_b = rigidMotion (Eigen::Vector3f (-0.2f, 0.1f, 0.05f),
                                               2.0f,
                                               Eigen::Vector3f (3, -1, 2))
                                      .matrix();
  mid::ObjectModels models{modelOf (0, kFace, Eigen::Matrix4f::Identity(), {0, 1}),
                           modelOf (kFace, kLandmarks, frame_b, {1, 2})};
  EXPECT_EQ (mid::mergeOverlappingModels (keypoints_, models), 1u);
  ASSERT_EQ (models.size(), 1u);
  EXPECT_EQ (models.front().landmarks.size(), static_cast<std::size_t> (kLandmarks));
  expectExactInstances (models.front(), 1, kLandmarks);
}

TEST_F (InstanceOverlap, AnotherCopyShowingBothFacesBecomesOneInstance)
{
  // A knows the top face on all three copies, B the side face on copies 1 and 2: linked
  // through one of them, B's instance on the other copy takes the pose of A's there and joins
  // it (the two do not overlap: their keypoints lie on different faces).
  const Eigen::Matrix4f frame_b = rigidMotion (Eigen::Vector3f (0.1f, 0.2f, -0.1f),
                                               -0.7f,
                                               Eigen::Vector3f (1, 1, 0))
                                      .matrix();
  mid::ObjectModels models{modelOf (0, kFace, Eigen::Matrix4f::Identity(), {0, 1, 2}),
                           modelOf (kFace, kLandmarks, frame_b, {1, 2})};
  EXPECT_EQ (mid::mergeOverlappingModels (keypoints_, models), 1u);
  ASSERT_EQ (models.size(), 1u);
  expectExactInstances (models.front(), 2, kLandmarks);
  for (const auto& instance : models.front().instances)
    EXPECT_EQ (instance.keypoints.size(),
               instance.keypoints.front() / kLandmarks == 0 ? kFace : kLandmarks);
}

TEST_F (InstanceOverlap, LeavesModelsOfDifferentCopiesApart)
{
  mid::ObjectModels models{modelOf (0, 12, Eigen::Matrix4f::Identity(), {0, 1}),
                           modelOf (8, kFace, Eigen::Matrix4f::Identity(), {2})};
  EXPECT_EQ (mid::mergeOverlappingModels (keypoints_, models), 0u);
  EXPECT_EQ (models.size(), 2u);
}
