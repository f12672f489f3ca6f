#pragma once

#include <mid/registration/object_model.h>
#include <mid/segmentation/model_size.h>

#include <Eigen/Core>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

namespace mid {

/** \brief The boxes of a model's copies measured on what the copies agree on (not in the
  * paper).
  *
  * In a pile, the surface grown from a copy's keypoints (growInstanceSurfaces()) runs on over
  * a neighbour of its height lying flush with it, and the copy's box (fitInstanceBox()) holds
  * both. The model's other copies do not have that neighbour in the same place. So each copy's
  * surface is brought into the model frame by its instance's pose, and only the pixels that
  * lie within `radius` of another copy's surface there are kept: a box fitted to those holds
  * the copy alone. A copy whose part the others do not see (hidden, or seen from another side)
  * gives a box of the part they share, smaller than the copy.
  *
  * \param[in] organized the frame (camera frame, metres; NaN where the depth is missing)
  * \param[in] plane the support plane (fitSupportPlane())
  * \param[in] model the model; its instances' poses map the model frame to the camera
  * \param[in] extents its instances' boxes (measureInstanceBoxes()), one per instance, in order
  * \param[in] radius how near another copy's surface a pixel must lie to be kept (metres, > 0)
  * \param[out] consensus one box per instance, in order: fitted to its kept pixels, or zero
  * size and no surface when fewer than fitInstanceBox() needs are kept, the instance was not
  * measured, or the model has fewer than two measured copies
  * \return false (with a PCL_ERROR, consensus empty) if `extents` is not one box per instance,
  * `radius` is not > 0, or a surface pixel lies outside the frame or has no point
  */
bool
consensusBoxes (const pcl::PointCloud<pcl::PointXYZ>& organized,
                const Eigen::Vector4f& plane,
                const ObjectModel& model,
                const InstanceExtents& extents,
                float radius,
                InstanceExtents& consensus);

} // namespace mid
