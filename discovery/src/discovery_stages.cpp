#include "frame_stages.h"
#include "model_stages.h"
#include "peer_grouping.h"
#include "round_stages.h"
#include "stage_tools.h"

#include <mid/discovery/discovery_stages.h>
#include <mid/features/self_matcher.h>
#include <mid/registration/correspondence_rejection_ppf_triplet.h>
#include <mid/registration/multi_instance_model_builder.h>
#include <mid/segmentation/photometric_verification.h>
#include <mid/segmentation/transformation_space_clustering.h>

#include <pcl/common/time.h>
#include <pcl/console/print.h>

#include <memory>
#include <string>

namespace mid {

namespace detail {

namespace {

/** Ours: the PPF triplet rejector, then DBSCAN in transformation space (`surface` lets it
  * orient anchorless half turns; unset when its cloud is null).
  */
bool
groupWithTriplets (const DiscoveryParameters& p,
                   const KeypointSurface& surface,
                   DiscoveryResult& result,
                   TripletClusters& clusters)
{
  pcl::StopWatch watch;
  CorrespondenceRejectorPPFTriplet rejector;
  rejector.setInputSource (result.keypoints);
  rejector.setMaxDistanceDifference (p.ppf_distance);
  rejector.setMaxAngleDifference (p.ppf_angle);
  rejector.setMinEdgeLength (p.min_edge_length);
  rejector.setMaxEdgeLength (p.max_edge_length);
  rejector.setMinTriangleAngle (p.min_triangle_angle);
  rejector.setOverlapDistance (p.overlap_distance);
  rejector.setMaxTripletsPerKeypoint (p.triplets_per_keypoint);
  rejector.setMaxTriplets (p.max_triplets);
  pcl::Correspondences remaining;
  if (!result.matches.empty())
    rejector.getRemainingCorrespondences (result.matches, remaining);
  auto triplets = std::make_shared<const TripletMatches> (rejector.getTripletMatches());
  result.triplets = triplets->size();
  result.timing_ms.emplace_back ("triplets", watch.getTime());

  watch.reset();
  TransformationSpaceClustering clustering;
  clustering.setInputCloud (result.keypoints);
  clustering.setSceneCloud (result.keypoints);
  clustering.setInputTriplets (triplets);
  clustering.setClusterDistance (p.cluster_distance);
  clustering.setMinClusterSize (p.min_cluster_size);
  clustering.setSplitChains (p.split_chains);
  clustering.setSplitCompounds (p.split_compounds);
  clustering.setKeypointSurface (surface);
  std::vector<pcl::Correspondences> groups;
  if (!triplets->empty())
    clustering.cluster (groups); // PCL's void interface: a refusal leaves no clusters
  clusters = clustering.getClusters();
  result.clusters = clusters.size();
  result.timing_ms.emplace_back ("clustering", watch.getTime());
  return true;
}

/** The photometric verification of the clusters (DiscoveryParameters::verify_clusters), when
  * the frame and its grey levels are known and a pinhole camera fits the frame.
  */
bool
verifyClusters (const DiscoveryParameters& p,
                const KeypointSurface& surface,
                DiscoveryResult& result,
                TripletClusters& clusters)
{
  pcl::StopWatch watch;
  result.rejected_clusters = 0;
  // Without a pinhole camera (frameSurface() has warned) the clusters are not verified.
  if (p.verify_clusters && canCompareLooks (surface) && !clusters.empty()) {
    TripletClusters verified;
    if (!makeVerification (p, surface, p.min_photometric_correlation)
             .filter (clusters, verified))
      return false;
    result.rejected_clusters = clusters.size() - verified.size();
    clusters.swap (verified);
  }
  result.timing_ms.emplace_back ("verification", watch.getTime());
  return true;
}

} // namespace

bool
runStages (const DiscoveryParameters& p,
           DiscoveryResult& result,
           const pcl::PointCloud<pcl::PointNormal>::ConstPtr& surface,
           const KeypointSurface& frame)
{
  if (!result.keypoints || !result.descriptors) {
    PCL_ERROR ("[mid::discoverFromKeypoints] Keypoints and descriptors must be set.\n");
    return false;
  }
  std::string problem;
  if (!validateDiscoveryParameters (p, problem)) {
    PCL_ERROR ("[mid::discoverFromKeypoints] Invalid parameter: %s.\n",
               problem.c_str());
    return false;
  }
  KeypointSurface keypoint_surface = frame;
  keypoint_surface.keypoint_pixels.clear();
  if (const auto& organized = frame.organized) {
    keypoint_surface.keypoint_pixels = pixelIndices (result.image_keypoints);
    if (!isValidKeypointSurface (keypoint_surface, result.keypoints->size())) {
      PCL_ERROR (
          "[mid::discoverFromKeypoints] The organized frame (%u x %u) does not hold "
          "the pixels of the %zu keypoints (%zu image keypoints given).\n",
          organized->width,
          organized->height,
          result.keypoints->size(),
          result.image_keypoints.size());
      return false;
    }
  }
  pcl::StopWatch watch;
  SelfMatcher matcher;
  matcher.setInputKeypoints (result.keypoints);
  matcher.setInputDescriptors (result.descriptors);
  matcher.setMaxDescriptorDistance (p.max_descriptor_distance);
  matcher.setMinKeypointDistance (p.min_keypoint_distance);
  matcher.setMaxDistanceRatio (p.max_distance_ratio);
  matcher.setMaxMatchesPerKeypoint (p.matches_per_keypoint);
  matcher.setMutualCheck (p.mutual_check);
  if (!matcher.match (result.matches))
    return false;
  result.timing_ms.emplace_back ("matching", watch.getTime());

  auto clusters = std::make_shared<TripletClusters>();
  if (p.grouping == Grouping::triplets) {
    if (!groupWithTriplets (p, keypoint_surface, result, *clusters))
      return false;
  }
  else {
    result.timing_ms.emplace_back ("triplets", 0.0);
    watch.reset();
    if (!groupWithPeer (p, result.keypoints, surface, result.matches, *clusters))
      return false;
    result.clusters = clusters->size();
    result.timing_ms.emplace_back ("clustering", watch.getTime());
  }
  if (!verifyClusters (p, keypoint_surface, result, *clusters))
    return false;

  watch.reset();
  MultiInstanceModelBuilder builder;
  builder.setInputCloud (result.keypoints);
  builder.setInputDescriptors (result.descriptors);
  builder.setClusters (std::const_pointer_cast<const TripletClusters> (clusters));
  builder.setRefinementIterations (p.refinement_iterations);
  builder.setDuplicateThresholds (p.duplicate_angle, p.duplicate_distance);
  builder.setLinkTolerance (p.link_tolerance);
  if (!builder.compute (result.models))
    return false;
  result.timing_ms.emplace_back ("modeling", watch.getTime());

  watch.reset();
  if (p.merge_models &&
      !mergeMatchingModels (p, *result.keypoints, result.models, 0, keypoint_surface))
    return false;
  if (p.resolve_overlaps)
    resolveOverlaps (p, *result.keypoints, result.models);
  if (p.merge_through_regions && !mergeThroughRegions (p, keypoint_surface, result))
    return false;
  if (p.detect_additional_instances &&
      !detectAdditionalInstances (p, keypoint_surface, result))
    return false;
  if (!searchGuidedInstances (p, keypoint_surface, result))
    return false;
  if (p.resolve_overlaps)
    resolveOverlaps (p, *result.keypoints, result.models);
  if (!splitByAppearance (p, keypoint_surface, result))
    return false;
  result.timing_ms.emplace_back ("detection", watch.getTime());

  watch.reset();
  if (p.discover_leftovers && !discoverLeftovers (p, surface, keypoint_surface, result))
    return false;
  result.timing_ms.emplace_back ("leftovers", watch.getTime());
  return discoverFromPatches (p, keypoint_surface, result);
}

} // namespace detail

bool
discoverFromKeypoints (const DiscoveryParameters& p,
                       DiscoveryResult& result,
                       const pcl::PointCloud<pcl::PointNormal>::ConstPtr& surface,
                       const pcl::PointCloud<pcl::PointXYZRGB>::ConstPtr& organized)
{
  const std::size_t timed = result.timing_ms.size();
  const KeypointSurface frame = detail::frameSurface (p, organized);
  detail::FramePlane plane;
  if (detail::runStages (p, result, surface, frame) &&
      detail::searchFromBoxes (p, frame, plane, result) &&
      detail::refineOnSurface (p, frame, result) &&
      detail::splitBySize (p, frame, plane, result) &&
      detail::mergeBySize (p, frame, plane, result) &&
      detail::pruneOutsideBoxes (p, frame, plane, result) &&
      detail::removeRepeatedPrints (p, frame, plane, result) &&
      detail::searchBySize (p, frame, plane, result) &&
      detail::removeInterpenetrating (p, frame, plane, result) &&
      detail::removeDisagreeingSizes (p, frame, plane, result) &&
      detail::resolveBoxTurns (p, frame, plane, result) &&
      detail::removeSupportPrints (p, frame, plane, result) &&
      detail::pruneObservations (p, result)) {
    // Merges add landmarks in the frame of the model they join: every model is centred again,
    // before its box is measured in that frame.
    for (auto& model : result.models)
      centerModelFrame (model);
    if (detail::measureObjectBoxes (p, frame, plane, result))
      return true;
  }
  // No partial output: the stages' results go, the given keypoints and descriptors stay.
  result.matches.clear();
  result.triplets = result.clusters = result.rejected_clusters = 0;
  result.models.clear();
  result.model_sizes.clear();
  result.timing_ms.resize (timed);
  return false;
}

} // namespace mid
