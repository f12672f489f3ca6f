#include "../segmentation/rendered_keypoints.h"
#include "rendered_objects_scene.h"
#include "rigid_motion.h"

#include <mid/discovery/discovery_stages.h>
#include <mid/segmentation/frame_pinhole.h>
#include <mid/segmentation/photometric_verification.h>

#include <gtest/gtest.h>

#include <limits>
#include <random>
#include <set>
#include <string>

namespace {

/** Landmarks of a model with `count` points on a 12 x 8 x 3 cm object, each with one
  * descriptor far (L2 > 350) from every other; the first `shared` points and descriptors are
  * those of `like` (the same object point seen in both models), the others new.
  */
mid::ObjectModel
makeModel (std::size_t count,
           std::uint32_t seed,
           const mid::ObjectModel* like = nullptr,
           std::size_t shared = 0)
{
  std::mt19937 rng (seed);
  std::uniform_real_distribution<float> x (-0.06f, 0.06f), y (-0.04f, 0.04f),
      z (-0.015f, 0.015f), value (0.0f, 200.0f);
  mid::ObjectModel model;
  for (std::size_t l = 0; l < count; ++l) {
    pcl::PointNormal point;
    mid::SIFTDescriptor descriptor;
    if (l < shared) {
      point = like->landmarks[l];
      descriptor = like->descriptors[l];
    }
    else {
      point.getVector3fMap() = Eigen::Vector3f (x (rng), y (rng), z (rng));
      for (float& v : descriptor.histogram)
        v = value (rng);
    }
    point.getNormalVector3fMap() = Eigen::Vector3f::UnitZ();
    model.landmarks.push_back (point);
    model.descriptors.push_back (descriptor);
    model.descriptor_landmarks.push_back (static_cast<int> (l));
  }
  mid::updateModelDiameter (model);
  return model;
}

/** Place the model's landmarks in the frame at `pose` as a new instance of it. */
void
addInstance (mid::ObjectModel& model,
             const Eigen::Isometry3f& pose,
             mid::KeypointCloud& frame)
{
  mid::ModelInstance instance;
  instance.pose = pose.matrix();
  for (std::size_t l = 0; l < model.landmarks.size(); ++l) {
    pcl::PointNormal point;
    point.getVector3fMap() = pose * model.landmarks[l].getVector3fMap();
    point.getNormalVector3fMap() =
        pose.linear() * model.landmarks[l].getNormalVector3fMap();
    instance.keypoints.push_back (static_cast<pcl::index_t> (frame.size()));
    instance.landmarks.push_back (static_cast<int> (l));
    frame.push_back (point);
  }
  model.instances.push_back (instance);
}

/** Two models with two instances each, the second sharing `shared` of its `count` landmarks
  * with the first; merged with the given parameters. Returns the models left.
  */
mid::ObjectModels
mergeTwoModels (std::size_t count,
                std::size_t shared,
                const mid::DiscoveryParameters& parameters = {})
{
  const mid::ObjectModel first = makeModel (40, 1);
  mid::ObjectModels models{first, makeModel (count, 2, &first, shared)};
  mid::KeypointCloud frame;
  addInstance (models[0], mid::test::rigidMotion ({-0.2f, 0.0f, 0.8f}), frame);
  addInstance (models[0], mid::test::rigidMotion ({0.0f, 0.1f, 0.8f}, 0.5f), frame);
  addInstance (models[1], mid::test::rigidMotion ({0.2f, 0.0f, 0.8f}, -0.7f), frame);
  addInstance (models[1], mid::test::rigidMotion ({0.0f, -0.1f, 0.9f}, 1.2f), frame);
  std::string problem;
  EXPECT_EQ (mid::mergeMatchingModels (parameters, frame, models),
             mid::validateDiscoveryParameters (parameters, problem));
  return models;
}

} // namespace

TEST (ModelMergingStage, MergesModelsThatShareManyLandmarks)
{
  // 14 of 40 shared points: one object seen from two sides. The merged model holds the four
  // instances at their true relative poses.
  const mid::ObjectModels models = mergeTwoModels (40, 14);
  ASSERT_EQ (models.size(), 1u);
  ASSERT_EQ (models.front().instances.size(), 4u);
  EXPECT_EQ (models.front().landmarks.size(), 40u + 40u - 14u);
  const mid::ObjectModel& merged = models.front();
  const Eigen::Matrix4f truth = (mid::test::rigidMotion ({0.2f, 0.0f, 0.8f}, -0.7f) *
                                 mid::test::rigidMotion ({-0.2f, 0.0f, 0.8f}).inverse())
                                    .matrix();
  const auto error = mid::test::poseError (
      merged.instances[2].pose * merged.instances[0].pose.inverse(), truth);
  EXPECT_LT (error.first, 1e-3);
  EXPECT_LT (error.second, 1e-4);
}

TEST (ModelMergingStage, KeepsModelsApartOnAFewChanceMatches)
{
  // 6 of 40 shared points: two products that share a small print. The paper's rule (any 5
  // inliers; merge_fraction 0) merges them.
  EXPECT_EQ (mergeTwoModels (40, 6).size(), 2u);
  mid::DiscoveryParameters paper;
  paper.merge_fraction = 0.0f;
  EXPECT_EQ (mergeTwoModels (40, 6, paper).size(), 1u);
}

TEST (ModelMergingStage, MergesASmallModelOnAShareOfItsLandmarks)
{
  // A 12-landmark model, 6 of them shared: half of the smaller model, more than the 30 %
  // merge_fraction; a 10-inlier rule alone would keep it apart.
  EXPECT_EQ (mergeTwoModels (12, 6).size(), 1u);
  mid::DiscoveryParameters count_only;
  count_only.merge_fraction = 1.0f;
  EXPECT_EQ (mergeTwoModels (12, 6, count_only).size(), 2u);
}

TEST (ModelMergingStage, ComparesOnlyThePairsWithANewModel)
{
  // Three models of one object, each sharing 14 landmarks with the first: with first_new 2,
  // the two old ones are not compared with each other (they were before), the new one merges
  // into the first.
  const mid::ObjectModel first = makeModel (40, 1);
  mid::ObjectModels models{
      first, makeModel (40, 2, &first, 14), makeModel (40, 3, &first, 14)};
  mid::KeypointCloud frame;
  for (std::size_t m = 0; m < models.size(); ++m) {
    const float shift = 0.3f * static_cast<float> (m);
    addInstance (
        models[m], mid::test::rigidMotion ({-0.1f + shift, 0.0f, 0.8f}), frame);
    addInstance (
        models[m], mid::test::rigidMotion ({-0.1f + shift, 0.2f, 0.9f}, 0.6f), frame);
  }
  mid::ObjectModels merged = models;
  ASSERT_TRUE (mid::mergeMatchingModels ({}, frame, merged, 2));
  ASSERT_EQ (merged.size(), 2u);
  EXPECT_EQ (merged[0].instances.size(), 4u); // the first and the new one
  EXPECT_EQ (merged[1].instances.size(), 2u); // the second, not compared with the first
  // Compared in full (first_new 0), all three merge.
  merged = models;
  ASSERT_TRUE (mid::mergeMatchingModels ({}, frame, merged, 0));
  EXPECT_EQ (merged.size(), 1u);
}

TEST (ModelMergingStage, KeepsApartModelsWhoseCopiesLookDifferent)
{
  // Boxes 0 and 1 carry the apple print, boxes 2 and 3 the same print in other colours with the
  // same grey levels. Models of the true instances of {0, 1} and of {2, 3} share their SIFT
  // descriptors and geometry: RANSAC merges them unless the colours are compared.
  const char* print = mid::test::kApplePrint;
  const Eigen::Vector3d size = mid::test::kPrintedBoxSize;
  auto scene = mid::test::renderBoxes (
      {{print, size, mid::test::boxPose (-0.14, -0.08, 0.8, 15.0)},
       {print, size, mid::test::boxPose (0.12, -0.07, 0.84, 140.0, 15.0)},
       {print, size, mid::test::boxPose (-0.12, 0.11, 0.82, -40.0)},
       {print, size, mid::test::boxPose (0.13, 0.12, 0.85, 250.0, -10.0)}},
      0.95);
  ASSERT_GT (mid::test::tintKeepingGreyLevels (scene, 2), 1000u);
  ASSERT_GT (mid::test::tintKeepingGreyLevels (scene, 3), 1000u);
  mid::test::RenderedKeypoints frame (scene);
  pcl::PointCloud<pcl::PointXYZRGB> colour;
  pcl::copyPointCloud (*scene.cloud, colour);
  frame.surface.chromaticity = std::make_shared<const std::vector<mid::Chromaticity>> (
      mid::chromaticities (colour));
  mid::FramePinhole pinhole;
  ASSERT_TRUE (mid::fitFramePinhole (*frame.surface.organized, pinhole));
  frame.surface.pinhole = std::make_shared<const mid::FramePinhole> (pinhole);
  mid::ObjectModels models (2);
  frame.addTruthInstance (0, models[0]);
  frame.addTruthInstance (1, models[0]);
  frame.addTruthInstance (2, models[1]);
  frame.addTruthInstance (3, models[1]);

  mid::ObjectModels kept = models;
  ASSERT_TRUE (mid::mergeMatchingModels ({}, *frame.keypoints, kept, 0, frame.surface));
  ASSERT_EQ (kept.size(), 2u);
  for (std::size_t m = 0; m < 2; ++m)
    for (std::size_t i = 0; i < 2; ++i)
      EXPECT_EQ (frame.boxOf (kept[m].instances[i].keypoints),
                 static_cast<int> (2 * m + i));

  // Without the frame, or with the check off, they merge: one model on the four boxes.
  mid::ObjectModels merged = models;
  ASSERT_TRUE (mid::mergeMatchingModels ({}, *frame.keypoints, merged));
  EXPECT_EQ (merged.size(), 1u);
  mid::DiscoveryParameters unchecked;
  unchecked.verify_joins = false;
  merged = models;
  ASSERT_TRUE (
      mid::mergeMatchingModels (unchecked, *frame.keypoints, merged, 0, frame.surface));
  ASSERT_EQ (merged.size(), 1u);
  std::set<int> boxes;
  for (const auto& instance : merged.front().instances)
    boxes.insert (frame.boxOf (instance.keypoints));
  EXPECT_EQ (boxes, (std::set<int>{0, 1, 2, 3}));

  // A surface without a pixel for every keypoint is refused, the models untouched.
  mid::KeypointSurface short_surface = frame.surface;
  short_surface.keypoint_pixels.pop_back();
  merged = models;
  EXPECT_FALSE (
      mid::mergeMatchingModels ({}, *frame.keypoints, merged, 0, short_surface));
  ASSERT_EQ (merged.size(), 2u);
  for (std::size_t m = 0; m < 2; ++m)
    EXPECT_EQ (merged[m].instances.size(), models[m].instances.size());
}

TEST (ModelMergingStage, RefusesParametersOutOfRange)
{
  // A fraction outside [0, 1] is refused before any model is touched.
  for (const float fraction : {-0.5f, 1.5f, std::numeric_limits<float>::quiet_NaN()}) {
    mid::DiscoveryParameters bad;
    bad.merge_fraction = fraction;
    EXPECT_EQ (mergeTwoModels (40, 14, bad).size(), 2u) << fraction;
  }
}
