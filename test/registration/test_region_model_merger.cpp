#include "rigid_motion.h"

#include <mid/registration/instance_region.h>
#include <mid/registration/region_model_merger.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
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
class RegionModelMergerTest : public ::testing::Test
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
    add (-0.005f, 0.005f, 0.008f, kMiddle);
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

  /** Give object 1 the appearance of object 0 on the first `count` points of the middle band
    * (two products that share a small print).
    */
  void
  shareMiddlePoints (int count)
  {
    for (int p = kLeft; p < kLeft + count; ++p)
      appearances_[1][static_cast<std::size_t> (p)] =
          appearances_[0][static_cast<std::size_t> (p)];
  }

  /** Two copies of object 0 and two of object 1, which shares the appearance of `common`
    * points of the middle band; a model of each object (left part, right part).
    */
  mid::ObjectModels
  twoObjectsSharing (int common)
  {
    shareMiddlePoints (common);
    addCopy (0, rigidMotion (Eigen::Vector3f (-0.3f, 0.0f, 0.8f), 0.4f));
    addCopy (0, rigidMotion (Eigen::Vector3f (-0.1f, 0.1f, 0.85f), 2.1f));
    addCopy (1, rigidMotion (Eigen::Vector3f (0.1f, -0.1f, 0.8f), -1.2f));
    addCopy (1, rigidMotion (Eigen::Vector3f (0.3f, 0.05f, 0.9f), 3.0f));
    return {modelOf (0, kLeft, Eigen::Isometry3f::Identity(), {0, 1}),
            modelOf (kLeft + kMiddle, kRight, Eigen::Isometry3f::Identity(), {2, 3})};
  }

  /** Expect one model with an instance on each of `copies` copies, each where its copy is
    * relative to the first copy's instance (the true relative poses).
    */
  void
  expectOneModelAtTheTruePoses (const mid::ObjectModels& models, int copies) const
  {
    ASSERT_EQ (models.size(), 1u);
    const mid::ModelInstances& instances = models.front().instances;
    ASSERT_EQ (instances.size(), static_cast<std::size_t> (copies));
    const auto on_copy = [&] (int copy) {
      for (const auto& instance : instances)
        if (copyOf (instance) == copy)
          return instance.pose;
      ADD_FAILURE() << "no instance on copy " << copy;
      return Eigen::Matrix4f (Eigen::Matrix4f::Identity());
    };
    for (int copy = 1; copy < copies; ++copy) {
      const auto [angle, distance] =
          poseError (on_copy (copy) * on_copy (0).inverse(),
                     poses_[static_cast<std::size_t> (copy)] * poses_[0].inverse());
      EXPECT_LT (angle, 1e-3) << "copy " << copy;
      EXPECT_LT (distance, 1e-4) << "copy " << copy;
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

TEST_F (RegionModelMergerTest, MergesTwoModelsOfOneObjectThroughTheSurfaceNeitherHolds)
{
  // Four copies of one plate; copies 0 and 1 paired on the left part, 2 and 3 on the right.
  addCopy (0, rigidMotion (Eigen::Vector3f (-0.3f, 0.0f, 0.8f), 0.4f));
  addCopy (0, rigidMotion (Eigen::Vector3f (-0.1f, 0.1f, 0.85f), 2.1f));
  addCopy (0, rigidMotion (Eigen::Vector3f (0.1f, -0.1f, 0.8f), -1.2f, {0, 1, 4}));
  addCopy (0, rigidMotion (Eigen::Vector3f (0.3f, 0.05f, 0.9f), 3.0f));
  const Eigen::Isometry3f frame_a = rigidMotion ({0.01f, 0.02f, 0.0f}, 0.3f);
  mid::ObjectModels models{
      modelOf (0, kLeft, frame_a, {0, 1}),
      modelOf (
          kLeft + kMiddle, kRight, rigidMotion ({0.0f, -0.03f, 0.01f}, -0.7f), {2, 3})};
  // The models share no landmark and no copy: the paper's model comparison has nothing to
  // match; the middle band, around the instances of both, holds 15 common points.
  mid::RegionModelMerger merge = merger();
  ASSERT_TRUE (merge.merge (models));
  EXPECT_EQ (merge.getMergedCount(), 1u);
  expectOneModelAtTheTruePoses (models, 4);
  // The second model's landmarks join the first's, in the first model's frame.
  ASSERT_EQ (models.front().landmarks.size(),
             static_cast<std::size_t> (kLeft + kRight));
  for (int l = 0; l < kRight; ++l)
    EXPECT_LT ((models.front()
                    .landmarks[static_cast<std::size_t> (kLeft + l)]
                    .getVector3fMap() -
                frame_a * object_[static_cast<std::size_t> (kLeft + kMiddle + l)])
                   .norm(),
               1e-4f);
}

TEST_F (RegionModelMergerTest, MergesEveryModelOfOneObjectInOnePass)
{
  // Three models of one plate: after the second merges into the first, the third (now second
  // in the list) is compared with the first too.
  addCopy (0, rigidMotion (Eigen::Vector3f (-0.3f, 0.0f, 0.8f), 0.4f));
  addCopy (0, rigidMotion (Eigen::Vector3f (-0.1f, 0.1f, 0.85f), 2.1f));
  addCopy (0, rigidMotion (Eigen::Vector3f (0.1f, -0.1f, 0.8f), -1.2f));
  addCopy (0, rigidMotion (Eigen::Vector3f (0.3f, 0.05f, 0.9f), 3.0f));
  addCopy (0, rigidMotion (Eigen::Vector3f (-0.2f, -0.25f, 0.95f), -2.5f));
  addCopy (0, rigidMotion (Eigen::Vector3f (0.2f, 0.25f, 0.85f), 1.0f));
  mid::ObjectModels models{
      modelOf (0, kLeft, Eigen::Isometry3f::Identity(), {0, 1}),
      modelOf (kLeft + kMiddle, kRight, Eigen::Isometry3f::Identity(), {2, 3}),
      modelOf (0, kLeft, rigidMotion ({0.0f, 0.0f, 0.02f}, 1.0f), {4, 5})};
  mid::RegionModelMerger merge = merger();
  ASSERT_TRUE (merge.merge (models));
  EXPECT_EQ (merge.getMergedCount(), 2u);
  expectOneModelAtTheTruePoses (models, 6);
}

// Two objects of one shape that share the appearance of a few points of the middle band: with
// the default 6 inliers, 5 common points keep them apart and 6 merge them.
TEST_F (RegionModelMergerTest, KeepsObjectsApartOnFiveCommonPoints)
{
  const mid::ObjectModels before = twoObjectsSharing (5);
  mid::ObjectModels models = before;
  mid::RegionModelMerger merge = merger();
  ASSERT_TRUE (merge.merge (models));
  EXPECT_EQ (merge.getMergedCount(), 0u);
  ASSERT_EQ (models.size(), 2u);
  for (std::size_t m = 0; m < 2; ++m)
    for (std::size_t i = 0; i < 2; ++i)
      EXPECT_TRUE (models[m].instances[i].pose.isApprox (before[m].instances[i].pose));
}

TEST_F (RegionModelMergerTest, MergesObjectsOnSixCommonPoints)
{
  mid::ObjectModels models = twoObjectsSharing (6);
  mid::RegionModelMerger merge = merger();
  ASSERT_TRUE (merge.merge (models));
  EXPECT_EQ (merge.getMergedCount(), 1u);
  expectOneModelAtTheTruePoses (models, 4);
}

TEST_F (RegionModelMergerTest, AsksTheMergeConditionAboutEachPairOfCopiesBeforeMerging)
{
  // The four copies and two models of MergesTwoModelsOfOneObjectThroughTheSurfaceNeitherHolds.
  addCopy (0, rigidMotion (Eigen::Vector3f (-0.3f, 0.0f, 0.8f), 0.4f));
  addCopy (0, rigidMotion (Eigen::Vector3f (-0.1f, 0.1f, 0.85f), 2.1f));
  addCopy (0, rigidMotion (Eigen::Vector3f (0.1f, -0.1f, 0.8f), -1.2f, {0, 1, 4}));
  addCopy (0, rigidMotion (Eigen::Vector3f (0.3f, 0.05f, 0.9f), 3.0f));
  const mid::ObjectModels before{
      modelOf (0, kLeft, Eigen::Isometry3f::Identity(), {0, 1}),
      modelOf (kLeft + kMiddle, kRight, Eigen::Isometry3f::Identity(), {2, 3})};
  std::vector<mid::TripletCluster> asked;
  const auto refuse_first = [&asked] (const mid::TripletCluster& link) {
    asked.push_back (link);
    return asked.size() > 1;
  };
  mid::ObjectModels models = before;
  mid::RegionModelMerger merge = merger();
  merge.setMergeCondition (refuse_first);
  ASSERT_TRUE (merge.merge (models));
  // The first pair of copies refused, the search went on and merged through the next.
  ASSERT_EQ (asked.size(), 2u);
  EXPECT_EQ (merge.getRefusedCount(), 1u);
  EXPECT_EQ (merge.getMergedCount(), 1u);
  expectOneModelAtTheTruePoses (models, 4);
  // Each link is the true motion of one copy of the first model onto one of the second, on
  // the keypoints of one object point seen on both (the middle band's).
  for (const auto& link : asked) {
    ASSERT_GE (link.correspondences.size(), 6u);
    EXPECT_EQ (link.source_indices.size(), link.correspondences.size());
    EXPECT_EQ (link.target_indices.size(), link.correspondences.size());
    EXPECT_TRUE (
        std::is_sorted (link.source_indices.begin(), link.source_indices.end()));
    EXPECT_TRUE (
        std::is_sorted (link.target_indices.begin(), link.target_indices.end()));
    const int from = link.correspondences.front().index_query / kPoints,
              to = link.correspondences.front().index_match / kPoints;
    EXPECT_LT (from, 2);
    EXPECT_GE (to, 2);
    const auto [angle, distance] =
        poseError (link.transformation,
                   poses_[static_cast<std::size_t> (to)] *
                       poses_[static_cast<std::size_t> (from)].inverse());
    EXPECT_LT (angle, 1e-3);
    EXPECT_LT (distance, 1e-3);
    for (const auto& pair : link.correspondences) {
      EXPECT_EQ (pair.index_query / kPoints, from);
      EXPECT_EQ (pair.index_match / kPoints, to);
      EXPECT_EQ (pair.index_query % kPoints, pair.index_match % kPoints);
    }
  }

  // A condition that refuses every pair keeps the models as they were.
  models = before;
  merge.setMergeCondition ([] (const mid::TripletCluster&) { return false; });
  ASSERT_TRUE (merge.merge (models));
  EXPECT_EQ (merge.getMergedCount(), 0u);
  EXPECT_GE (merge.getRefusedCount(), 1u);
  ASSERT_EQ (models.size(), 2u);
  for (std::size_t m = 0; m < 2; ++m)
    for (std::size_t i = 0; i < 2; ++i)
      EXPECT_TRUE (models[m].instances[i].pose.isApprox (before[m].instances[i].pose));
}

TEST_F (RegionModelMergerTest, AKeypointAroundTwoTouchingCopiesMatchesNeitherWay)
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

TEST (InstanceRegions, FreeKeypointsGoToTheNearestBoxWithinTheMargin)
{
  // One model whose landmark box spans x in [-45, 45] mm and y in [-20, 20] mm (a 21 x 9 grid,
  // trimmed to its 5th and 95th percentiles), with instances at x = -50 mm and, turned by a
  // half turn, at x = 50 mm (boxes 10 mm apart), and one with a non-finite pose; a second
  // model with one instance at x = 300 mm.
  mid::ObjectModel model;
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j <= 8; ++j) {
      pcl::PointNormal landmark;
      landmark.getVector3fMap() =
          Eigen::Vector3f (-0.05f + 0.005f * static_cast<float> (i),
                           -0.02f + 0.005f * static_cast<float> (j),
                           0.0f);
      model.landmarks.push_back (landmark);
    }
  mid::KeypointCloud keypoints;
  const auto keypoint = [&keypoints] (float x) {
    pcl::PointNormal k;
    k.getVector3fMap() = Eigen::Vector3f (x, 0.0f, 0.8f);
    keypoints.push_back (k);
    return static_cast<pcl::index_t> (keypoints.size() - 1);
  };
  mid::ObjectModel other = model;
  model.instances.resize (3);
  model.instances[0].pose = rigidMotion (Eigen::Vector3f (-0.05f, 0.0f, 0.8f)).matrix();
  // The half turn written exactly, so that a keypoint at x = 0 is exactly as far from both.
  model.instances[1].pose << -1, 0, 0, 0.05f, 0, -1, 0, 0, 0, 0, 1, 0.8f, 0, 0, 0, 1;
  model.instances[2].pose.setConstant (std::numeric_limits<float>::quiet_NaN());
  other.instances.resize (1);
  other.instances[0].pose = rigidMotion (Eigen::Vector3f (0.3f, 0.0f, 0.8f)).matrix();
  const pcl::index_t inside_0 = keypoint (-0.03f), inside_1 = keypoint (0.03f),
                     nearer_0 = keypoint (-0.002f), midway = keypoint (0.0f),
                     beyond = keypoint (-0.13f), near_other = keypoint (0.31f),
                     observed = keypoint (0.04f);
  model.instances[0].keypoints = {
      observed}; // inside instance 1's box, but observed by 0
  model.instances[0].landmarks = {0};
  const auto regions =
      mid::computeInstanceRegions (keypoints, mid::ObjectModels{model, other}, 0.02f);
  ASSERT_EQ (regions.size(), 2u);
  ASSERT_EQ (regions[0].size(), 3u);
  ASSERT_EQ (regions[1].size(), 1u);
  EXPECT_EQ (regions[0][0], (pcl::Indices{inside_0, nearer_0, observed}));
  EXPECT_EQ (regions[0][1], (pcl::Indices{inside_1}));
  EXPECT_TRUE (regions[0][2].empty());
  EXPECT_EQ (regions[1][0], (pcl::Indices{near_other}));
  // 5 mm from both boxes: neither; 35 mm beyond the first box: outside the 20 mm margin.
  for (const auto& model_regions : regions)
    for (const auto& region : model_regions)
      for (const auto k : region) {
        EXPECT_NE (k, midway);
        EXPECT_NE (k, beyond);
      }
}

TEST_F (RegionModelMergerTest, RefusesUnusableInputWithoutTouchingTheModels)
{
  addCopy (0, rigidMotion (Eigen::Vector3f (-0.3f, 0.0f, 0.8f), 0.4f));
  addCopy (0, rigidMotion (Eigen::Vector3f (-0.1f, 0.1f, 0.85f), 2.1f));
  addCopy (0, rigidMotion (Eigen::Vector3f (0.1f, -0.1f, 0.8f), -1.2f));
  // Models that would merge (test MergesTwoModels... above): a refusal leaves them as they are.
  const mid::ObjectModels before{
      modelOf (0, kLeft, Eigen::Isometry3f::Identity(), {0, 1}),
      modelOf (kLeft + kMiddle, kRight, Eigen::Isometry3f::Identity(), {1, 2})};
  const auto expectRefused = [] (mid::RegionModelMerger merge,
                                 const mid::ObjectModels& input) {
    mid::ObjectModels models = input;
    EXPECT_FALSE (merge.merge (models));
    EXPECT_EQ (merge.getMergedCount(), 0u);
    ASSERT_EQ (models.size(), input.size());
    for (std::size_t m = 0; m < models.size(); ++m) {
      EXPECT_EQ (models[m].landmarks.size(), input[m].landmarks.size());
      EXPECT_EQ (models[m].descriptors.size(), input[m].descriptors.size());
      ASSERT_EQ (models[m].instances.size(), input[m].instances.size());
      for (std::size_t i = 0; i < models[m].instances.size(); ++i)
        EXPECT_EQ (models[m].instances[i].pose, input[m].instances[i].pose);
    }
  };
  mid::ObjectModels merged = before;
  ASSERT_TRUE (merger().merge (merged));
  ASSERT_EQ (merged.size(), 1u);

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
  // Also when no search would run (no models): the parameter is wrong all the same.
  expectRefused (bad_detector, mid::ObjectModels());
  mid::ObjectModels outside = before;
  outside.back().instances.back().keypoints.back() =
      static_cast<pcl::index_t> (keypoints_->size());
  expectRefused (merger(), outside);
}
