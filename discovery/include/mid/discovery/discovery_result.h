#pragma once

#include <mid/features/keypoint_types.h>
#include <mid/registration/object_model.h>
#include <mid/segmentation/model_size.h>

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
  /** \brief The box each object's copies occupy on the table, one per model in the order of
    * `models`, in the final model frames (not in the paper): ModelSize::valid when at least one
    * copy was measured (a surface grown from its keypoints, stopped at creases and depth steps,
    * off the support plane), ModelSize::agreeing how many copies agree on it. A copy joined
    * with a touching neighbour, or partly hidden, measures too large or too small; the size
    * most copies agree on is taken, so one measured copy alone is the least sure. All invalid
    * for a frame without a support plane or without its organized cloud.
    */
  ModelSizes model_sizes;
  /** \brief Milliseconds per stage, in pipeline order: features, matching, triplets,
    * clustering, verification, modeling, detection, leftovers; then total.
    */
  std::vector<std::pair<std::string, double>> timing_ms;
};

/** \brief The box of a result's model `m` (DiscoveryResult::model_sizes), or nullptr when the
  * result holds no boxes (not one per model) or there is no model `m`: the one rule of every
  * output that writes or draws the boxes (result and model files, overlay, 3D view).
  */
inline const ModelSize*
modelBox (const DiscoveryResult& result, std::size_t m)
{
  return result.model_sizes.size() == result.models.size() && m < result.models.size()
             ? &result.model_sizes[m]
             : nullptr;
}

} // namespace mid
