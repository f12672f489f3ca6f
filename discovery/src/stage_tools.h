#pragma once

// The building blocks the discovery pipeline's stages share: detectors, look checks and
// guided searches with the pipeline's parameters, and the bookkeeping of instances.

#include <mid/discovery/discovery_parameters.h>
#include <mid/discovery/discovery_result.h>
#include <mid/registration/model_instance_detector.h>
#include <mid/registration/triplet_cluster.h>
#include <mid/segmentation/guided_instance_search.h>
#include <mid/segmentation/photometric_verification.h>
#include <mid/segmentation/surface_gap.h>

#include <memory>
#include <utility>
#include <vector>

namespace mid {
namespace detail {

/** A detector for one model's instances among the frame's keypoints, with the pipeline's
  * RANSAC parameters.
  */
ModelInstanceDetector
makeDetector (const DiscoveryParameters& p,
              const std::shared_ptr<const ObjectModel>& model);

/** A detector of `model` (null: set later) among another model's landmarks, with the
  * pipeline's RANSAC parameters, at least `min_inliers` inliers and no test of the inliers'
  * spread off a line (DiscoveryParameters::min_inlier_spread is the frame's detection's).
  */
ModelInstanceDetector
makeModelMatcher (const DiscoveryParameters& p,
                  const std::shared_ptr<const ObjectModel>& model,
                  std::size_t min_inliers);

/** Model `b` seen as a frame of keypoints: one point per descriptor, at its landmark. */
void
modelAsKeypoints (const ObjectModel& b, KeypointCloud& keypoints);

/** Keep one instance per physical object, merging models that share one (see
  * DiscoveryParameters::resolve_overlaps), and drop models left with a single instance.
  */
void
resolveOverlaps (const DiscoveryParameters& p,
                 const KeypointCloud& frame,
                 ObjectModels& models);

/** The photometric verification on `surface` with the pipeline's radius, depth tolerance and
  * largest chromaticity differences (all colours and the vivid ones), and the given minimum
  * correlation.
  */
PhotometricVerification
makeVerification (const DiscoveryParameters& p,
                  const KeypointSurface& surface,
                  float min_correlation);

/** True if the frame lets PhotometricVerification compare surfaces: its organized points, grey
  * levels and projection are known.
  */
bool
canCompareLooks (const KeypointSurface& surface);

/** The pair of copies, one of `as` and one of `bs`, that observe the most pairs of `same`
  * landmarks (a landmark of the model of `as`, one of the model of `bs`), as a cluster linking
  * the copy of `as` to the copy of `bs` on the keypoints they observe of those pairs;
  * `b_to_a` maps the frame of the model of `bs` into that of `as`. No correspondences if no
  * two copies observe a pair.
  */
TripletCluster
bestCopyLink (const ModelInstances& as,
              const ModelInstances& bs,
              const std::vector<std::pair<int, int>>& same,
              const Eigen::Matrix4f& b_to_a);

/** True if copies must pass the look check to join a model (DiscoveryParameters::verify_joins)
  * and `link`, between a copy of the model and the copy that would join, fails it.
  */
bool
copiesLookApart (const DiscoveryParameters& p,
                 const KeypointSurface& surface,
                 const TripletCluster& link);

/** Add the instances found of `model` to it (addInstance()), and the unconfirmed copies
  * (GuidedInstanceSearch::search()) with landmarks of their own (addInstanceOfKeypoints()), and
  * refine it if there were any.
  */
void
addFoundInstances (const DiscoveryParameters& p,
                   const DiscoveryResult& result,
                   const ModelInstances& found,
                   ObjectModel& model,
                   const ModelInstances& unconfirmed = {});

/** Marks the keypoints an instance observes, and those within `margin` of the box of its
  * model's landmarks placed by its pose (all of them where boxes overlap).
  */
void
markInstances (const KeypointCloud& keypoints,
               const ObjectModels& models,
               float margin,
               std::vector<bool>& taken);

/** True if the guided search can run: the frame, its grey levels and projection, and one
  * image keypoint per keypoint.
  */
bool
canSearchGuided (const KeypointSurface& surface, const DiscoveryResult& result);

/** The guided search on the frame's keypoints with the pipeline's settings. */
GuidedInstanceSearch
makeGuidedSearch (const DiscoveryParameters& p,
                  const KeypointSurface& surface,
                  const DiscoveryResult& result);

} // namespace detail
} // namespace mid
