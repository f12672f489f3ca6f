#pragma once

#include <mid/simulation/box_shape.h>
#include <mid/simulation/procedural_texture.h>
#include <mid/simulation/scene.h>
#include <mid/simulation/table_plane.h>

#include <Eigen/Geometry>

#include <memory>

namespace mid {
namespace simulation {
namespace test {

/** A box with a distinct uniform colour per face. */
inline BoxShape::Ptr
makeColoredBox (double size_x, double size_y, double size_z)
{
  auto box = std::make_shared<BoxShape> (size_x, size_y, size_z);
  for (int face = 0; face < BoxShape::FACE_COUNT; ++face)
    box->setFaceTexture (
        static_cast<BoxShape::Face> (face),
        makeUniformTexture (cv::Vec3b (static_cast<uchar> (40 * face + 20),
                                       100,
                                       static_cast<uchar> (200 - 30 * face))));
  return box;
}

/** A pose from a translation and a rotation about an axis. */
inline Eigen::Isometry3d
makePose (const Eigen::Vector3d& translation,
          double angle = 0.0,
          const Eigen::Vector3d& axis = Eigen::Vector3d::UnitY())
{
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::AngleAxisd (angle, axis.normalized()).toRotationMatrix();
  pose.translation() = translation;
  return pose;
}

/** An infinite table plane facing the camera (normal towards -z of the camera) at depth z. */
inline TablePlane::Ptr
makeFacingPlane ()
{
  auto plane = std::make_shared<TablePlane> (0.5, 0.5);
  plane->setTexture (makeCheckerboardTexture (
      8, 8, 16, cv::Vec3b (30, 30, 30), cv::Vec3b (220, 220, 220)));
  return plane;
}

/** Pose of a plane (model z = 0, normal +z) facing the camera at depth z: model +z -> camera -z.
  */
inline Eigen::Isometry3d
facingPlanePose (double z)
{
  return makePose (Eigen::Vector3d (0.0, 0.0, z), M_PI, Eigen::Vector3d::UnitX());
}

} // namespace test
} // namespace simulation
} // namespace mid
