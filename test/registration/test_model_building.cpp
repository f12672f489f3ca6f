// The model builder, the joint refinement, the RANSAC detector and model merging, on synthetic
// keypoints of objects at exactly known poses.

#include "rigid_motion.h"

#include <mid/registration/model_instance_detector.h>
#include <mid/registration/model_merging.h>
#include <mid/registration/model_refinement.h>
#include <mid/registration/multi_instance_model_builder.h>
#include <mid/registration/rigid_transform.h>

#include <gtest/gtest.h>

#include <random>
#include <set>

namespace {

using mid::test::poseError;
using Poses =
    std::vector<Eigen::Isometry3f, Eigen::aligned_allocator<Eigen::Isometry3f>>;

/** Instances of random objects (each `points` keypoints in a 10 cm cube with a random
  * descriptor per point, shared by its copies up to small noise), then random clutter.
  */
struct Frame
{
  mid::KeypointCloud::Ptr keypoints = pcl::make_shared<mid::KeypointCloud>();
  mid::SIFTDescriptorCloud::Ptr descriptors =
      pcl::make_shared<mid::SIFTDescriptorCloud>();
  std::vector<int> object_of;   // per keypoint: object type, -1 for clutter
  std::vector<int> instance_of; // per keypoint: instance number, -1 for clutter
  std::vector<int> point_of;    // per keypoint: point of its object
  Poses poses;                  // per instance
  std::mt19937 rng{17};
  std::vector<std::vector<Eigen::Vector3f>> objects;
  std::vector<std::vector<mid::SIFTDescriptor>> object_descriptors;

  int
  addObject (int points)
  {
    std::uniform_real_distribution<float> unit (-0.05f, 0.05f), value (0.0f, 80.0f);
    objects.emplace_back();
    object_descriptors.emplace_back();
    for (int k = 0; k < points; ++k) {
      objects.back().emplace_back (unit (rng), unit (rng), unit (rng));
      mid::SIFTDescriptor d;
      for (float& v : d.histogram)
        v = value (rng);
      object_descriptors.back().push_back (d);
    }
    return static_cast<int> (objects.size()) - 1;
  }

  /** Add an instance of object `o`; noise (metres) on the positions. */
  std::vector<int>
  addInstance (int o, const Eigen::Isometry3f& pose, float noise = 0.0f)
  {
    std::normal_distribution<float> jitter (0.0f, noise > 0.0f ? noise : 1e-9f);
    std::normal_distribution<float> descriptor_jitter (0.0f, 3.0f);
    std::vector<int> indices;
    const int instance = static_cast<int> (poses.size());
    poses.push_back (pose);
    for (std::size_t k = 0; k < objects[static_cast<std::size_t> (o)].size(); ++k) {
      pcl::PointNormal p;
      p.getVector3fMap() =
          pose * objects[static_cast<std::size_t> (o)][k] +
          (noise > 0.0f ? Eigen::Vector3f (jitter (rng), jitter (rng), jitter (rng))
                        : Eigen::Vector3f::Zero());
      p.getNormalVector3fMap() = pose.linear() * Eigen::Vector3f::UnitZ();
      indices.push_back (static_cast<int> (keypoints->size()));
      keypoints->push_back (p);
      mid::SIFTDescriptor d = object_descriptors[static_cast<std::size_t> (o)][k];
      for (float& v : d.histogram)
        v += descriptor_jitter (rng);
      descriptors->push_back (d);
      object_of.push_back (o);
      instance_of.push_back (instance);
      point_of.push_back (static_cast<int> (k));
    }
    return indices;
  }

  void
  addClutter (int count)
  {
    std::uniform_real_distribution<float> unit (-0.5f, 0.5f), value (0.0f, 80.0f);
    for (int i = 0; i < count; ++i) {
      pcl::PointNormal p;
      p.getVector3fMap() = Eigen::Vector3f (unit (rng), unit (rng), 1.0f + unit (rng));
      p.getNormalVector3fMap() = -Eigen::Vector3f::UnitZ();
      keypoints->push_back (p);
      mid::SIFTDescriptor d;
      for (float& v : d.histogram)
        v = value (rng);
      descriptors->push_back (d);
      object_of.push_back (-1);
      instance_of.push_back (-1);
      point_of.push_back (-1);
    }
  }

  /** The cluster of a pair of instances: every point matched, with the exact motion. */
  mid::TripletCluster
  cluster (const std::vector<int>& a,
           const std::vector<int>& b,
           std::size_t count) const
  {
    mid::TripletCluster c;
    Eigen::Matrix3Xf from (3, static_cast<Eigen::Index> (count)), to (3, from.cols());
    for (std::size_t k = 0; k < count; ++k) {
      c.correspondences.emplace_back (a[k], b[k], 0.0f);
      c.source_indices.push_back (a[k]);
      c.target_indices.push_back (b[k]);
      from.col (static_cast<Eigen::Index> (k)) =
          (*keypoints)[static_cast<std::size_t> (a[k])].getVector3fMap();
      to.col (static_cast<Eigen::Index> (k)) =
          (*keypoints)[static_cast<std::size_t> (b[k])].getVector3fMap();
    }
    c.transformation = mid::estimateRigidTransform (from, to, &c.rms_error);
    return c;
  }
};

Eigen::Isometry3f
pose (float x, float y, float angle, const Eigen::Vector3f& axis)
{
  return mid::test::rigidMotion ({x, y, 0.9f}, angle, axis);
}

/** The instance a model instance observes (all its keypoints must agree). */
int
trueInstance (const Frame& f, const mid::ModelInstance& instance)
{
  std::set<int> seen;
  for (const auto k : instance.keypoints)
    seen.insert (f.instance_of[static_cast<std::size_t> (k)]);
  EXPECT_EQ (seen.size(), 1u);
  return *seen.begin();
}

void
expectPosesRelativeToTruth (const Frame& f,
                            const mid::ObjectModel& model,
                            double max_angle,
                            double max_distance)
{
  const int first = trueInstance (f, model.instances.front());
  for (std::size_t i = 1; i < model.instances.size(); ++i) {
    const int other = trueInstance (f, model.instances[i]);
    const Eigen::Matrix4f estimated =
        model.instances[i].pose * model.instances.front().pose.inverse();
    const Eigen::Matrix4f truth = (f.poses[static_cast<std::size_t> (other)] *
                                   f.poses[static_cast<std::size_t> (first)].inverse())
                                      .matrix();
    const auto error = poseError (estimated, truth);
    EXPECT_LT (error.first, max_angle);
    EXPECT_LT (error.second, max_distance);
  }
}

} // namespace

TEST (MultiInstanceModelBuilder, ChainsClustersIntoOneModelPerObject)
{
  Frame f;
  const int box = f.addObject (30), can = f.addObject (20);
  const auto a = f.addInstance (box, pose (-0.3f, 0.0f, 0.2f, {0, 0, 1}));
  const auto b = f.addInstance (box, pose (0.0f, 0.1f, 1.9f, {1, 1, 0}));
  const auto c = f.addInstance (box, pose (0.3f, -0.1f, -1.0f, {0, 1, 1}));
  const auto d = f.addInstance (can, pose (-0.2f, 0.3f, 0.5f, {1, 0, 0}));
  const auto e = f.addInstance (can, pose (0.2f, 0.3f, 2.5f, {0, 1, 0}));
  f.addClutter (25);
  // a-b and b-c share the points of b (only 20 of 30 matched each time): one chain a-b-c.
  auto clusters = std::make_shared<mid::TripletClusters>();
  clusters->push_back (f.cluster (a, b, 25));
  clusters->push_back (f.cluster (c, b, 20));
  clusters->push_back (f.cluster (d, e, 20));

  mid::MultiInstanceModelBuilder builder;
  builder.setInputCloud (f.keypoints);
  builder.setInputDescriptors (f.descriptors);
  builder.setClusters (clusters);
  mid::ObjectModels models;
  ASSERT_TRUE (builder.compute (models));
  ASSERT_EQ (models.size(), 2u);
  ASSERT_EQ (models[0].instances.size(), 3u); // a, b, c
  ASSERT_EQ (models[1].instances.size(), 2u); // d, e
  EXPECT_EQ (models[0].landmarks.size(), 25u);
  EXPECT_EQ (models[1].landmarks.size(), 20u);
  expectPosesRelativeToTruth (f, models[0], 1e-4, 1e-5);
  expectPosesRelativeToTruth (f, models[1], 1e-4, 1e-5);
  for (const auto& model : models) {
    for (const auto& instance : model.instances)
      EXPECT_LT (instance.rms_error, 1e-5f);
    // The model frame is centred on the landmarks.
    Eigen::Vector3f centroid = Eigen::Vector3f::Zero();
    for (const auto& l : model.landmarks)
      centroid += l.getVector3fMap();
    EXPECT_LT ((centroid / static_cast<float> (model.landmarks.size())).norm(), 1e-5f);
    EXPECT_EQ (model.descriptors.size(), model.descriptor_landmarks.size());
  }
  // Clutter and the unmatched points of the instances are unused.
  EXPECT_EQ (builder.getUnusedKeypoints().size(),
             25u + (3u * 30u - 25u - 25u - 20u) + 0u);
}

/** A row of six translated copies matched neighbour to neighbour, plus a cluster copy 1 ->
  * copy 4 that also holds one keypoint of copy 2 (matched to copy 5: the row is periodic, so the
  * match agrees with the cluster's pose). That keypoint is shared with the sets on copy 2.
  */
struct StrayRow
{
  Frame f;
  std::vector<std::vector<int>> copies;
  std::shared_ptr<mid::TripletClusters> clusters =
      std::make_shared<mid::TripletClusters>();

  StrayRow()
  {
    const int box = f.addObject (30);
    for (int k = 0; k < 6; ++k)
      copies.push_back (f.addInstance (
          box, pose (-0.3f + 0.12f * static_cast<float> (k), 0.0f, 0.3f, {0, 0, 1})));
    for (std::size_t k = 0; k + 1 < copies.size(); ++k)
      clusters->push_back (f.cluster (copies[k], copies[k + 1], 20));
    std::vector<int> from (copies[1].begin(), copies[1].begin() + 20);
    std::vector<int> to (copies[4].begin(), copies[4].begin() + 20);
    from.push_back (copies[2][0]);
    to.push_back (copies[5][0]);
    clusters->push_back (f.cluster (from, to, from.size()));
  }

  mid::ObjectModels
  build (float link_tolerance) const
  {
    mid::MultiInstanceModelBuilder builder;
    builder.setInputCloud (f.keypoints);
    builder.setInputDescriptors (f.descriptors);
    builder.setClusters (clusters);
    builder.setLinkTolerance (link_tolerance);
    mid::ObjectModels models;
    EXPECT_TRUE (builder.compute (models));
    return models;
  }
};

TEST (MultiInstanceModelBuilder, AStrayKeypointDoesNotTieTwoCopiesIntoOneInstance)
{
  StrayRow row;
  const auto models = row.build (0.04f);
  ASSERT_EQ (models.size(), 1u);
  ASSERT_EQ (models[0].instances.size(), 6u);
  std::set<int> found;
  for (const auto& instance : models[0].instances)
    found.insert (trueInstance (row.f, instance)); // each on one copy
  EXPECT_EQ (found.size(), 6u);
  expectPosesRelativeToTruth (row.f, models[0], 1e-3, 1e-4);

  // The paper keeps every link: copies 1 and 2 become one instance, and so do copies 4 and 5
  // (through the stray keypoint's match on copy 5).
  const auto tied = row.build (1e3f);
  ASSERT_EQ (tied.size(), 1u);
  EXPECT_EQ (tied[0].instances.size(), 4u);
}

TEST (MultiInstanceModelBuilder, KeepsALinkWhosePosesDisagreeLessThanTheTolerance)
{
  StrayRow row;
  // Without the stray keypoint, and with a 15 mm error in the pose of the cluster copy 1 ->
  // copy 2, the loop copy 1 -> 2 -> 3 -> 4 -> 1 (back through the cluster copy 1 -> copy 4)
  // closes with a 15 mm disagreement on the sets of one copy: below the tolerance, so one
  // instance per copy.
  auto& long_cluster = row.clusters->back();
  long_cluster.correspondences.pop_back();
  long_cluster.source_indices.pop_back();
  long_cluster.target_indices.pop_back();
  (*row.clusters)[1].transformation (0, 3) += 0.015f;
  const auto models = row.build (0.04f);
  ASSERT_EQ (models.size(), 1u);
  EXPECT_EQ (models[0].instances.size(), 6u);
  // With a 10 mm tolerance the closing link is dropped and that copy is seen twice.
  EXPECT_EQ (row.build (0.01f)[0].instances.size(), 7u);
}

TEST (MultiInstanceModelBuilder, RefusesInconsistentInput)
{
  Frame f;
  const int box = f.addObject (10);
  const auto a = f.addInstance (box, pose (-0.3f, 0.0f, 0.2f, {0, 0, 1}));
  const auto b = f.addInstance (box, pose (0.0f, 0.1f, 1.9f, {1, 1, 0}));
  auto clusters = std::make_shared<mid::TripletClusters> (1, f.cluster (a, b, 10));
  mid::MultiInstanceModelBuilder builder;
  mid::ObjectModels models (2);
  EXPECT_FALSE (builder.compute (models));
  EXPECT_TRUE (models.empty());
  builder.setInputCloud (f.keypoints);
  builder.setInputDescriptors (pcl::make_shared<mid::SIFTDescriptorCloud> (3, 1));
  builder.setClusters (clusters);
  EXPECT_FALSE (builder.compute (models));
  builder.setInputDescriptors (f.descriptors);
  (*clusters)[0].correspondences[0].index_match = 1000;
  EXPECT_FALSE (builder.compute (models));
  (*clusters)[0].correspondences[0].index_match = b[0];
  (*clusters)[0].transformation (0, 0) = NAN;
  EXPECT_FALSE (builder.compute (models));
  EXPECT_TRUE (models.empty());
}

TEST (ModelRefinement, LowersTheCostMonotonicallyTowardsTheTruth)
{
  Frame f;
  const int box = f.addObject (40);
  Poses truth;
  for (int i = 0; i < 4; ++i)
    f.addInstance (box,
                   pose (-0.3f + 0.2f * static_cast<float> (i),
                         0.0f,
                         0.7f * static_cast<float> (i),
                         {1, 1, 1}),
                   0.0005f);
  // A model from noisy observations and perturbed poses (reference instance 0 exact).
  mid::ObjectModel model;
  model.landmarks.resize (40);
  model.instances.resize (4);
  std::mt19937 rng (1);
  std::normal_distribution<float> small (0.0f, 1.0f);
  for (int i = 0; i < 4; ++i) {
    Eigen::Isometry3f perturbed = f.poses[static_cast<std::size_t> (i)];
    if (i > 0)
      perturbed =
          f.poses[static_cast<std::size_t> (i)] *
          mid::test::rigidMotion (
              {0.004f * small (rng), 0.004f * small (rng), 0.004f * small (rng)},
              0.05f,
              {small (rng), small (rng), small (rng)});
    model.instances[static_cast<std::size_t> (i)].pose = perturbed.matrix();
    for (int k = 0; k < 40; ++k) {
      model.instances[static_cast<std::size_t> (i)].keypoints.push_back (i * 40 + k);
      model.instances[static_cast<std::size_t> (i)].landmarks.push_back (k);
    }
  }
  for (int k = 0; k < 40; ++k)
    model.landmarks[static_cast<std::size_t> (k)].getVector3fMap() =
        f.poses[0].inverse() *
        (*f.keypoints)[static_cast<std::size_t> (k)].getVector3fMap();
  std::vector<float> costs;
  const float rms = mid::refineModel (model, *f.keypoints, 50, 0, &costs);
  ASSERT_GE (costs.size(), 2u);
  for (std::size_t i = 1; i < costs.size(); ++i)
    EXPECT_LE (costs[i], costs[i - 1] * (1.0f + 1e-5f));
  EXPECT_LT (costs.back(), 0.05f * costs.front());
  EXPECT_LT (rms, 0.001f); // about the 0.5 mm noise
  for (int i = 1; i < 4; ++i) {
    const auto error = poseError (model.instances[static_cast<std::size_t> (i)].pose,
                                  f.poses[static_cast<std::size_t> (i)].matrix());
    EXPECT_LT (error.first, 0.5 * M_PI / 180.0);
    EXPECT_LT (error.second, 0.001);
  }
}

namespace {

/** The true model of object o: its points and descriptors, no instances. */
std::shared_ptr<mid::ObjectModel>
trueModel (const Frame& f, int o)
{
  auto model = std::make_shared<mid::ObjectModel>();
  for (std::size_t k = 0; k < f.objects[static_cast<std::size_t> (o)].size(); ++k) {
    pcl::PointNormal p;
    p.getVector3fMap() = f.objects[static_cast<std::size_t> (o)][k];
    p.getNormalVector3fMap() = Eigen::Vector3f::UnitZ();
    model->landmarks.push_back (p);
    model->descriptors.push_back (
        f.object_descriptors[static_cast<std::size_t> (o)][k]);
    model->descriptor_landmarks.push_back (static_cast<int> (k));
  }
  mid::updateModelDiameter (*model);
  return model;
}

} // namespace

TEST (ModelInstanceDetector, FindsEveryInstanceIncludingASingleOne)
{
  for (const int copies : {1, 4}) {
    Frame f;
    const int box = f.addObject (30), other = f.addObject (30);
    for (int i = 0; i < copies; ++i)
      f.addInstance (box,
                     pose (-0.3f + 0.2f * static_cast<float> (i),
                           0.05f * static_cast<float> (i),
                           1.1f * static_cast<float> (i),
                           {1, 2, 0}),
                     0.0005f);
    f.addInstance (other, pose (0.0f, -0.3f, 0.3f, {0, 0, 1}));
    f.addClutter (60);
    mid::ModelInstanceDetector detector;
    detector.setModel (trueModel (f, box));
    detector.setInputKeypoints (f.keypoints);
    detector.setInputDescriptors (f.descriptors);
    detector.setSeed (5);
    mid::ModelInstances found;
    ASSERT_TRUE (detector.detect (found));
    ASSERT_EQ (found.size(), static_cast<std::size_t> (copies));
    std::set<int> instances;
    for (const auto& instance : found) {
      const int truth = trueInstance (f, instance);
      instances.insert (truth);
      const auto error =
          poseError (instance.pose, f.poses[static_cast<std::size_t> (truth)].matrix());
      EXPECT_LT (error.first, 1.0 * M_PI / 180.0);
      EXPECT_LT (error.second, 0.002);
      EXPECT_GE (instance.keypoints.size(), 25u);
    }
    EXPECT_EQ (instances.size(), static_cast<std::size_t> (copies));

    mid::ModelInstances again;
    ASSERT_TRUE (detector.detect (again));
    ASSERT_EQ (again.size(), found.size());
    for (std::size_t i = 0; i < found.size(); ++i)
      EXPECT_EQ (again[i].pose, found[i].pose);
  }
}

TEST (ModelInstanceDetector, RespectsCandidatesAndTheInlierRequirements)
{
  Frame f;
  const int box = f.addObject (30);
  const auto a = f.addInstance (box, pose (-0.2f, 0.0f, 0.3f, {0, 0, 1}));
  f.addInstance (box, pose (0.2f, 0.0f, 1.3f, {0, 1, 0}));
  mid::ModelInstanceDetector detector;
  detector.setModel (trueModel (f, box));
  detector.setInputKeypoints (f.keypoints);
  detector.setInputDescriptors (f.descriptors);
  detector.setCandidates (pcl::make_shared<pcl::Indices> (a.begin(), a.end()));
  mid::ModelInstances found;
  ASSERT_TRUE (detector.detect (found));
  ASSERT_EQ (found.size(), 1u);
  EXPECT_EQ (trueInstance (f, found.front()), 0);

  detector.setCandidates (pcl::make_shared<pcl::Indices> (a.begin(), a.begin() + 4));
  ASSERT_TRUE (detector.detect (found));
  EXPECT_TRUE (found.empty()); // 4 keypoints cannot give 5 inliers

  detector.setCandidates (pcl::make_shared<pcl::Indices> (1, 5000));
  EXPECT_FALSE (detector.detect (found));
  detector.setCandidates (nullptr);
  detector.setMinInliers (2);
  EXPECT_FALSE (detector.detect (found));
  EXPECT_TRUE (found.empty());
}

TEST (ModelInstanceDetector, KeypointsAlongOneLineGiveNoInstance)
{
  // Six of the object's points lie along one line (1 mm either side of it, like a row of
  // letters), the seventh 2 cm off it. Seen alone, the six fix no turn about the line: any
  // such turn of the model keeps them all as inliers.
  Frame f;
  const int box = f.addObject (30);
  auto& points = f.objects[static_cast<std::size_t> (box)];
  for (int k = 0; k < 6; ++k)
    points[static_cast<std::size_t> (k)] =
        Eigen::Vector3f (-0.04f + 0.016f * static_cast<float> (k),
                         0.01f + (k % 2 == 0 ? 0.001f : -0.001f),
                         0.02f);
  points[6] = Eigen::Vector3f (0.0f, 0.03f, 0.02f);
  const auto copy = f.addInstance (box, pose (0.1f, 0.0f, 0.7f, {1, 1, 0}));
  mid::ModelInstanceDetector detector;
  detector.setModel (trueModel (f, box));
  detector.setInputKeypoints (f.keypoints);
  detector.setInputDescriptors (f.descriptors);
  detector.setCandidates (
      pcl::make_shared<pcl::Indices> (copy.begin(), copy.begin() + 6));
  mid::ModelInstances found;
  ASSERT_TRUE (detector.detect (found));
  EXPECT_TRUE (found.empty());

  // Without the test the six give an instance.
  const float spread = detector.getMinInlierSpread();
  detector.setMinInlierSpread (0.0f);
  ASSERT_TRUE (detector.detect (found));
  EXPECT_EQ (found.size(), 1u);

  // The seventh point fixes the turn: the copy is found at its pose.
  detector.setMinInlierSpread (spread);
  detector.setCandidates (
      pcl::make_shared<pcl::Indices> (copy.begin(), copy.begin() + 7));
  ASSERT_TRUE (detector.detect (found));
  ASSERT_EQ (found.size(), 1u);
  EXPECT_EQ (found.front().keypoints.size(), 7u);
  const auto error = poseError (found.front().pose, f.poses.front().matrix());
  EXPECT_LT (error.first, 0.5 * M_PI / 180.0);
  EXPECT_LT (error.second, 0.001);

  detector.setMinInlierSpread (-0.01f);
  EXPECT_FALSE (detector.detect (found));
  EXPECT_TRUE (found.empty());
}

TEST (ModelMerging, TwoPartialModelsOfOneObjectBecomeOne)
{
  Frame f;
  const int box = f.addObject (30);
  const auto a = f.addInstance (box, pose (-0.2f, 0.0f, 0.3f, {0, 0, 1}));
  const auto b = f.addInstance (box, pose (0.2f, 0.0f, 1.3f, {0, 1, 0}));
  // Two models of the same two instances: points 0-17 and points 12-29 (overlap 12-17).
  auto build = [&] (int first, int last) {
    std::vector<int> pa (a.begin() + first, a.begin() + last),
        pb (b.begin() + first, b.begin() + last);
    auto clusters =
        std::make_shared<mid::TripletClusters> (1, f.cluster (pa, pb, pa.size()));
    mid::MultiInstanceModelBuilder builder;
    builder.setInputCloud (f.keypoints);
    builder.setInputDescriptors (f.descriptors);
    builder.setClusters (clusters);
    mid::ObjectModels models;
    EXPECT_TRUE (builder.compute (models));
    return models.front();
  };
  mid::ObjectModel first = build (0, 18);
  const mid::ObjectModel second = build (12, 30);
  // Where `second`'s frame sits in `first`'s: from their instances of the same true instance.
  const Eigen::Matrix4f first_to_second =
      second.instances[0].pose.inverse() * first.instances[0].pose;
  std::vector<std::pair<int, int>> same;
  for (std::size_t o = 0; o < first.instances[0].keypoints.size(); ++o)
    for (std::size_t p = 0; p < second.instances[0].keypoints.size(); ++p)
      if (first.instances[0].keypoints[o] == second.instances[0].keypoints[p])
        same.emplace_back (first.instances[0].landmarks[o],
                           second.instances[0].landmarks[p]);
  ASSERT_EQ (same.size(), 6u);
  mid::mergeModel (first, second, first_to_second, same, 0.17f, 0.01f);
  EXPECT_EQ (first.landmarks.size(), 30u);
  ASSERT_EQ (first.instances.size(), 2u); // the same two instances, joined
  for (const auto& instance : first.instances)
    EXPECT_EQ (instance.keypoints.size(), 30u);
  mid::refineModel (first, *f.keypoints);
  expectPosesRelativeToTruth (f, first, 1e-4, 1e-5);
  for (const auto& instance : first.instances)
    EXPECT_LT (instance.rms_error, 1e-5f);
}

TEST (ModelFrame, CentringKeepsWhereEveryInstancePlacesTheLandmarks)
{
  // Landmarks around (0.3, -0.1, 0.9), seen by two instances at known rigid motions.
  mid::ObjectModel model;
  const std::vector<Eigen::Vector3f> points = {
      {0.30f, -0.10f, 0.90f}, {0.36f, -0.08f, 0.92f}, {0.28f, -0.02f, 0.95f}};
  for (const auto& point : points) {
    pcl::PointNormal landmark;
    landmark.getVector3fMap() = point;
    landmark.getNormalVector3fMap() = Eigen::Vector3f (0.0f, 0.6f, -0.8f);
    model.landmarks.push_back (landmark);
  }
  const std::vector<Eigen::Isometry3f> motions = {
      mid::test::rigidMotion (Eigen::Vector3f::Zero()),
      mid::test::rigidMotion (Eigen::Vector3f (0.1f, 0.2f, -0.05f), 0.7f, {1, 2, 3})};
  for (const auto& motion : motions) {
    mid::ModelInstance instance;
    instance.pose = motion.matrix();
    model.instances.push_back (instance);
  }
  mid::centerModelFrame (model);

  const Eigen::Vector3f centroid =
      (points[0] + points[1] + points[2]) / 3.0f; // where the frame moved to
  Eigen::Vector3f sum = Eigen::Vector3f::Zero();
  for (std::size_t l = 0; l < points.size(); ++l) {
    const Eigen::Vector3f landmark = model.landmarks[l].getVector3fMap();
    sum += landmark;
    EXPECT_LT ((landmark - (points[l] - centroid)).norm(), 1e-5f);
    EXPECT_TRUE (model.landmarks[l].getNormalVector3fMap().isApprox (
        Eigen::Vector3f (0.0f, 0.6f, -0.8f)));
    for (std::size_t i = 0; i < motions.size(); ++i) {
      const Eigen::Matrix4f& pose = model.instances[i].pose;
      const Eigen::Vector3f placed =
          pose.topLeftCorner<3, 3>() * landmark + pose.topRightCorner<3, 1>();
      EXPECT_LT ((placed - motions[i] * points[l]).norm(), 1e-5f);
      const Eigen::Matrix3f rotation = pose.topLeftCorner<3, 3>();
      EXPECT_LT ((rotation - motions[i].linear()).norm(), 1e-5f);
    }
  }
  EXPECT_LT (sum.norm(), 1e-5f);

  mid::ObjectModel empty;
  empty.instances.resize (1);
  mid::centerModelFrame (empty);
  EXPECT_TRUE (empty.instances.front().pose.isIdentity());
}

TEST (ModelFrame, ModelOfKeypointsIsCentredOnThemAndPlacesEachOnItsKeypoint)
{
  // Keypoints 0.8 m in front of the camera, each with its own normal and descriptor; the
  // model of three of them (the pipeline's models from patches).
  mid::KeypointCloud keypoints;
  mid::SIFTDescriptorCloud descriptors;
  const std::vector<Eigen::Vector3f> points = {{0.10f, -0.05f, 0.80f},
                                               {0.14f, -0.02f, 0.82f},
                                               {0.07f, 0.01f, 0.85f},
                                               {0.30f, 0.20f, 0.90f}};
  for (std::size_t k = 0; k < points.size(); ++k) {
    pcl::PointNormal keypoint;
    keypoint.getVector3fMap() = points[k];
    keypoint.getNormalVector3fMap() =
        Eigen::Vector3f (0.1f * static_cast<float> (k), 0.6f, -0.8f).normalized();
    keypoints.push_back (keypoint);
    mid::SIFTDescriptor descriptor;
    std::fill (std::begin (descriptor.histogram),
               std::end (descriptor.histogram),
               static_cast<float> (k + 1));
    descriptors.push_back (descriptor);
  }
  const pcl::Indices observed = {2, 0, 1};
  const mid::ObjectModel model =
      mid::modelOfKeypoints (keypoints, descriptors, observed);

  ASSERT_EQ (model.landmarks.size(), 3u);
  ASSERT_EQ (model.instances.size(), 1u);
  const mid::ModelInstance& instance = model.instances.front();
  EXPECT_EQ (instance.keypoints, observed);
  const Eigen::Vector3f centroid = (points[0] + points[1] + points[2]) / 3.0f;
  // The frame sits at the keypoints' centroid with the camera's axes.
  const Eigen::Matrix3f rotation = instance.pose.topLeftCorner<3, 3>();
  EXPECT_TRUE (rotation.isIdentity (1e-6f));
  EXPECT_LT ((instance.pose.topRightCorner<3, 1>() - centroid).norm(), 1e-6f);
  Eigen::Vector3f sum = Eigen::Vector3f::Zero();
  for (std::size_t i = 0; i < observed.size(); ++i) {
    const auto k = static_cast<std::size_t> (observed[i]);
    const auto l = static_cast<std::size_t> (instance.landmarks[i]);
    const Eigen::Vector3f landmark = model.landmarks[l].getVector3fMap();
    sum += landmark;
    EXPECT_LT ((landmark + centroid - points[k]).norm(), 1e-6f);
    EXPECT_TRUE (model.landmarks[l].getNormalVector3fMap().isApprox (
        keypoints[k].getNormalVector3fMap()));
    const auto d =
        static_cast<std::size_t> (std::find (model.descriptor_landmarks.begin(),
                                             model.descriptor_landmarks.end(),
                                             static_cast<int> (l)) -
                                  model.descriptor_landmarks.begin());
    ASSERT_LT (d, model.descriptors.size());
    EXPECT_EQ (model.descriptors[d].histogram[0], static_cast<float> (k + 1));
  }
  EXPECT_LT (sum.norm(), 1e-6f);
  EXPECT_LT (instance.rms_error, 1e-6f);
  float diameter = 0.0f; // the farthest two of the three keypoints
  for (std::size_t a = 0; a < 3; ++a)
    for (std::size_t b = a + 1; b < 3; ++b)
      diameter = std::max (diameter, (points[a] - points[b]).norm());
  EXPECT_NEAR (model.diameter, diameter, 1e-6f);

  const pcl::Indices none;
  const mid::ObjectModel empty = mid::modelOfKeypoints (keypoints, descriptors, none);
  EXPECT_TRUE (empty.landmarks.empty());
  EXPECT_TRUE (empty.instances.empty());
}

TEST (ModelFrame, AnInstanceOfKeypointsCarriesThemIntoTheModelFrame)
{
  // A model with one landmark; a copy at a known pose observes two more keypoints.
  mid::ObjectModel model;
  pcl::PointNormal first;
  first.getVector3fMap() = Eigen::Vector3f (0.01f, 0.0f, 0.0f);
  first.getNormalVector3fMap() = Eigen::Vector3f::UnitZ();
  model.landmarks.push_back (first);
  model.descriptors.resize (1);
  model.descriptor_landmarks.push_back (0);
  const Eigen::Isometry3f motion =
      mid::test::rigidMotion (Eigen::Vector3f (-0.2f, 0.1f, 0.9f), 1.1f, {0, 1, 1});
  const std::vector<Eigen::Vector3f> in_model = {{0.03f, 0.02f, -0.01f},
                                                 {-0.04f, 0.05f, 0.02f}};
  mid::KeypointCloud keypoints;
  mid::SIFTDescriptorCloud descriptors;
  for (const auto& point : in_model) {
    pcl::PointNormal keypoint;
    keypoint.getVector3fMap() = motion * point;
    keypoint.getNormalVector3fMap() = motion.linear() * Eigen::Vector3f::UnitX();
    keypoints.push_back (keypoint);
    mid::SIFTDescriptor descriptor;
    std::fill (std::begin (descriptor.histogram),
               std::end (descriptor.histogram),
               static_cast<float> (10 + keypoints.size()));
    descriptors.push_back (descriptor);
  }
  mid::addInstanceOfKeypoints (keypoints, descriptors, {0, 1}, motion.matrix(), model);

  ASSERT_EQ (model.landmarks.size(), 3u);
  ASSERT_EQ (model.instances.size(), 1u);
  EXPECT_EQ (model.descriptors.size(), 3u);
  EXPECT_EQ (model.descriptor_landmarks, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ (model.instances.front().landmarks, (std::vector<int>{1, 2}));
  EXPECT_EQ (model.instances.front().keypoints, (pcl::Indices{0, 1}));
  EXPECT_TRUE (model.instances.front().pose.isApprox (motion.matrix()));
  EXPECT_EQ (model.descriptors[1].histogram[0], 11.0f);
  EXPECT_EQ (model.descriptors[2].histogram[127], 12.0f);
  for (std::size_t i = 0; i < in_model.size(); ++i) {
    EXPECT_LT ((model.landmarks[i + 1].getVector3fMap() - in_model[i]).norm(), 1e-5f);
    EXPECT_LT (
        (model.landmarks[i + 1].getNormalVector3fMap() - Eigen::Vector3f::UnitX())
            .norm(),
        1e-5f);
  }
  EXPECT_LT (model.instances.front().rms_error, 1e-5f);
  const std::vector<Eigen::Vector3f> all = {
      Eigen::Vector3f (0.01f, 0.0f, 0.0f), in_model[0], in_model[1]};
  float diameter = 0.0f;
  for (std::size_t a = 0; a < all.size(); ++a)
    for (std::size_t b = a + 1; b < all.size(); ++b)
      diameter = std::max (diameter, (all[a] - all[b]).norm());
  EXPECT_NEAR (model.diameter, diameter, 1e-5f);
}

TEST (ModelFrame, CopiesThatShareLandmarksFormOneGroup)
{
  // Six landmarks; instances 0 and 2 share landmark 1, instance 3 shares landmark 4 with 2 (so
  // 0, 2, 3 are one group through 2), instance 1 sees landmarks nobody else sees, instance 4
  // sees nothing, and instance 5 observes a landmark the model does not have besides 5, which
  // it shares with 1.
  mid::ObjectModel model;
  model.landmarks.resize (6);
  const std::vector<std::vector<int>> observed = {
      {0, 1}, {2, 3}, {1, 4}, {4}, {}, {9, -1, 5, 3}};
  for (const auto& landmarks : observed) {
    mid::ModelInstance instance;
    instance.landmarks = landmarks;
    instance.keypoints.assign (landmarks.size(), 0);
    model.instances.push_back (instance);
  }
  EXPECT_EQ (mid::sharedLandmarkGroups (model), (std::vector<int>{0, 1, 0, 0, 2, 1}));

  // Every copy linked: one group.
  model.instances[4].landmarks = {0};
  model.instances[5].landmarks = {4, 3};
  EXPECT_EQ (mid::sharedLandmarkGroups (model), (std::vector<int> (6, 0)));
  EXPECT_TRUE (mid::sharedLandmarkGroups (mid::ObjectModel()).empty());
}
