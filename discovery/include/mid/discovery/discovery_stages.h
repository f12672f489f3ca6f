#pragma once

#include <mid/discovery/discovery_parameters.h>
#include <mid/discovery/discovery_result.h>
#include <mid/segmentation/surface_gap.h>

namespace mid {

/** \brief The stages of MultiInstanceDiscovery after keypoint extraction: self-matching,
  * triplets, clustering, model building and additional instance detection. For users who bring
  * their own keypoints and descriptors (result.keypoints / result.descriptors must be set).
  * Appends the stages' times to result.timing_ms. With a peer grouping (PCL's classes) the
  * "triplets" stage is empty and "clustering" times the peer.
  * \param[in] parameters the parameters
  * \param[in,out] result keypoints and descriptors in; matches, counts, models, their boxes
  * on the table (DiscoveryResult::model_sizes, measured with `organized` only) and times out;
  * every model's frame is centred on its landmarks (centerModelFrame())
  * \param[in] surface the frame's points with normals; needed by Grouping::hough3d only
  * \param[in] organized the organized colour frame the keypoints were found in, with
  * result.image_keypoints giving their pixels (ImageKeypoint::pixel_index); optional: it lets
  * the clustering orient a half turn between two copies lying apart that no third copy
  * anchors (TransformationSpaceClustering::setKeypointSurface()), and the photometric
  * verification check every cluster (DiscoveryParameters::verify_clusters)
  * \return false (with a PCL_ERROR) if a stage refuses its input or parameters, or if
  * `organized` is given but result.image_keypoints do not give a pixel inside it for every
  * keypoint; then result's matches, counts, models and boxes are empty and timing_ms is as it
  * came in (keypoints, descriptors and image keypoints stay)
  */
bool
discoverFromKeypoints (
    const DiscoveryParameters& parameters,
    DiscoveryResult& result,
    const pcl::PointCloud<pcl::PointNormal>::ConstPtr& surface = nullptr,
    const pcl::PointCloud<pcl::PointXYZRGB>::ConstPtr& organized = nullptr);

/** \brief The pipeline's model merging (DiscoveryParameters::merge_models): every model j is
  * searched, by descriptor matching and RANSAC (ModelInstanceDetector), among the landmarks of
  * every model i before it; with enough inliers (DiscoveryParameters::min_merge_inliers) j joins
  * i (mergeModel()) and i is refined again on the frame's keypoints.
  * \param[in] parameters the RANSAC and merge parameters
  * \param[in] frame the keypoints the models' instances refer to
  * \param[in,out] models the models; merged ones are removed
  * \param[in] first_new only pairs with at least one model from this index on are compared
  * (the models before it were compared with each other already); 0 compares every pair
  * \param[in] surface the frame's keypoint surface, with a pixel for each of `frame`'s
  * keypoints; when it holds grey levels and a projection, a merge also needs the two copies
  * that observe the most of the matched landmarks to look alike
  * (DiscoveryParameters::verify_joins); empty (the default): no such check
  * \return false (with a PCL_ERROR, models unchanged) if a parameter is out of its range
  * (validateDiscoveryParameters()), `surface` has an organized frame but no pixel inside it
  * for some keypoint of `frame`, or the detector refuses a model
  */
bool
mergeMatchingModels (const DiscoveryParameters& parameters,
                     const KeypointCloud& frame,
                     ObjectModels& models,
                     std::size_t first_new = 0,
                     const KeypointSurface& surface = KeypointSurface());

} // namespace mid
