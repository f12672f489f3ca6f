#pragma once

// Boxes resting on a table at known poses, rendered with their keypoints: the scenes of the
// tests of the steps that measure boxes on the support plane.
#include "rendered_keypoints.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <vector>

namespace mid {
namespace test {

/** The table the boxes rest on, facing the camera (metres). */
inline constexpr double kTableDepth = 0.95;

/** A box of the given size lying on the table at (x, y), turned by `roll` degrees. */
inline BoxSpec
restingBox (const char* print,
            double x,
            double y,
            double roll,
            const Eigen::Vector3d& size = kPrintedBoxSize)
{
  return {print, size, boxPose (x, y, kTableDepth - 0.5 * size.z(), roll)};
}

/** Four boxes apart on the table: 0 and 1 with one print, 2 and 3 with another. */
inline std::vector<BoxSpec>
fourBoxes (const Eigen::Vector3d& size_of_2_and_3 = kPrintedBoxSize)
{
  return {restingBox (kApplePrint, -0.16, -0.1, 10.0),
          restingBox (kApplePrint, 0.16, -0.12, -35.0),
          restingBox (kSoyPrint, -0.15, 0.12, 70.0, size_of_2_and_3),
          restingBox (kSoyPrint, 0.17, 0.11, 160.0, size_of_2_and_3)};
}

/** The proper rotations that map a box with three different edges onto itself. */
inline std::array<Eigen::Matrix3f, 4>
boxSymmetries ()
{
  return {Eigen::Matrix3f::Identity(),
          Eigen::Matrix3f (
              Eigen::AngleAxisf (static_cast<float> (M_PI), Eigen::Vector3f::UnitX())),
          Eigen::Matrix3f (
              Eigen::AngleAxisf (static_cast<float> (M_PI), Eigen::Vector3f::UnitY())),
          Eigen::Matrix3f (
              Eigen::AngleAxisf (static_cast<float> (M_PI), Eigen::Vector3f::UnitZ()))};
}

/** Rotation error (degrees) of `pose` against the box's true pose, modulo the box's
  * symmetries (the model frame is the box's own frame).
  */
inline double
rotationErrorModuloBox (const Eigen::Matrix4f& pose, const Eigen::Isometry3d& truth)
{
  double best = 180.0;
  for (const auto& s : boxSymmetries()) {
    const Eigen::Matrix3f expected = truth.linear().cast<float>() * s;
    const Eigen::AngleAxisf error (expected.transpose() * pose.topLeftCorner<3, 3>());
    best = std::min (best, static_cast<double> (error.angle()) * 180.0 / M_PI);
  }
  return best;
}

/** True if `point` lies in the box (within 2 mm). */
inline bool
insideBox (const BoxSpec& box, const Eigen::Vector3f& point)
{
  const Eigen::Vector3d local = box.pose.inverse() * point.cast<double>();
  return (local.cwiseAbs() - 0.5 * box.size).maxCoeff() < 0.002;
}

struct RestingBoxes : RenderedKeypoints
{
  /** \param[in] view_tilt see renderBoxes() */
  explicit RestingBoxes (const std::vector<BoxSpec>& boxes,
                         double table = kTableDepth,
                         double view_tilt = 0.0)
  : RenderedKeypoints (renderBoxes (boxes, table, view_tilt))
  {}

  /** A model of the given boxes at their true poses, in the frame of the first box moved by
    * `frame` (model -> box), so that two models' frames differ; with `keep`, of the keypoints
    * alone whose position in their box's frame it keeps.
    */
  mid::ObjectModel
  modelOf (const std::vector<std::size_t>& boxes,
           const Eigen::Isometry3f& frame = Eigen::Isometry3f::Identity(),
           const std::function<bool (const Eigen::Vector3f&)>& keep = {}) const
  {
    mid::ObjectModel model;
    for (const auto b : boxes)
      addTruthInstance (b, model, keep);
    for (auto& instance : model.instances)
      instance.pose = instance.pose * frame.matrix();
    const Eigen::Isometry3f to_model = frame.inverse();
    for (auto& landmark : model.landmarks) {
      landmark.getVector3fMap() = to_model * landmark.getVector3fMap();
      landmark.getNormalVector3fMap() =
          to_model.linear() * landmark.getNormalVector3fMap();
    }
    return model;
  }

  /** The pixels of the keypoints on box b. */
  pcl::Indices
  seedsOn (int b) const
  {
    pcl::Indices seeds;
    for (const auto k : on ({b}))
      seeds.push_back (surface.keypoint_pixels[static_cast<std::size_t> (k)]);
    return seeds;
  }
};

/** A step that measures boxes on the table (a SupportPlaneMeasurement), given the scene's
  * keypoints and keypoint surface.
  */
template <typename Step>
Step
measuringStep (const RestingBoxes& scene)
{
  Step step;
  step.setInputKeypoints (scene.keypoints);
  step.setKeypointSurface (scene.surface);
  return step;
}

/** measuringStep(), for a step that also keeps the keypoints' descriptors. */
template <typename Step>
Step
describingStep (const RestingBoxes& scene)
{
  Step step = measuringStep<Step> (scene);
  step.setInputDescriptors (scene.descriptors);
  return step;
}

/** Boxes 0 and 1 (one print) apart, boxes 2 and 3 (another print) touching along their long
  * edges, so that their tops join in one flat surface.
  */
inline std::vector<BoxSpec>
twoApartTwoTouching (const Eigen::Vector3d& size_of_0_and_1 = kPrintedBoxSize)
{
  return {restingBox (kApplePrint, -0.16, -0.1, 10.0, size_of_0_and_1),
          restingBox (kApplePrint, 0.16, -0.12, -35.0, size_of_0_and_1),
          restingBox (kSoyPrint, 0.0, 0.1, 0.0),
          restingBox (kSoyPrint, 0.0, 0.19, 180.0)};
}

/** Boxes 0 and 1 (one print), each lying flush with a box of its height and another print, 0's
  * along its long edge (box 4), 1's along its short edge (box 5), so that the top of each joins
  * its neighbour's in one flat surface in a different place; boxes 2 and 3 (a third print, of
  * `size_of_2_and_3`) apart.
  */
inline std::vector<BoxSpec>
twoJoinedTwoApart (const Eigen::Vector3d& size_of_2_and_3 = kPrintedBoxSize)
{
  constexpr const char* kNeighbourPrint = "god_morgon_orange_juice_front.jpg";
  return {restingBox (kApplePrint, -0.2, -0.15, 0.0),
          restingBox (kApplePrint, 0.2, -0.15, 0.0),
          restingBox (kSoyPrint, -0.15, 0.2, 70.0, size_of_2_and_3),
          restingBox (kSoyPrint, 0.17, 0.2, 160.0, size_of_2_and_3),
          restingBox (kNeighbourPrint, -0.2, -0.15 + kPrintedBoxSize.y(), 0.0),
          restingBox (kNeighbourPrint, 0.2 + kPrintedBoxSize.x(), -0.15, 0.0)};
}

} // namespace test
} // namespace mid
