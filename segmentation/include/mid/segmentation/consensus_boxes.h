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
  * both. The model's other copies do not have that neighbour in the same place. So every
  * measured copy's surface (every second row and column of it) is brought into the model frame
  * by its instance's pose. A pixel is shared when another copy's surface lies within `radius`
  * of it there; the shared pixels within `radius` of the copy's own unshared ones go too, as
  * the neighbour is shared up to `radius` past the other copies' edges. A box is fitted to the
  * pixels left: the copy without the neighbour. Where a copy's own surface is not shared (a
  * part the others do not see, hidden or seen from another side) the box loses that part and
  * a band of `radius` around it; a neighbour that reaches less than `radius` past every other
  * copy's edge stays in. So the radius must exceed how far the copies' poses and views of one
  * surface disagree, and stay under the width of a neighbour.
  *
  * \param[in] organized the frame (camera frame, metres; NaN where the depth is missing)
  * \param[in] plane the support plane (fitSupportPlane())
  * \param[in] model the model; its instances' poses map the model frame to the camera
  * \param[in] extents its instances' boxes (measureInstanceBoxes()), one per instance, in order
  * \param[in] radius metres, finite and > 0 (see above)
  * \param[out] consensus one box per instance, in order, its `surface` the pixels it was
  * fitted to; zero size and no surface when fewer pixels are left than fitInstanceBox() needs,
  * the instance was not measured, or the model has fewer than two measured copies
  * \return false (with a PCL_ERROR, consensus empty) if `extents` is not one box per instance,
  * `radius` is not finite and > 0, the frame is not organized, or a surface pixel lies outside
  * it or has no point
  */
bool
consensusBoxes (const pcl::PointCloud<pcl::PointXYZ>& organized,
                const Eigen::Vector4f& plane,
                const ObjectModel& model,
                const InstanceExtents& extents,
                float radius,
                InstanceExtents& consensus);

} // namespace mid
