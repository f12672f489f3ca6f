#pragma once

#include <mid/features/keypoint_types.h>
#include <mid/registration/object_model.h>

#include <vector>

namespace mid {

/** \brief The keypoints around every instance of some models: for each model, for each of its
  * instances, its region (sorted keypoint indices).
  *
  * The region of an instance holds the keypoints it observes (a keypoint several instances
  * observe belongs to the last of them, in model order), and the free keypoints (observed by no
  * instance) that lie within `margin` of the box of its model's landmarks (computeLandmarkBox())
  * placed by its pose, and nearer to that box than to the box of any other instance; a free
  * keypoint at the same distance from two boxes belongs to none. So regions never share a
  * keypoint, and the free keypoints between two touching copies go to the nearer one. A model
  * with fewer than 3 landmarks has no box: its instances' regions hold only what they observe;
  * an instance whose pose is not finite takes no free keypoint and keeps none from another.
  * RegionModelMerger searches the regions of two models' instances for each other.
  * \param[in] keypoints the frame's keypoints, which the instances index (not checked)
  * \param[in] models the models
  * \param[in] margin how far a region reaches beyond its box (metres)
  * \return regions[m][i]: the region of instance i of models[m]
  */
std::vector<std::vector<pcl::Indices>>
computeInstanceRegions (const KeypointCloud& keypoints,
                        const ObjectModels& models,
                        float margin);

} // namespace mid
