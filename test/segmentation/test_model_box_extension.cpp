// ModelBoxExtender and retractModelExtension on rendered boxes resting on a table at known
// poses: models that observe only one half of each box's keypoints.
#include "resting_boxes.h"

#include <mid/segmentation/guided_instance_search.h>
#include <mid/segmentation/model_box_extension.h>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace {

using mid::test::fourBoxes;
using mid::test::kPrintedBoxSize;
using mid::test::kTableDepth;
using Boxes = mid::test::RestingBoxes;

/** The keypoints on box b in one half of it: x < 0 (`first`) or x >= 0 in the box's frame. */
pcl::Indices
halfOf (const Boxes& scene, int b, bool first)
{
  const Eigen::Isometry3d to_box =
      scene.scene.boxes[static_cast<std::size_t> (b)].pose.inverse();
  pcl::Indices half;
  for (const auto k : scene.on ({b})) {
    const double x = (to_box * (*scene.keypoints)[static_cast<std::size_t> (k)]
                                   .getVector3fMap()
                                   .cast<double>())
                         .x();
    if ((x < 0.0) == first)
      half.push_back (k);
  }
  return half;
}

/** A model whose instances sit on the given boxes at their true poses (the model frame is the
  * boxes' own) and observe the first half of each box's keypoints, each a landmark of its own.
  */
mid::ObjectModel
halfModel (const Boxes& scene, const std::vector<int>& boxes)
{
  mid::ObjectModel model;
  for (const int b : boxes)
    mid::addInstanceOfKeypoints (
        *scene.keypoints,
        *scene.descriptors,
        halfOf (scene, b, true),
        scene.scene.boxes[static_cast<std::size_t> (b)].pose.matrix().cast<float>(),
        model);
  return model;
}

mid::ModelBoxExtender
extenderFor (const Boxes& scene)
{
  return mid::test::describingStep<mid::ModelBoxExtender> (scene);
}

/** Height of a point above the table (which faces the camera at kTableDepth). */
double
aboveTable (const pcl::PointNormal& point)
{
  return kTableDepth - static_cast<double> (point.z);
}

TEST (ModelBoxExtender, ExtendsEachInstanceByTheKeypointsInsideItsBox)
{
  const Boxes scene (fourBoxes());
  const mid::ObjectModel original = halfModel (scene, {0, 1});
  mid::ObjectModels models = {original};
  mid::ModelExtension extension;
  ASSERT_TRUE (extenderFor (scene).extend (models, extension));
  ASSERT_EQ (extension.landmarks_before,
             std::vector<std::size_t>{original.landmarks.size()});
  ASSERT_EQ (extension.observations.size(), 1u);
  const mid::ObjectModel& model = models[0];
  ASSERT_EQ (model.instances.size(), 2u);
  EXPECT_EQ (model.landmarks.size(),
             original.landmarks.size() + extension.observations[0].size());
  EXPECT_EQ (model.descriptors.size(), model.descriptor_landmarks.size());

  for (std::size_t i = 0; i < 2; ++i) {
    const int b = static_cast<int> (i);
    const auto& instance = model.instances[i];
    ASSERT_EQ (instance.keypoints.size(), instance.landmarks.size());
    // The first half stays as it was.
    const auto& before = original.instances[i];
    for (std::size_t o = 0; o < before.keypoints.size(); ++o) {
      EXPECT_EQ (instance.keypoints[o], before.keypoints[o]);
      EXPECT_EQ (instance.landmarks[o], before.landmarks[o]);
    }
    // Every added keypoint lies on the instance's own box, its landmark at the keypoint
    // carried into the model frame (the box's own) by the true pose.
    const std::set<pcl::index_t> added (
        instance.keypoints.begin() +
            static_cast<std::ptrdiff_t> (before.keypoints.size()),
        instance.keypoints.end());
    const Eigen::Isometry3d to_box = scene.scene.boxes[i].pose.inverse();
    for (std::size_t o = before.keypoints.size(); o < instance.keypoints.size(); ++o) {
      const auto k = static_cast<std::size_t> (instance.keypoints[o]);
      EXPECT_EQ (scene.box_of[k], b) << "keypoint " << k;
      const Eigen::Vector3f expected =
          (to_box * (*scene.keypoints)[k].getVector3fMap().cast<double>())
              .cast<float>();
      const auto l = static_cast<std::size_t> (instance.landmarks[o]);
      EXPECT_LT ((model.landmarks[l].getVector3fMap() - expected).norm(), 1e-4f);
      EXPECT_GE (l, original.landmarks.size());
    }
    // ... and every keypoint of its other half that is not within the table's tolerance
    // (10 mm) was added.
    std::size_t other_half = 0;
    for (const auto k : halfOf (scene, b, false))
      if (aboveTable ((*scene.keypoints)[static_cast<std::size_t> (k)]) > 0.012) {
        EXPECT_EQ (added.count (k), 1u) << "box " << b << ", keypoint " << k;
        ++other_half;
      }
    EXPECT_GE (other_half, 10u) << "box " << b;
  }
  // Boxes 2 and 3 (not the model's copies) and the table give nothing.
  std::size_t total = 0;
  for (const auto& [i, k] : extension.observations[0]) {
    EXPECT_EQ (scene.box_of[static_cast<std::size_t> (k)], static_cast<int> (i));
    ++total;
  }
  EXPECT_EQ (total, model.landmarks.size() - original.landmarks.size());
}

TEST (ModelBoxExtender, TakesNothingFromTheTable)
{
  // A printed mat 3 mm thin lies on the table 1 cm beside box 0 (the table itself shows no
  // texture). Grown by 3 cm, box 0 reaches over the mat, whose keypoints lie within the
  // table's tolerance and are not the object's.
  auto boxes = fourBoxes();
  boxes.push_back (mid::test::restingBox (
      mid::test::kSoyPrint, -0.16, 0.0, 10.0, {0.12, 0.09, 0.003}));
  const Boxes scene (boxes);
  ASSERT_GE (scene.on ({4}).size(), 20u) << "the mat shows texture";
  // Some of the mat's keypoints lie in box 0 grown by 3 cm.
  const Eigen::Isometry3d to_box = scene.scene.boxes[0].pose.inverse();
  const Eigen::Vector3d reach =
      0.5 * kPrintedBoxSize + Eigen::Vector3d::Constant (0.03);
  std::size_t reached = 0;
  for (const auto k : scene.on ({4})) {
    const Eigen::Vector3d local =
        to_box * (*scene.keypoints)[static_cast<std::size_t> (k)]
                     .getVector3fMap()
                     .cast<double>();
    reached += (local.cwiseAbs() - reach).maxCoeff() <= 0.0 ? 1 : 0;
  }
  ASSERT_GE (reached, 3u);
  mid::ObjectModels models = {halfModel (scene, {0, 1})};
  mid::ModelBoxExtender wide = extenderFor (scene);
  wide.setMargin (0.03f);
  mid::ModelExtension extension;
  ASSERT_TRUE (wide.extend (models, extension));
  ASSERT_FALSE (extension.observations[0].empty());
  for (const auto& [i, k] : extension.observations[0])
    EXPECT_EQ (scene.box_of[static_cast<std::size_t> (k)], static_cast<int> (i))
        << "keypoint " << k;
}

TEST (ModelBoxExtender, RetractingKeepsOnlyWhatANewCopyObserves)
{
  const Boxes scene (fourBoxes());
  const mid::ObjectModel original = halfModel (scene, {0, 1});
  mid::ObjectModels models = {original};
  mid::ModelExtension extension;
  ASSERT_TRUE (extenderFor (scene).extend (models, extension));
  const mid::ObjectModel extended = models[0];
  const auto& first = extended.instances[0];
  const std::size_t own = original.instances[0].keypoints.size();
  ASSERT_GE (first.keypoints.size(), own + 4);

  // A copy found since, observing three of the added landmarks but not the first one added
  // (through box 0's keypoints: what matters here is what stays of the model).
  mid::ModelInstance found;
  found.pose = extended.instances[1].pose;
  for (std::size_t o = own + 1; o < own + 4; ++o) {
    found.keypoints.push_back (first.keypoints[o]);
    found.landmarks.push_back (first.landmarks[o]);
  }
  models[0].instances.push_back (found);

  // Another list of models, an instance or landmark count it does not have, or an
  // observation of a missing landmark are refused, and nothing changes.
  const auto refused = [&] (const mid::ModelExtension& wrong,
                            mid::ObjectModels changed) {
    EXPECT_FALSE (mid::retractModelExtension (wrong, changed));
    EXPECT_EQ (changed[0].instances[0].keypoints.size(), first.keypoints.size());
    EXPECT_EQ (changed[0].landmarks.size(), extended.landmarks.size());
  };
  refused (extension, {models[0], models[0]});
  mid::ModelExtension no_instance = extension;
  no_instance.observations[0].emplace_back (7, 0);
  refused (no_instance, models);
  mid::ModelExtension more_landmarks = extension;
  more_landmarks.landmarks_before[0] = extended.landmarks.size() + 1;
  refused (more_landmarks, models);
  mid::ObjectModels missing = models;
  missing[0].instances[2].landmarks[0] = static_cast<int> (extended.landmarks.size());
  EXPECT_FALSE (mid::retractModelExtension (extension, missing));

  ASSERT_TRUE (mid::retractModelExtension (extension, models));
  const mid::ObjectModel& model = models[0];
  ASSERT_EQ (model.instances.size(), 3u);
  // The extended instances observe what they observed before, the original landmarks and
  // descriptors come first as they were, and of the added landmarks the three the new copy
  // observes stay, renumbered after them, each with its descriptor.
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ (model.instances[i].keypoints, original.instances[i].keypoints);
    EXPECT_EQ (model.instances[i].landmarks, original.instances[i].landmarks);
  }
  ASSERT_EQ (model.landmarks.size(), original.landmarks.size() + 3);
  for (std::size_t l = 0; l < original.landmarks.size(); ++l)
    EXPECT_EQ (model.landmarks[l].getVector3fMap(),
               original.landmarks[l].getVector3fMap());
  ASSERT_EQ (model.descriptors.size(), original.descriptors.size() + 3);
  EXPECT_EQ (model.descriptor_landmarks.size(), model.descriptors.size());
  const auto& copy = model.instances[2];
  EXPECT_EQ (copy.keypoints, found.keypoints);
  ASSERT_EQ (copy.landmarks.size(), 3u);
  for (std::size_t o = 0; o < 3; ++o) {
    const auto now = static_cast<std::size_t> (copy.landmarks[o]);
    const auto then = static_cast<std::size_t> (found.landmarks[o]);
    EXPECT_EQ (now, original.landmarks.size() + o);
    EXPECT_EQ (model.landmarks[now].getVector3fMap(),
               extended.landmarks[then].getVector3fMap());
    EXPECT_EQ (model.descriptor_landmarks[original.descriptors.size() + o],
               static_cast<int> (now));
  }
}

TEST (ModelBoxExtender, LetsTheGuidedSearchFindACopyShowingWhatTheModelLacks)
{
  // The model observes the first half of box 0; box 1, a copy, offers only its other half.
  const Boxes scene (fourBoxes());
  mid::ObjectModels models = {halfModel (scene, {0})};
  mid::GuidedInstanceSearch search;
  search.setInputKeypoints (scene.keypoints);
  search.setInputDescriptors (scene.descriptors);
  search.setImageKeypoints (scene.image_keypoints);
  search.setKeypointSurface (scene.surface);
  search.setCandidates (halfOf (scene, 1, false));
  search.setFoundInstances (models[0].instances);

  mid::ModelInstances found;
  ASSERT_TRUE (search.search (models[0], found));
  EXPECT_TRUE (found.empty()) << "the model holds nothing of that half";

  mid::ModelExtension extension;
  ASSERT_TRUE (extenderFor (scene).extend (models, extension));
  ASSERT_TRUE (search.search (models[0], found));
  ASSERT_EQ (found.size(), 1u);
  EXPECT_EQ (scene.boxOf (found[0].keypoints), 1);
  // The model frame is box 0's own: the copy's pose is box 1's true pose.
  const Eigen::Matrix4d error =
      found[0].pose.cast<double>().inverse() * scene.scene.boxes[1].pose.matrix();
  EXPECT_LT (Eigen::AngleAxisd (error.topLeftCorner<3, 3>()).angle() * 180.0 / M_PI,
             2.0);
  const Eigen::Vector3d shift = error.topRightCorner<3, 1>();
  EXPECT_LT (shift.norm(), 0.003);
}

TEST (ModelBoxExtender, ExtendsWithinAKnownBoxInsteadOfMeasuring)
{
  // Known for the model: the half y >= 0 of the true box (in the model frame, the boxes' own),
  // edges ascending: box x, y, z along model z, y, -x. The frame measures the whole box; the
  // extension must keep to the known half.
  const Boxes scene (fourBoxes());
  const mid::ObjectModel original = halfModel (scene, {0, 1});
  mid::ModelSize half;
  half.valid = true;
  half.agreeing = 2;
  half.size = Eigen::Vector3f (0.04f, 0.045f, 0.12f);
  half.box_in_model.topLeftCorner<3, 3>() << 0, 0, -1, 0, 1, 0, 1, 0, 0;
  half.box_in_model.topRightCorner<3, 1>() = Eigen::Vector3f (0.0f, 0.0225f, 0.0f);
  mid::ModelBoxExtender known = extenderFor (scene);
  known.setKnownSizes ({half});
  mid::ObjectModels models = {original};
  mid::ModelExtension extension;
  ASSERT_TRUE (known.extend (models, extension));
  const float margin = known.getMargin();
  for (std::size_t i = 0; i < 2; ++i) {
    const int b = static_cast<int> (i);
    const Eigen::Isometry3d to_box = scene.scene.boxes[i].pose.inverse();
    const auto& instance = models[0].instances[i];
    const std::set<pcl::index_t> added (
        instance.keypoints.begin() +
            static_cast<std::ptrdiff_t> (original.instances[i].keypoints.size()),
        instance.keypoints.end());
    std::size_t inside = 0, outside = 0;
    for (const auto k : halfOf (scene, b, false)) {
      const auto& point = (*scene.keypoints)[static_cast<std::size_t> (k)];
      const double y = (to_box * point.getVector3fMap().cast<double>()).y();
      if (y < -margin - 1e-3) {
        EXPECT_EQ (added.count (k), 0u) << "box " << b << ", keypoint " << k;
        ++outside;
      }
      else if (y > margin && aboveTable (point) > 0.012) {
        EXPECT_EQ (added.count (k), 1u) << "box " << b << ", keypoint " << k;
        ++inside;
      }
    }
    EXPECT_EQ (added.size(),
               instance.keypoints.size() - original.instances[i].keypoints.size());
    EXPECT_GE (inside, 4u) << "box " << b;
    EXPECT_GE (outside, 4u) << "box " << b << ": the measured box would add these";
  }
  // Measured in the frame, the box adds keypoints of the half y < 0 too.
  mid::ObjectModels measured = {original};
  ASSERT_TRUE (extenderFor (scene).extend (measured, extension));
  EXPECT_GT (measured[0].landmarks.size(), models[0].landmarks.size());

  // A known box that is not valid leaves the model as it is, although the frame would measure
  // one; known sizes that are not one per model are refused.
  half.valid = false;
  known.setKnownSizes ({half});
  models = {original};
  ASSERT_TRUE (known.extend (models, extension));
  EXPECT_EQ (models[0].landmarks.size(), original.landmarks.size());
  known.setKnownSizes ({half, half});
  EXPECT_FALSE (known.extend (models, extension));
  EXPECT_TRUE (extension.observations.empty());
  // ... and so is a valid box that is no box: mirrored, or with edges not ascending.
  half.valid = true;
  mid::ModelSize mirrored = half, unsorted = half;
  mirrored.box_in_model.col (0) *= -1.0f;
  unsorted.size = Eigen::Vector3f (0.12f, 0.045f, 0.04f);
  for (const auto& box : {mirrored, unsorted}) {
    known.setKnownSizes ({box});
    EXPECT_FALSE (known.extend (models, extension));
    EXPECT_EQ (models[0].landmarks.size(), original.landmarks.size());
  }
}

TEST (ModelBoxExtender, LeavesTheModelsWithoutASupportPlaneOrASize)
{
  const Boxes scene (fourBoxes());
  const mid::ObjectModels original = {halfModel (scene, {0, 1})};
  mid::ObjectModels models = original;
  mid::ModelBoxExtender no_plane = extenderFor (scene);
  no_plane.setSupportPlane (Eigen::Vector4f::Zero());
  mid::ModelExtension extension;
  ASSERT_TRUE (no_plane.extend (models, extension));
  EXPECT_EQ (models[0].landmarks.size(), original[0].landmarks.size());
  EXPECT_TRUE (extension.observations[0].empty());
  EXPECT_TRUE (mid::retractModelExtension (extension, models));

  // Two measured instances that must agree on a size, and disagree: no size, no extension.
  const Boxes other (fourBoxes ({0.15, 0.11, 0.06}));
  const mid::ObjectModels two_sizes = {halfModel (other, {0, 2})};
  mid::ObjectModels unsized = two_sizes;
  mid::ModelBoxExtender strict = extenderFor (other);
  strict.setMinAgreeing (2);
  ASSERT_TRUE (strict.extend (unsized, extension));
  EXPECT_EQ (unsized[0].landmarks.size(), two_sizes[0].landmarks.size());
  // One measured instance is enough by default: the same model is extended.
  mid::ObjectModels sized = two_sizes;
  ASSERT_TRUE (extenderFor (other).extend (sized, extension));
  EXPECT_GT (sized[0].landmarks.size(), two_sizes[0].landmarks.size());
}

TEST (ModelBoxExtender, RefusesBadInputAndLeavesTheModels)
{
  const Boxes scene (fourBoxes());
  const mid::ObjectModels original = {halfModel (scene, {0, 1})};
  const auto refuses = [&] (const mid::ModelBoxExtender& extender) {
    mid::ObjectModels models = original;
    mid::ModelExtension extension;
    extension.landmarks_before = {1, 2, 3};
    EXPECT_FALSE (extender.extend (models, extension));
    EXPECT_TRUE (extension.landmarks_before.empty());
    EXPECT_EQ (models[0].landmarks.size(), original[0].landmarks.size());
  };
  mid::ModelBoxExtender no_descriptors = extenderFor (scene);
  no_descriptors.setInputDescriptors (nullptr);
  refuses (no_descriptors);
  mid::ModelBoxExtender negative = extenderFor (scene);
  negative.setMargin (-0.001f);
  refuses (negative);
  mid::ModelBoxExtender no_keypoints = extenderFor (scene);
  no_keypoints.setInputKeypoints (nullptr);
  refuses (no_keypoints);

  mid::ObjectModels outside = original;
  outside[0].instances[0].keypoints[0] =
      static_cast<pcl::index_t> (scene.keypoints->size());
  mid::ModelExtension extension;
  EXPECT_FALSE (extenderFor (scene).extend (outside, extension));
  EXPECT_EQ (outside[0].landmarks.size(), original[0].landmarks.size());
}

} // namespace
