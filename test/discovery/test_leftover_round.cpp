// The second discovery round on the keypoints left over (DiscoveryParameters::
// discover_leftovers), on keypoint scenes with known poses and descriptor distances.
#include "pipeline_stages.h"
#include "rigid_motion.h"

#include <mid/discovery/discovery_stages.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

namespace {

/** Points on the 12 x 8 cm front face of a product (normals along +z), at least 12 mm apart. */
std::vector<Eigen::Vector3f>
makeFace (std::uint32_t seed)
{
  std::mt19937 rng (seed);
  std::uniform_real_distribution<float> x (-0.06f, 0.06f), y (-0.04f, 0.04f);
  std::vector<Eigen::Vector3f> face;
  while (face.size() < 30) {
    const Eigen::Vector3f point (x (rng), y (rng), 0.0f);
    bool apart = true;
    for (const auto& other : face)
      apart = apart && (other - point).norm() > 0.012f;
    if (apart)
      face.push_back (point);
  }
  return face;
}

/** A descriptor per face point, far (L2 about 900) from every other. */
std::vector<mid::SIFTDescriptor>
makeDescriptors (std::size_t count, std::uint32_t seed)
{
  std::mt19937 rng (seed);
  std::uniform_real_distribution<float> value (0.0f, 200.0f);
  std::vector<mid::SIFTDescriptor> descriptors (count);
  for (auto& descriptor : descriptors)
    for (float& v : descriptor.histogram)
      v = value (rng);
  return descriptors;
}

/** Adds one copy of a face at `pose`: each descriptor moved by a random offset of L2 norm
  * `noise`, so that two copies' descriptors of one point lie about noise x sqrt(2) apart.
  */
void
addCopy (const std::vector<Eigen::Vector3f>& face,
         const std::vector<mid::SIFTDescriptor>& descriptors,
         const Eigen::Isometry3f& pose,
         float noise,
         std::mt19937& rng,
         mid::DiscoveryResult& frame)
{
  std::normal_distribution<float> gaussian;
  for (std::size_t i = 0; i < face.size(); ++i) {
    pcl::PointNormal point;
    point.getVector3fMap() = pose * face[i];
    point.getNormalVector3fMap() = pose.linear() * Eigen::Vector3f::UnitZ();
    frame.keypoints->push_back (point);
    Eigen::Matrix<float, 128, 1> offset;
    for (int d = 0; d < 128; ++d)
      offset[d] = gaussian (rng);
    offset *= noise / offset.norm();
    mid::SIFTDescriptor descriptor = descriptors[i];
    for (int d = 0; d < 128; ++d)
      descriptor.histogram[d] += offset[d];
    frame.descriptors->push_back (descriptor);
  }
}

const std::vector<Eigen::Isometry3f> kPosesA = {
    mid::test::rigidMotion ({-0.25f, -0.1f, 0.8f}),
    mid::test::rigidMotion ({0.0f, -0.12f, 0.8f}, 0.4f),
    mid::test::rigidMotion ({0.25f, -0.1f, 0.8f}, -0.3f)};
const std::vector<Eigen::Isometry3f> kPosesB = {
    mid::test::rigidMotion ({-0.15f, 0.15f, 0.85f}, 0.2f),
    mid::test::rigidMotion ({0.15f, 0.14f, 0.85f}, 1.1f)};

/** Three copies of product A, whose copies' descriptors lie about 14 apart, and two of
  * product B, whose copies' descriptors lie about 400 apart (above the first round's 350, below
  * the leftover round's 450).
  */
mid::DiscoveryResult
makeFrame ()
{
  mid::DiscoveryResult frame;
  frame.keypoints = pcl::make_shared<mid::KeypointCloud>();
  frame.descriptors = pcl::make_shared<mid::SIFTDescriptorCloud>();
  std::mt19937 rng (7);
  const auto face_a = makeFace (1), face_b = makeFace (2);
  const auto descriptors_a = makeDescriptors (face_a.size(), 3);
  const auto descriptors_b = makeDescriptors (face_b.size(), 4);
  for (const auto& pose : kPosesA)
    addCopy (face_a, descriptors_a, pose, 10.0f, rng, frame);
  for (const auto& pose : kPosesB)
    addCopy (face_b, descriptors_b, pose, 283.0f, rng, frame);
  return frame;
}

/** Whether a model holds exactly the given copies, at their true relative poses. */
bool
holdsCopies (const mid::ObjectModel& model, const std::vector<Eigen::Isometry3f>& poses)
{
  if (model.instances.size() != poses.size())
    return false;
  // The instances' order is the model's: find each one's copy by its translation.
  std::vector<std::size_t> copy_of;
  for (const auto& instance : model.instances) {
    std::size_t best = 0;
    for (std::size_t c = 1; c < poses.size(); ++c)
      if ((poses[c].translation() - instance.pose.topRightCorner<3, 1>()).norm() <
          (poses[best].translation() - instance.pose.topRightCorner<3, 1>()).norm())
        best = c;
    copy_of.push_back (best);
  }
  for (std::size_t i = 1; i < model.instances.size(); ++i) {
    const Eigen::Matrix4f found =
        model.instances[i].pose * model.instances[0].pose.inverse();
    const Eigen::Matrix4f truth =
        (poses[copy_of[i]] * poses[copy_of[0]].inverse()).matrix();
    const auto error = mid::test::poseError (found, truth);
    if (copy_of[i] == copy_of[0] || error.first > 0.01 || error.second > 0.002)
      return false;
  }
  return true;
}

} // namespace

TEST (LeftoverRound, FindsAProductWhoseCopiesLookLessAlike)
{
  mid::DiscoveryResult result = makeFrame();
  ASSERT_TRUE (mid::discoverFromKeypoints (mid::DiscoveryParameters(), result));
  ASSERT_EQ (result.models.size(), 2u);
  // The first round's model is A; the second B, with the keypoints of B's copies.
  EXPECT_TRUE (holdsCopies (result.models[0], kPosesA));
  EXPECT_TRUE (holdsCopies (result.models[1], kPosesB));
  for (const auto& instance : result.models[1].instances)
    for (const auto k : instance.keypoints)
      EXPECT_GE (k, 90); // A's 3 x 30 keypoints come first
  // Without an organized frame the patches, the search from the boxes, the surface
  // refinement, the size split and merge, the removal of repeated prints, the size search, the
  // removal of interpenetrating instances, of models of disagreeing sizes and of prints on the
  // table and the measurement of the objects' boxes do not run, but are timed; the pruning of
  // the observations runs.
  const auto& stages = mid::test::pipelineStages();
  const std::vector<std::string> last (
      std::find (stages.begin(), stages.end(), "leftovers"), stages.end());
  ASSERT_EQ (result.model_sizes.size(), 2u); // no frame: no box measured
  EXPECT_FALSE (result.model_sizes[0].valid || result.model_sizes[1].valid);
  ASSERT_GE (result.timing_ms.size(), last.size());
  for (std::size_t i = 0; i < last.size(); ++i)
    EXPECT_EQ (result.timing_ms[result.timing_ms.size() - last.size() + i].first,
               last[i]);
}

TEST (LeftoverRound, TheFirstRoundAloneFindsOnlyTheAlikeProduct)
{
  mid::DiscoveryParameters paper;
  paper.discover_leftovers = false;
  mid::DiscoveryResult result = makeFrame();
  ASSERT_TRUE (mid::discoverFromKeypoints (paper, result));
  ASSERT_EQ (result.models.size(), 1u);
  EXPECT_TRUE (holdsCopies (result.models[0], kPosesA));
  // With the first round's threshold raised to 450, B is found in one round too.
  paper.max_descriptor_distance = 450.0f;
  result = makeFrame();
  ASSERT_TRUE (mid::discoverFromKeypoints (paper, result));
  EXPECT_EQ (result.models.size(), 2u);
}

TEST (LeftoverRound, NothingLeftOverChangesNothing)
{
  // Only product A: every keypoint lies on one of its copies, the second round gets none, and
  // the result is that of the first round alone.
  const auto only_a = [] {
    mid::DiscoveryResult frame = makeFrame();
    frame.keypoints->resize (90);
    frame.descriptors->resize (90);
    return frame;
  };
  mid::DiscoveryResult result = only_a(), first_round = only_a();
  mid::DiscoveryParameters paper;
  paper.discover_leftovers = false;
  ASSERT_TRUE (mid::discoverFromKeypoints (mid::DiscoveryParameters(), result));
  ASSERT_TRUE (mid::discoverFromKeypoints (paper, first_round));
  ASSERT_EQ (result.models.size(), 1u);
  EXPECT_TRUE (holdsCopies (result.models[0], kPosesA));
  ASSERT_EQ (first_round.models.size(), 1u);
  const auto& a = result.models[0];
  const auto& b = first_round.models[0];
  ASSERT_EQ (a.instances.size(), b.instances.size());
  EXPECT_EQ (a.landmarks.size(), b.landmarks.size());
  for (std::size_t i = 0; i < a.instances.size(); ++i) {
    EXPECT_EQ (a.instances[i].keypoints, b.instances[i].keypoints);
    EXPECT_TRUE (a.instances[i].pose.isApprox (b.instances[i].pose, 1e-6f));
  }
}

TEST (LeftoverRound, RefusesParametersOutOfRange)
{
  mid::DiscoveryParameters parameters;
  parameters.leftover_descriptor_distance = 0.0f;
  mid::DiscoveryResult result = makeFrame();
  EXPECT_FALSE (mid::discoverFromKeypoints (parameters, result));
  EXPECT_TRUE (result.models.empty());
  parameters = mid::DiscoveryParameters();
  parameters.leftover_margin = -0.01f;
  EXPECT_FALSE (mid::discoverFromKeypoints (parameters, result));
  EXPECT_TRUE (result.models.empty());
}
