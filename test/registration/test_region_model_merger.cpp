#include "rigid_motion.h"

#include <mid/registration/region_model_merger.h>

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace {

using mid::test::poseError;
using mid::test::rigidMotion;

/** Points of a flat 160 x 60 mm plate (object frame, z = 0): 20 on its left part (first
  * model's landmarks), 15 on a middle band that no model holds, 20 on its right part (second
  * model's landmarks).
  */
constexpr int kLeft = 20, kMiddle = 15, kRight = 20;
constexpr int kPoints = kLeft + kMiddle + kRight;

/** Frames of keypoints with known copies: every copy shows all kPoints points of its object,
  * each object point with its own random descriptor (the same on every copy of that object, up
  * to a little noise).
  */
class RegionModelMerger : public ::testing::Test
{
protected:
  void
  SetUp () override
  {
    std::mt19937 rng (11);
    // Points in [x_low, x_high] x [-half_width, half_width], one coordinate per statement.
    const auto add = [&] (float x_low, float x_high, float half_width, int count) {
      std::uniform_real_distribution<float> x (x_low, x_high),
          y (-half_width, half_width);
      for (int p = 0; p < count; ++p) {
        const float px = x (rng);
        const float py = y (rng);
        object_.emplace_back (px, py, 0.0f);
      }
    };
    add (-0.08f, -0.005f, 0.03f, kLeft);
    add (-0.008f, 0.008f, 0.008f, kMiddle);
    add (0.005f, 0.08f, 0.03f, kRight);
    std::uniform_real_distribution<float> bin (0.0f, 100.0f);
    for (auto& appearance : appearances_)
      for (int p = 0; p < kPoints; ++p) {
        mid::SIFTDescriptor descriptor;
        for (float& value : descriptor.histogram)
          value = bin (rng);
        appearance.push_back (descriptor);
      }
  }

  /** Add a copy of object `type` (0 or 1) at `pose` to the frame. */
  void
  addCopy (int type, const Eigen::Isometry3f& pose)
  {
    std::mt19937 rng (static_cast<std::uint32_t> (100 + poses_.size()));
    std::uniform_real_distribution<float> noise (-2.0f, 2.0f);
    poses_.push_back (pose.matrix());
    for (int p = 0; p < kPoints; ++p) {
      pcl::PointNormal k;
      k.getVector3fMap() = pose * object_[static_cast<std::size_t> (p)];
      k.getNormalVector3fMap() = -pose.linear().col (2);
      keypoints_->push_back (k);
      mid::SIFTDescriptor descriptor =
          appearances_[static_cast<std::size_t> (type)][static_cast<std::size_t> (p)];
      for (float& value : descriptor.histogram)
        value += noise (rng);
      descriptors_->push_back (descriptor);
    }
  }

  /** A model of object points [first, first + count) in a model frame moved by `frame` from
    * the object's, with one instance on each given copy observing those points.
    */
  mid::ObjectModel
  modelOf (int first,
           int count,
           const Eigen::Isometry3f& frame,
           const std::vector<int>& copies) const
  {
    mid::ObjectModel model;
    for (int l = 0; l < count; ++l) {
      const int point = first + l;
      const int observation = copies.front() * kPoints + point;
      pcl::PointNormal landmark;
      landmark.getVector3fMap() = frame * object_[static_cast<std::size_t> (point)];
      landmark.getNormalVector3fMap() = -frame.linear().col (2);
      model.landmarks.push_back (landmark);
      model.descriptors.push_back (
          (*descriptors_)[static_cast<std::size_t> (observation)]);
      model.descriptor_landmarks.push_back (l);
    }
    for (const int copy : copies) {
      mid::ModelInstance instance;
      instance.pose =
          poses_[static_cast<std::size_t> (copy)] * frame.inverse().matrix();
      for (int l = 0; l < count; ++l) {
        instance.keypoints.push_back (copy * kPoints + first + l);
        instance.landmarks.push_back (l);
      }
      model.instances.push_back (instance);
    }
    mid::updateModelDiameter (model);
    return model;
  }

  /** A merger on the fixture's frame with its defaults. */
  mid::RegionModelMerger
  merger () const
  {
    mid::RegionModelMerger merger;
    merger.setInputKeypoints (keypoints_);
    merger.setInputDescriptors (descriptors_);
    return merger;
  }

  /** The copy an instance observes (all its keypoints lie on one copy here). */
  static int
  copyOf (const mid::ModelInstance& instance)
  {
    return instance.keypoints.front() / kPoints;
  }

  std::vector<Eigen::Vector3f> object_;
  std::vector<mid::SIFTDescriptor> appearances_[2];
  std::vector<Eigen::Matrix4f> poses_;
  mid::KeypointCloud::Ptr keypoints_ = pcl::make_shared<mid::KeypointCloud>();
  mid::SIFTDescriptorCloud::Ptr descriptors_ =
      pcl::make_shared<mid::SIFTDescriptorCloud>();
};

} // namespace

TEST_F (RegionModelMerger, MergesTwoModelsOfOneObjectThroughTheSurfaceNeitherHolds)
{
  // Four copies of one plate; copies 0 and 1 paired on the left part, 2 and 3 on the right.
  addCopy (0, rigidMotion (Eigen::Vector3f (-0.3f, 0.0f, 0.8f), 0.4f));
  addCopy (0, rigidMotion (Eigen::Vector3f (-0.1f, 0.1f, 0.85f), 2.1f));
  addCopy (0, rigidMotion (Eigen::Vector3f (0.1f, -0.1f, 0.8f), -1.2f, {0, 1, 4}));
  addCopy (0, rigidMotion (Eigen::Vector3f (0.3f, 0.05f, 0.9f), 3.0f));
  mid::ObjectModels models{
      modelOf (0, kLeft, rigidMotion ({0.01f, 0.02f, 0.0f}, 0.3f), {0, 1}),
      modelOf (
          kLeft + kMiddle, kRight, rigidMotion ({0.0f, -0.03f, 0.01f}, -0.7f), {2, 3})};
  // The models share no landmark and no copy: the paper's model comparison has nothing to
  // match; the middle band, around the instances of both, holds 15 common points.
  mid::RegionModelMerger merge = merger();
  ASSERT_TRUE (merge.merge (models));
  EXPECT_EQ (merge.getMergedCount(), 1u);
  ASSERT_EQ (models.size(), 1u);
  ASSERT_EQ (models.front().instances.size(), 4u);
  // Every instance where its copy is, relative to copy 0's: the true relative poses.
  const mid::ModelInstances& instances = models.front().instances;
  const auto on_copy = [&] (int copy) {
    for (const auto& instance : instances)
      if (copyOf (instance) == copy)
        return instance.pose;
    ADD_FAILURE() << "no instance on copy " << copy;
    return Eigen::Matrix4f (Eigen::Matrix4f::Identity());
  };
  for (int copy = 1; copy < 4; ++copy) {
    const auto [angle, distance] =
        poseError (on_copy (copy) * on_copy (0).inverse(),
                   poses_[static_cast<std::size_t> (copy)] * poses_[0].inverse());
    EXPECT_LT (angle, 1e-3) << "copy " << copy;
    EXPECT_LT (distance, 1e-4) << "copy " << copy;
  }
}

TEST_F (RegionModelMerger, KeepsModelsOfDifferentObjectsApart)
{
  // The same geometry, but copies 2 and 3 are another object: nothing in common to find.
  addCopy (0, rigidMotion (Eigen::Vector3f (-0.3f, 0.0f, 0.8f), 0.4f));
  addCopy (0, rigidMotion (Eigen::Vector3f (-0.1f, 0.1f, 0.85f), 2.1f));
  addCopy (1, rigidMotion (Eigen::Vector3f (0.1f, -0.1f, 0.8f), -1.2f));
  addCopy (1, rigidMotion (Eigen::Vector3f (0.3f, 0.05f, 0.9f), 3.0f));
  const mid::ObjectModels before{
      modelOf (0, kLeft, Eigen::Isometry3f::Identity(), {0, 1}),
      modelOf (kLeft + kMiddle, kRight, Eigen::Isometry3f::Identity(), {2, 3})};
  mid::ObjectModels models = before;
  mid::RegionModelMerger merge = merger();
  ASSERT_TRUE (merge.merge (models));
  EXPECT_EQ (merge.getMergedCount(), 0u);
  ASSERT_EQ (models.size(), 2u);
  for (std::size_t m = 0; m < 2; ++m) {
    ASSERT_EQ (models[m].instances.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i)
      EXPECT_TRUE (models[m].instances[i].pose.isApprox (before[m].instances[i].pose));
  }
}

TEST_F (RegionModelMerger, AKeypointAroundTwoTouchingCopiesMatchesNeitherWay)
{
  // Copy 2, another object, touches copy 0 side by side. With regions 10 cm wide, each copy's
  // free keypoints lie around both: matched to themselves, they would give copy 0's pose to
  // copy 2 and merge the two objects.
  addCopy (0, rigidMotion (Eigen::Vector3f (-0.3f, 0.0f, 0.8f), 0.0f));
  addCopy (0, rigidMotion (Eigen::Vector3f (-0.1f, 0.2f, 0.85f), 2.1f));
  addCopy (1, rigidMotion (Eigen::Vector3f (-0.3f, 0.07f, 0.8f), 0.0f));
  addCopy (1, rigidMotion (Eigen::Vector3f (0.3f, 0.05f, 0.9f), 3.0f));
  mid::ObjectModels models{modelOf (0, kLeft, Eigen::Isometry3f::Identity(), {0, 1}),
                           modelOf (0, kLeft, Eigen::Isometry3f::Identity(), {2, 3})};
  mid::RegionModelMerger merge = merger();
  merge.setRegionMargin (0.1f);
  ASSERT_TRUE (merge.merge (models));
  EXPECT_EQ (merge.getMergedCount(), 0u);
  EXPECT_EQ (models.size(), 2u);
}

TEST_F (RegionModelMerger, RefusesUnusableInputWithoutTouchingTheModels)
{
  addCopy (0, rigidMotion (Eigen::Vector3f (-0.3f, 0.0f, 0.8f), 0.4f));
  addCopy (0, rigidMotion (Eigen::Vector3f (-0.1f, 0.1f, 0.85f), 2.1f));
  addCopy (0, rigidMotion (Eigen::Vector3f (0.1f, -0.1f, 0.8f), -1.2f));
  const mid::ObjectModels before{
      modelOf (0, kLeft, Eigen::Isometry3f::Identity(), {0, 1}),
      modelOf (kLeft + kMiddle, kRight, Eigen::Isometry3f::Identity(), {1, 2})};
  const auto expectRefused = [&] (mid::RegionModelMerger merge,
                                  const mid::ObjectModels& input) {
    mid::ObjectModels models = input;
    EXPECT_FALSE (merge.merge (models));
    EXPECT_EQ (merge.getMergedCount(), 0u);
    ASSERT_EQ (models.size(), input.size());
    for (std::size_t m = 0; m < models.size(); ++m)
      EXPECT_EQ (models[m].instances.size(), input[m].instances.size());
  };
  expectRefused (mid::RegionModelMerger(), before);
  mid::RegionModelMerger short_descriptors = merger();
  auto fewer = pcl::make_shared<mid::SIFTDescriptorCloud> (*descriptors_);
  fewer->resize (fewer->size() - 1);
  short_descriptors.setInputDescriptors (fewer);
  expectRefused (short_descriptors, before);
  mid::RegionModelMerger negative_margin = merger();
  negative_margin.setRegionMargin (-0.01f);
  expectRefused (negative_margin, before);
  mid::RegionModelMerger bad_detector = merger();
  mid::ModelInstanceDetector detector;
  detector.setInlierThreshold (-1.0f);
  bad_detector.setDetector (detector);
  expectRefused (bad_detector, before);
  mid::ObjectModels outside = before;
  outside.back().instances.back().keypoints.back() =
      static_cast<pcl::index_t> (keypoints_->size());
  expectRefused (merger(), outside);
}
