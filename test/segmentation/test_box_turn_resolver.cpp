// BoxTurnResolver on rendered printed boxes resting on a table at known poses: a copy posed by
// its box in the wrong turn is turned back to the truth by its print.
#include "resting_boxes.h"

#include <mid/segmentation/box_turn_resolver.h>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace {

using mid::test::kApplePrint;
using mid::test::restingBox;
using Boxes = mid::test::RestingBoxes;

/** A box whose printed face is a square: a quarter turn about its short edge keeps the box. */
const Eigen::Vector3d kSquareBoxSize{0.09, 0.09, 0.04};

/** Two copies of the apple print apart on the table, of the given size. */
std::vector<mid::test::BoxSpec>
twoCopies (const Eigen::Vector3d& size = mid::test::kPrintedBoxSize)
{
  return {restingBox (kApplePrint, -0.12, -0.02, 10.0, size),
          restingBox (kApplePrint, 0.13, 0.03, -35.0, size)};
}

/** The resolver on the scene, with a verification of the scene's frame. */
mid::BoxTurnResolver
resolverFor (const Boxes& scene)
{
  auto resolver = mid::test::measuringStep<mid::BoxTurnResolver> (scene);
  mid::PhotometricVerification verification;
  verification.setKeypointSurface (scene.surface);
  resolver.setVerification (verification);
  return resolver;
}

/** Boxes 0 and 1 as one model in the box frame, box 1 posed in `turn` (box frame) with the
  * landmarks it observes turned alike: every observation is where it was, the two copies share
  * no landmark, and box 1's relative pose is off by the turn (what a pose from the box alone
  * may be).
  */
mid::ObjectModel
modelWithTurnedCopy (const Boxes& scene, const Eigen::Matrix3f& turn)
{
  mid::ObjectModel model = scene.modelOf ({0});
  const std::size_t first_landmark = model.landmarks.size();
  scene.addTruthInstance (1, model);
  Eigen::Matrix4f turn4 = Eigen::Matrix4f::Identity();
  turn4.topLeftCorner<3, 3>() = turn;
  model.instances[1].pose = model.instances[1].pose * turn4;
  for (std::size_t l = first_landmark; l < model.landmarks.size(); ++l) {
    auto& landmark = model.landmarks[l];
    landmark.getVector3fMap() = turn.transpose() * landmark.getVector3fMap();
    landmark.getNormalVector3fMap() =
        turn.transpose() * landmark.getNormalVector3fMap();
  }
  return model;
}

/** Rotation error (degrees) of the model's relative pose of box 1 to box 0 against the
  * truth.
  */
double
relativeRotationError (const Boxes& scene, const mid::ObjectModel& model)
{
  const Eigen::Matrix3f estimated =
      model.instances[1].pose.topLeftCorner<3, 3>() *
      model.instances[0].pose.topLeftCorner<3, 3>().transpose();
  const Eigen::Matrix3f truth = (scene.scene.boxes[1].pose.linear() *
                                 scene.scene.boxes[0].pose.linear().transpose())
                                    .cast<float>();
  return static_cast<double> (
             Eigen::AngleAxisf (truth.transpose() * estimated).angle()) *
         180.0 / M_PI;
}

/** Every observation of the model lies where its instance's pose puts its landmark (1 mm). */
void
expectObservationsExplained (const Boxes& scene, const mid::ObjectModel& model)
{
  for (const auto& instance : model.instances) {
    EXPECT_LT (instance.rms_error, 0.001f);
    for (std::size_t o = 0; o < instance.keypoints.size(); ++o) {
      const Eigen::Vector3f placed =
          (instance.pose *
           model.landmarks[static_cast<std::size_t> (instance.landmarks[o])]
               .getVector3fMap()
               .homogeneous())
              .head<3>();
      EXPECT_LT (
          (placed - (*scene.keypoints)[static_cast<std::size_t> (instance.keypoints[o])]
                        .getVector3fMap())
              .norm(),
          0.001f);
    }
  }
}

/** A copy turned by `turn` about its box's axes is turned back: the relative pose is the
  * truth's and every observation stays explained.
  */
void
expectTurnedBack (const Eigen::Vector3d& size, const Eigen::Matrix3f& turn)
{
  const Boxes scene (twoCopies (size));
  mid::ObjectModels models{modelWithTurnedCopy (scene, turn)};
  ASSERT_GT (relativeRotationError (scene, models[0]), 80.0);
  std::size_t turned = 0;
  ASSERT_TRUE (resolverFor (scene).resolve (models, turned));
  EXPECT_EQ (turned, 1u);
  ASSERT_EQ (models.size(), 1u);
  ASSERT_EQ (models[0].instances.size(), 2u);
  EXPECT_LT (relativeRotationError (scene, models[0]), 2.0);
  expectObservationsExplained (scene, models[0]);
}

Eigen::Matrix3f
halfTurn (const Eigen::Vector3f& axis)
{
  return Eigen::AngleAxisf (static_cast<float> (M_PI), axis).toRotationMatrix();
}

} // namespace

TEST (BoxTurnResolver, TurnsACopyPosedUpsideDownInItsPrintBackToTheTruth)
{
  // A half turn about the axis towards the camera: the print faces the camera, upside down.
  expectTurnedBack (mid::test::kPrintedBoxSize, halfTurn (Eigen::Vector3f::UnitZ()));
}

TEST (BoxTurnResolver, TurnsACopyPosedWithItsPrintTowardsTheTableBackToTheTruth)
{
  // A half turn about the long edge: the print would face the table, where nothing shows it.
  expectTurnedBack (mid::test::kPrintedBoxSize, halfTurn (Eigen::Vector3f::UnitX()));
}

TEST (BoxTurnResolver, TurnsACopyOfASquareBoxPosedAQuarterTurnOffBackToTheTruth)
{
  expectTurnedBack (
      kSquareBoxSize,
      Eigen::AngleAxisf (static_cast<float> (M_PI / 2.0), Eigen::Vector3f::UnitZ())
          .toRotationMatrix());
}

TEST (BoxTurnResolver, KeepsCopiesInTheirTrueTurn)
{
  const Boxes scene (twoCopies());
  const mid::ObjectModels original{
      modelWithTurnedCopy (scene, Eigen::Matrix3f::Identity())};
  mid::ObjectModels models = original;
  std::size_t turned = 1;
  ASSERT_TRUE (resolverFor (scene).resolve (models, turned));
  EXPECT_EQ (turned, 0u);
  ASSERT_EQ (models.size(), 1u);
  for (std::size_t i = 0; i < 2; ++i)
    EXPECT_TRUE (models[0].instances[i].pose.isApprox (original[0].instances[i].pose));
  EXPECT_LT (relativeRotationError (scene, models[0]), 1.0);
}

TEST (BoxTurnResolver, LeavesCopiesThatObserveACommonLandmark)
{
  // The copies' relative pose rests on a common landmark (on the print), not on the box: it
  // is left as it is, even turned.
  const Boxes scene (twoCopies());
  mid::ObjectModels models{
      modelWithTurnedCopy (scene, halfTurn (Eigen::Vector3f::UnitZ()))};
  auto& second = models[0].instances[1];
  second.keypoints.push_back (models[0].instances[0].keypoints.front());
  second.landmarks.push_back (models[0].instances[0].landmarks.front());
  const mid::ObjectModels original = models;
  std::size_t turned = 1;
  ASSERT_TRUE (resolverFor (scene).resolve (models, turned));
  EXPECT_EQ (turned, 0u);
  EXPECT_TRUE (models[0].instances[1].pose.isApprox (original[0].instances[1].pose));
}

TEST (BoxTurnResolver, RefusesBadInputAndLeavesTheModels)
{
  const Boxes scene (twoCopies());
  const mid::ObjectModels original{
      modelWithTurnedCopy (scene, halfTurn (Eigen::Vector3f::UnitZ()))};
  const auto refused = [&] (const mid::BoxTurnResolver& resolver) {
    mid::ObjectModels models = original;
    std::size_t turned = 1;
    EXPECT_FALSE (resolver.resolve (models, turned));
    EXPECT_EQ (turned, 0u);
    EXPECT_TRUE (models[0].instances[1].pose.isApprox (original[0].instances[1].pose));
  };
  auto no_verification = mid::test::measuringStep<mid::BoxTurnResolver> (scene);
  refused (no_verification);
  for (const float gain : {-0.1f, 2.5f, std::nanf ("")}) {
    auto resolver = resolverFor (scene);
    resolver.setMinGain (gain);
    refused (resolver);
  }
  auto no_keypoints = resolverFor (scene);
  no_keypoints.setInputKeypoints (nullptr);
  refused (no_keypoints);
}
