#pragma once

#include <mid/features/keypoint_types.h>
#include <mid/registration/object_model.h>

#include <pcl/correspondence.h>

#include <string>
#include <utility>
#include <vector>

namespace mid {

/** \brief Everything one run of MultiInstanceDiscovery found in a frame. */
struct DiscoveryResult
{
  /** \brief The frame's keypoints (xyz in metres + normal), descriptors and image positions, in
    * one order.
    */
  ///@{
  KeypointCloud::Ptr keypoints;
  SIFTDescriptorCloud::Ptr descriptors;
  ImageKeypoints image_keypoints;
  ///@}
  /** \brief The self-matches (indices into keypoints), and how many triplets and clusters they
    * gave.
    */
  ///@{
  pcl::Correspondences matches;
  std::size_t triplets = 0;
  std::size_t clusters = 0;
  ///@}
  /** \brief How many clusters the photometric verification rejected (not in the paper;
    * DiscoveryParameters::verify_clusters), in both rounds (`clusters` counts the first
    * round's only). The model builder gets the others.
    */
  std::size_t rejected_clusters = 0;
  /** \brief The discovered objects, each with its instances (poses, keypoints). */
  ObjectModels models;
  /** \brief Milliseconds per stage, in pipeline order: features, matching, triplets,
    * clustering, verification, modeling, detection, leftovers; then total.
    */
  std::vector<std::pair<std::string, double>> timing_ms;
};

} // namespace mid
