#pragma once

#include <Eigen/Core>
#include <Eigen/StdVector>

#include <string>
#include <vector>

namespace mid {
namespace evaluation {

/** \brief One instance as our result JSON reports it. */
struct DetectedInstance
{
  /** \brief Model -> camera pose, metres. */
  Eigen::Matrix4f pose = Eigen::Matrix4f::Identity();
  /** \brief Pixel positions (u column, v row) of its keypoints. */
  std::vector<Eigen::Vector2f, Eigen::aligned_allocator<Eigen::Vector2f>> keypoints;
  /** \brief Its "group": instances of one object in one group have relative poses that rest
    * on their print (mid::sharedLandmarkGroups()); -1 when the result gives none.
    */
  int group = -1;

  EIGEN_MAKE_ALIGNED_OPERATOR_NEW
};

/** \brief One discovered object: its instances, and the size of the box its copies occupy on
  * the table.
  */
struct DetectedObject
{
  /** \brief Its instances, in the order of the JSON. */
  std::vector<DetectedInstance, Eigen::aligned_allocator<DetectedInstance>> instances;
  /** \brief box.size: edges ascending (metres); zero when the result gives no box. */
  Eigen::Vector3f box_size = Eigen::Vector3f::Zero();
  /** \brief box.copies: how many measured copies agree on that size; 0 without a box. */
  int box_copies = 0;
};

/** \brief What a result JSON (doc/result_format.md) says about one frame. */
struct DetectionResult
{
  /** \brief The discovered objects, in the order of the JSON. */
  std::vector<DetectedObject> objects;
  /** \brief timing_ms.total, or -1 if absent. */
  double total_ms = -1.0;
  /** \brief timing_ms.features, or -1 if absent. */
  double features_ms = -1.0;
  /** \brief timing_ms.triplets + timing_ms.clustering: the grouping stage that PCL's
    * correspondence grouping replaces in a peer run, or -1 if either is absent.
    */
  double grouping_ms = -1.0;
};

/** \brief Read a result JSON written by pcl_multi_instance_discovery or _detect.
  * \param[in] path the file
  * \param[out] result its objects, instances and timings; cleared on failure
  * \return false (with a PCL_ERROR) if the file is missing, not JSON, of another format or of a
  * version this build does not read
  */
bool
readDetectionResult (const std::string& path, DetectionResult& result);

} // namespace evaluation
} // namespace mid
