// SurfacePoseRefinement on rendered copies of a printed box at known poses.
#include "rendered_keypoints.h"

#include <mid/registration/model_refinement.h>
#include <mid/segmentation/surface_pose_refinement.h>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <limits>

namespace {

using mid::test::boxPose;
using mid::test::kApplePrint;
using mid::test::kPrintedBoxSize;

/** Three copies of one print (box 1 tilted), in front of a table; a model whose frame is box
  * 0's own: box 0 at its true pose with every keypoint a landmark, box 1 observing only its
  * two keypoints farthest apart, box 2 observing all of its own (each keypoint of a copy
  * observes the landmark within 2 mm of its true model point).
  */
struct ThreeCopies : mid::test::RenderedKeypoints
{
  mid::ObjectModel model;

  ThreeCopies()
  : RenderedKeypoints (mid::test::renderBoxes (
        {{kApplePrint, kPrintedBoxSize, boxPose (-0.12, -0.07, 0.8, 15.0)},
         {kApplePrint, kPrintedBoxSize, boxPose (0.11, -0.06, 0.84, 200.0, 20.0)},
         {kApplePrint, kPrintedBoxSize, boxPose (-0.1, 0.1, 0.82, -70.0)}},
        0.95))
  {
    addTruthInstance (0, model);
    model.instances.push_back (observingInstance (1));
    model.instances.push_back (observingInstance (2));
    auto& sparse = model.instances[1];
    std::size_t a = 0, b = 0;
    float widest = 0.0f;
    for (std::size_t i = 0; i < sparse.keypoints.size(); ++i)
      for (std::size_t j = i + 1; j < sparse.keypoints.size(); ++j) {
        const float d =
            (point (sparse.keypoints[i]) - point (sparse.keypoints[j])).norm();
        if (d > widest) {
          widest = d;
          a = i;
          b = j;
        }
      }
    sparse.keypoints = {sparse.keypoints[a], sparse.keypoints[b]};
    sparse.landmarks = {sparse.landmarks[a], sparse.landmarks[b]};
  }

  /** Box b at its true pose, observing the landmark nearest each of its keypoints' true model
    * points (within 2 mm).
    */
  mid::ModelInstance
  observingInstance (std::size_t b) const
  {
    mid::ModelInstance instance;
    instance.pose = scene.boxes[b].pose.matrix().cast<float>();
    const Eigen::Affine3f to_model (instance.pose.inverse());
    for (const auto k : on ({static_cast<int> (b)})) {
      const Eigen::Vector3f m = to_model * point (k);
      int nearest = -1;
      float best = 0.002f;
      for (std::size_t l = 0; l < model.landmarks.size(); ++l) {
        const float d = (model.landmarks[l].getVector3fMap() - m).norm();
        if (d < best) {
          best = d;
          nearest = static_cast<int> (l);
        }
      }
      if (nearest >= 0) {
        instance.keypoints.push_back (k);
        instance.landmarks.push_back (nearest);
      }
    }
    EXPECT_GE (instance.keypoints.size(), 3u) << "box " << b;
    return instance;
  }

  Eigen::Vector3f
  point (pcl::index_t k) const
  {
    return (*keypoints)[static_cast<std::size_t> (k)].getVector3fMap();
  }

  mid::SurfacePoseRefinement
  refinement () const
  {
    mid::SurfacePoseRefinement refinement;
    refinement.setInputKeypoints (keypoints);
    refinement.setKeypointSurface (surface);
    return refinement;
  }

  /** Turn instance 1 by `degrees` about the line through its two observed keypoints, which
    * its observations then cannot see.
    */
  void
  turnSparseInstance (float degrees)
  {
    auto& sparse = model.instances[1];
    const Eigen::Vector3f a = point (sparse.keypoints[0]),
                          b = point (sparse.keypoints[1]);
    const Eigen::Affine3f turn =
        Eigen::Translation3f (a) *
        Eigen::AngleAxisf (degrees * static_cast<float> (M_PI) / 180.0f,
                           (b - a).normalized()) *
        Eigen::Translation3f (-a);
    sparse.pose = turn.matrix() * sparse.pose;
  }

  /** Errors of the motion from instance 0 to instance n (pose_n * pose_0^-1, which does not
    * depend on the model frame) against the truth: its rotation (degrees), and how far from
    * the truth it carries box 0's centre (metres).
    */
  std::pair<double, double>
  relativeError (std::size_t n) const
  {
    const Eigen::Affine3d estimate (
        (model.instances[n].pose * model.instances[0].pose.inverse()).cast<double>());
    const Eigen::Affine3d truth = scene.boxes[n].pose * scene.boxes[0].pose.inverse();
    const Eigen::Vector3d centre = scene.boxes[0].pose.translation();
    return {Eigen::AngleAxisd (estimate.linear().transpose() * truth.linear()).angle() *
                180.0 / M_PI,
            (estimate * centre - truth * centre).norm()};
  }

  /** Angle (degrees) between the textured face's normal carried from box 0 to box n by the
    * estimated motion and by the true one: the tilt, which the depth sees.
    */
  double
  tiltError (std::size_t n) const
  {
    const Eigen::Matrix3d estimate =
        (model.instances[n].pose * model.instances[0].pose.inverse())
            .topLeftCorner<3, 3>()
            .cast<double>();
    const Eigen::Matrix3d truth =
        (scene.boxes[n].pose * scene.boxes[0].pose.inverse()).linear();
    const Eigen::Vector3d face =
        scene.boxes[0].pose.linear() * Eigen::Vector3d (0.0, 0.0, -1.0);
    return std::acos (std::min (1.0, (estimate * face).dot (truth * face))) * 180.0 /
           M_PI;
  }
};

TEST (SurfacePoseRefinement, TheDepthTurnsBackWhatTwoKeypointsLeaveOpen)
{
  ThreeCopies copies;
  ASSERT_GE (copies.model.instances[2].keypoints.size(), 6u);
  copies.turnSparseInstance (12.0f);
  ASSERT_GT (copies.relativeError (1).first, 11.0);
  // The paper's refinement cannot see the turn: box 1 observes two landmarks.
  mid::refineModel (copies.model, *copies.keypoints);
  EXPECT_GT (copies.relativeError (1).first, 11.0);

  ASSERT_GT (copies.tiltError (1), 11.0);

  ASSERT_TRUE (copies.refinement().refine (copies.model));
  EXPECT_LT (copies.tiltError (1), 0.5);
  // About the face's normal, two keypoints a SIFT localization apart decide alone.
  EXPECT_LT (copies.relativeError (1).first, 2.0);
  EXPECT_LT (copies.relativeError (1).second, 0.004);
  EXPECT_LT (copies.relativeError (2).first, 0.5);
  EXPECT_LT (copies.relativeError (2).second, 0.001);
  // Landmarks follow the poses: every observation within 2 mm.
  for (const auto& instance : copies.model.instances)
    EXPECT_LT (instance.rms_error, 0.002f);
}

TEST (SurfacePoseRefinement, WithoutTheSurfaceTheTurnStays)
{
  ThreeCopies copies;
  copies.turnSparseInstance (12.0f);
  auto refinement = copies.refinement();
  refinement.setSurfaceWeight (0.0f);
  ASSERT_TRUE (refinement.refine (copies.model));
  EXPECT_GT (copies.tiltError (1), 11.0);
  EXPECT_LT (copies.relativeError (2).first, 0.5);
}

TEST (SurfacePoseRefinement, TruePosesStayTrue)
{
  ThreeCopies copies;
  copies.model.instances[1] = copies.observingInstance (1);
  auto refinement = copies.refinement();
  refinement.setMaxIterations (20);
  ASSERT_TRUE (refinement.refine (copies.model));
  for (std::size_t n = 1; n < 3; ++n) {
    const auto error = copies.relativeError (n);
    EXPECT_LT (copies.tiltError (n), 0.2) << "box " << n;
    EXPECT_LT (error.first, 0.6) << "box " << n;
    EXPECT_LT (error.second, 0.002) << "box " << n;
  }
  // The model frame stays the reference instance's.
  EXPECT_TRUE (copies.model.instances[0].pose.isApprox (
      copies.scene.boxes[0].pose.matrix().cast<float>()));
}

TEST (SurfacePoseRefinement, OneInstanceIsLeftAsItIs)
{
  ThreeCopies copies;
  copies.model.instances.resize (1);
  copies.model.instances[0].pose (0, 3) += 0.01f;
  const mid::ObjectModel before = copies.model;
  ASSERT_TRUE (copies.refinement().refine (copies.model));
  EXPECT_TRUE (copies.model.instances[0].pose.isApprox (before.instances[0].pose));
}

TEST (SurfacePoseRefinement, RefusesBadInputAndLeavesTheModel)
{
  const ThreeCopies copies;
  const auto refused = [] (const mid::SurfacePoseRefinement& refinement,
                           const mid::ObjectModel& model) {
    mid::ObjectModel copy = model;
    copy.instances[1].pose (0, 3) += 0.005f;
    const mid::ObjectModel before = copy;
    const bool ok = refinement.refine (copy);
    return !ok && copy.instances[1].pose == before.instances[1].pose &&
           copy.landmarks.size() == before.landmarks.size();
  };
  auto refinement = copies.refinement();
  refinement.setInputKeypoints (nullptr);
  EXPECT_TRUE (refused (refinement, copies.model)) << "no keypoints";
  refinement = copies.refinement();
  refinement.setKeypointSurface (mid::KeypointSurface());
  EXPECT_TRUE (refused (refinement, copies.model)) << "no frame";
  refinement = copies.refinement();
  refinement.setSampleStep (0);
  EXPECT_TRUE (refused (refinement, copies.model)) << "sample step 0";
  refinement = copies.refinement();
  refinement.setMaxCorrespondenceDistance (0.0f);
  EXPECT_TRUE (refused (refinement, copies.model)) << "distance 0";
  refinement = copies.refinement();
  refinement.setSurfaceWeight (std::numeric_limits<float>::quiet_NaN());
  EXPECT_TRUE (refused (refinement, copies.model)) << "NaN weight";
  refinement = copies.refinement();
  refinement.setBoxMargin (-0.001f);
  EXPECT_TRUE (refused (refinement, copies.model)) << "negative margin";
  refinement = copies.refinement();
  refinement.setMaxIterations (0);
  EXPECT_TRUE (refused (refinement, copies.model)) << "no iterations";
  mid::ObjectModel broken = copies.model;
  broken.instances[2].landmarks.back() = 100000;
  EXPECT_TRUE (refused (copies.refinement(), broken)) << "a missing landmark";
  broken = copies.model;
  broken.instances[2].keypoints.back() = -1;
  EXPECT_TRUE (refused (copies.refinement(), broken)) << "a negative keypoint";
  broken = copies.model;
  broken.instances[0].pose (1, 1) = std::numeric_limits<float>::infinity();
  EXPECT_TRUE (refused (copies.refinement(), broken)) << "a pose that is not finite";
}

} // namespace
