#pragma once

#include <mid/features/keypoint_types.h>
#include <mid/registration/object_model.h>
#include <mid/segmentation/instance_extent.h>
#include <mid/segmentation/model_size.h>

#include <Eigen/Core>
#include <Eigen/StdVector>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstddef>
#include <vector>

namespace mid {
namespace detail {

// The objects on the table that no instance observes, which SizeInstanceSearch measures: how
// they grow from the keypoints, which boxes they occupy, and what lies around them.

/** \brief How far inside an object's box a found copy's keypoint must lie to rule the object
  * out (metres): touching copies share a face, and their keypoints lie on it.
  */
constexpr float kBoxMargin = 0.005f;

/** \brief Pixels around an object's surface (within this many of it) that tell what it stands
  * on, leans on or is hidden by.
  */
constexpr int kRingPixels = 4;

/** \brief How much nearer the camera than an object's outline a point around it must lie to
  * hide part of the object (metres; occludedOutline()).
  */
constexpr float kOccluderStep = 0.01f;

/** \brief The axis of the box that stands up: the one closest to the plane's normal. */
int
upAxis (const InstanceExtent& extent, const Eigen::Vector4f& plane);

/** \brief A box in the camera frame (camera -> box frame, and half its edges), and the test of
  * the points inside it.
  */
struct OrientedBox
{
  Eigen::Matrix4f to_box = Eigen::Matrix4f::Identity();
  Eigen::Array3f half = Eigen::Array3f::Zero();

  /** \brief True if `point` lies inside the box grown by `margin` (shrunk if negative). */
  bool
  holds (const Eigen::Vector3f& point, float margin) const
  {
    const Eigen::Vector3f local =
        to_box.topLeftCorner<3, 3>() * point + to_box.topRightCorner<3, 1>();
    return (local.array().abs() < half + margin).all();
  }

  EIGEN_MAKE_ALIGNED_OPERATOR_NEW
};

using OrientedBoxes = std::vector<OrientedBox, Eigen::aligned_allocator<OrientedBox>>;

/** \brief The boxes of the found copies of the models with a size. */
OrientedBoxes
foundCopyBoxes (const ObjectModels& models, const ModelSizes& sizes);

/** \brief `organized` without the points inside `boxes` (NaN there): a copy touching a found
  * one, flush, then grows over its own surface alone instead of over the found copy's too.
  */
pcl::PointCloud<pcl::PointXYZ>
withoutFoundCopies (const pcl::PointCloud<pcl::PointXYZ>& organized,
                    const OrientedBoxes& boxes);

/** \brief True if one of `keypoints` marked in `observed` lies inside `box`, farther than
  * `margin` from its faces: an object whose box holds a found copy's keypoint is no other
  * copy.
  */
bool
boxHoldsObserved (const InstanceExtent& box,
                  const KeypointCloud& keypoints,
                  const std::vector<bool>& observed,
                  float margin);

/** \brief Share of the pixels around an object's surface (within kRingPixels of it, not on
  * it) that hold a point off the support plane (farther than `tolerance` from it) and outside
  * the object's box: where the object leans on, lies under or stands beside something else.
  * Missing depth (the shadow beside an object) counts as free. 1 if no pixel lies around.
  */
float
surroundedShare (const pcl::PointCloud<pcl::PointXYZ>& organized,
                 const Eigen::Vector4f& plane,
                 const InstanceExtent& object,
                 float tolerance);

/** \brief An object on the table that no instance observes: its surface, its keypoints and
  * its box.
  */
struct FreeObject
{
  pcl::Indices pixels;
  pcl::Indices keypoints;
  InstanceExtent extent;

  EIGEN_MAKE_ALIGNED_OPERATOR_NEW
};

using FreeObjects = std::vector<FreeObject, Eigen::aligned_allocator<FreeObject>>;

/** \brief The seeds the objects grow from: every instance (its keypoints' pixels), then every
  * keypoint no instance observes.
  */
struct ObjectSeeds
{
  std::vector<pcl::Indices> pixels;
  std::size_t instances = 0;  ///< the first seeds, one per instance
  pcl::Indices free;          ///< the keypoint of each seed after them
  std::vector<bool> observed; ///< by keypoint: an instance observes it
};

/** \brief The seeds of the instances of `models` and of the keypoints they leave free. */
ObjectSeeds
objectSeeds (const ObjectModels& models, const pcl::Indices& keypoint_pixels);

/** \brief How the surfaces grow (growInstanceSurfaces()). */
struct Growth
{
  float max_step, max_radius, plane_tolerance;
};

/** \brief The objects of free keypoints alone (at least `min_keypoints`) whose surfaces, grown
  * in `cloud` (`organized` or a part of it) and joined where they touch along a border, give
  * a box that holds no instance's keypoint; those whose box does hold one go to
  * `boxing_found`, if given. False if the surfaces could not grow (PCL_ERROR printed).
  */
bool
freeObjects (const pcl::PointCloud<pcl::PointXYZ>& cloud,
             const pcl::PointCloud<pcl::PointXYZ>& organized,
             const Eigen::Vector4f& plane,
             const ObjectSeeds& seeds,
             const KeypointCloud& keypoints,
             const Growth& growth,
             int min_keypoints,
             FreeObjects& objects,
             FreeObjects* boxing_found = nullptr);

} // namespace detail
} // namespace mid
