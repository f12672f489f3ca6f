#include "peer_grouping.h"

#include <mid/discovery/discovery_stages.h>
#include <mid/features/self_matcher.h>
#include <mid/registration/correspondence_rejection_ppf_triplet.h>
#include <mid/registration/instance_overlap.h>
#include <mid/registration/landmark_box.h>
#include <mid/registration/model_instance_detector.h>
#include <mid/registration/model_merging.h>
#include <mid/registration/model_refinement.h>
#include <mid/registration/multi_instance_model_builder.h>
#include <mid/registration/observation_pruning.h>
#include <mid/registration/region_model_merger.h>
#include <mid/segmentation/appearance_model_splitter.h>
#include <mid/segmentation/frame_pinhole.h>
#include <mid/segmentation/guided_instance_search.h>
#include <mid/segmentation/instance_extent.h>
#include <mid/segmentation/interpenetration_filter.h>
#include <mid/segmentation/keypoint_patch.h>
#include <mid/segmentation/model_box_extension.h>
#include <mid/segmentation/model_size_merger.h>
#include <mid/segmentation/model_size_splitter.h>
#include <mid/segmentation/photometric_verification.h>
#include <mid/segmentation/repeated_print_filter.h>
#include <mid/segmentation/size_instance_search.h>
#include <mid/segmentation/surface_gap.h>
#include <mid/segmentation/surface_pose_refinement.h>
#include <mid/segmentation/transformation_space_clustering.h>

#include <pcl/common/io.h>
#include <pcl/common/time.h>
#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <set>
#include <string>

namespace mid {

namespace {

/** A detector for one model with the pipeline's RANSAC parameters. */
ModelInstanceDetector
makeDetector (const DiscoveryParameters& p,
              const std::shared_ptr<const ObjectModel>& model)
{
  ModelInstanceDetector detector;
  detector.setModel (model);
  detector.setMaxDescriptorDistance (p.max_descriptor_distance);
  detector.setInlierThreshold (p.inlier_threshold);
  detector.setMinInliers (p.min_inliers);
  detector.setMinInlierRatio (p.min_inlier_ratio);
  detector.setMaxIterations (p.ransac_iterations);
  detector.setSeed (p.seed);
  return detector;
}

/** Model `b` seen as a frame of keypoints: one point per descriptor, at its landmark. */
void
modelAsKeypoints (const ObjectModel& b, KeypointCloud& keypoints)
{
  keypoints.clear();
  for (const int l : b.descriptor_landmarks)
    keypoints.push_back (b.landmarks[static_cast<std::size_t> (l)]);
}

/** Inliers (descriptor matches) that merge models a and b: min_merge_inliers, or
  * merge_fraction of the smaller model's landmarks, but at least min_inliers (validated
  * parameters).
  */
std::size_t
mergeInliers (const DiscoveryParameters& p, const ObjectModel& a, const ObjectModel& b)
{
  const auto smaller =
      static_cast<double> (std::min (a.landmarks.size(), b.landmarks.size()));
  const auto share = static_cast<std::size_t> (
      std::ceil (static_cast<double> (p.merge_fraction) * smaller));
  return std::max (p.min_inliers, std::min (p.min_merge_inliers, share));
}

/** Keep one instance per physical object, merging models that share one (see
  * DiscoveryParameters::resolve_overlaps), and drop models left with a single instance.
  */
void
resolveOverlaps (const DiscoveryParameters& p,
                 const KeypointCloud& frame,
                 ObjectModels& models)
{
  if (mergeOverlappingModels (frame, models, p.duplicate_angle, p.duplicate_distance) >
      0)
    for (auto& model : models)
      refineModel (model, frame, p.refinement_iterations);
  for (auto& model : models)
    removeOverlappingInstances (frame, model);
  models.erase (std::remove_if (models.begin(),
                                models.end(),
                                [] (const ObjectModel& model) {
                                  return model.instances.size() < 2;
                                }),
                models.end());
}

/** The photometric verification on `surface` with the pipeline's radius, depth tolerance and
  * largest chromaticity difference, and the given minimum correlation.
  */
PhotometricVerification
makeVerification (const DiscoveryParameters& p,
                  const KeypointSurface& surface,
                  float min_correlation)
{
  PhotometricVerification verification;
  verification.setKeypointSurface (surface);
  verification.setRadius (p.verification_radius);
  verification.setDepthTolerance (p.verification_depth_tolerance);
  verification.setMinCorrelation (min_correlation);
  verification.setMaxChromaticityDifference (p.max_chromaticity_difference);
  return verification;
}

/** True if the frame lets PhotometricVerification compare surfaces: its organized points, grey
  * levels and projection are known.
  */
bool
canCompareLooks (const KeypointSurface& surface)
{
  return surface.organized && surface.intensity && surface.pinhole;
}

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
              const Eigen::Matrix4f& b_to_a)
{
  const auto observed = [] (const ModelInstance& instance) {
    std::map<int, pcl::index_t> keypoint_of;
    for (std::size_t o = 0; o < instance.landmarks.size(); ++o)
      keypoint_of.emplace (instance.landmarks[o], instance.keypoints[o]);
    return keypoint_of;
  };
  TripletCluster best;
  for (const auto& copy_a : as) {
    const auto in_a = observed (copy_a);
    for (const auto& copy_b : bs) {
      const auto in_b = observed (copy_b);
      TripletCluster link;
      for (const auto& [landmark_a, landmark_b] : same) {
        const auto ka = in_a.find (landmark_a);
        const auto kb = in_b.find (landmark_b);
        if (ka != in_a.end() && kb != in_b.end() && ka->second != kb->second)
          link.correspondences.emplace_back (ka->second, kb->second, 0.0f);
      }
      if (link.correspondences.size() <= best.correspondences.size())
        continue;
      for (const auto& pair : link.correspondences) {
        link.source_indices.push_back (pair.index_query);
        link.target_indices.push_back (pair.index_match);
      }
      link.transformation = copy_b.pose * b_to_a.inverse() * copy_a.pose.inverse();
      best = std::move (link);
    }
  }
  for (auto* indices : {&best.source_indices, &best.target_indices}) {
    std::sort (indices->begin(), indices->end());
    indices->erase (std::unique (indices->begin(), indices->end()), indices->end());
  }
  return best;
}

/** True if copies must pass the look check to join a model (DiscoveryParameters::verify_joins)
  * and `link`, between a copy of the model and the copy that would join, fails it.
  */
bool
copiesLookApart (const DiscoveryParameters& p,
                 const KeypointSurface& surface,
                 const TripletCluster& link)
{
  if (!p.verify_joins || !canCompareLooks (surface) || link.correspondences.empty())
    return false;
  const PhotometricVerification verification =
      makeVerification (p, surface, p.min_join_correlation);
  return verification.rejects (verification.compare (link));
}

/** Merge the models whose instances show a common surface around their landmarks
  * (RegionModelMerger), with the pipeline's RANSAC settings; when the frame can tell, only
  * through copies whose common surface looks alike (DiscoveryParameters::verify_joins).
  */
bool
mergeThroughRegions (const DiscoveryParameters& p,
                     const KeypointSurface& surface,
                     DiscoveryResult& result)
{
  ModelInstanceDetector detector = makeDetector (p, nullptr);
  detector.setMinInliers (p.min_region_merge_inliers);
  RegionModelMerger merger;
  merger.setInputKeypoints (result.keypoints);
  merger.setInputDescriptors (result.descriptors);
  merger.setDetector (detector);
  merger.setRegionMargin (p.region_margin);
  merger.setDuplicateThresholds (p.duplicate_angle, p.duplicate_distance);
  merger.setRefinementIterations (p.refinement_iterations);
  merger.setMergeCondition ([&p, &surface] (const TripletCluster& link) {
    return !copiesLookApart (p, surface, link);
  });
  return merger.merge (result.models);
}

/** Add the instances found of `model` to it (addInstance()), and refine it if there were any. */
void
addFoundInstances (const DiscoveryParameters& p,
                   const DiscoveryResult& result,
                   const ModelInstances& found,
                   ObjectModel& model)
{
  for (const auto& instance : found)
    addInstance (
        model, instance, *result.descriptors, p.duplicate_angle, p.duplicate_distance);
  if (!found.empty())
    refineModel (model, *result.keypoints, p.refinement_iterations);
}

/** Look for each model's instances among the keypoints no model uses yet; when the frame can
  * tell, an instance whose surface does not look like that of the model's copy that observes
  * most of its landmarks is not added (DiscoveryParameters::verify_joins).
  */
bool
detectAdditionalInstances (const DiscoveryParameters& p,
                           const KeypointSurface& surface,
                           DiscoveryResult& result)
{
  std::set<pcl::index_t> used;
  for (const auto& model : result.models)
    for (const auto& instance : model.instances)
      used.insert (instance.keypoints.begin(), instance.keypoints.end());
  for (auto& model : result.models) {
    auto candidates = pcl::make_shared<pcl::Indices>();
    for (std::size_t k = 0; k < result.keypoints->size(); ++k)
      if (used.count (static_cast<pcl::index_t> (k)) == 0)
        candidates->push_back (static_cast<pcl::index_t> (k));
    ModelInstanceDetector detector =
        makeDetector (p, std::make_shared<const ObjectModel> (model));
    detector.setInputKeypoints (result.keypoints);
    detector.setInputDescriptors (result.descriptors);
    detector.setCandidates (candidates);
    ModelInstances found;
    if (!detector.detect (found))
      return false;
    const auto looks_apart = [&] (const ModelInstance& instance) {
      std::vector<std::pair<int, int>> same;
      for (const int l : instance.landmarks)
        same.emplace_back (l, l);
      return copiesLookApart (
          p,
          surface,
          bestCopyLink (
              model.instances, {instance}, same, Eigen::Matrix4f::Identity()));
    };
    found.erase (std::remove_if (found.begin(), found.end(), looks_apart), found.end());
    for (const auto& instance : found)
      used.insert (instance.keypoints.begin(), instance.keypoints.end());
    addFoundInstances (p, result, found, model);
  }
  return true;
}

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
mergeMatchingModels (const DiscoveryParameters& p,
                     const KeypointCloud& frame,
                     ObjectModels& models,
                     std::size_t first_new,
                     const KeypointSurface& surface)
{
  std::string problem;
  if (!validateDiscoveryParameters (p, problem)) {
    PCL_ERROR ("[mid::mergeMatchingModels] Invalid parameter: %s.\n", problem.c_str());
    return false;
  }
  if (surface.organized && !isValidKeypointSurface (surface, frame.size())) {
    PCL_ERROR (
        "[mid::mergeMatchingModels] The keypoint surface does not give a pixel inside "
        "its frame for each of the %zu keypoints (%zu given).\n",
        frame.size(),
        surface.keypoint_pixels.size());
    return false;
  }
  for (std::size_t i = 0; i < models.size(); ++i)
    for (std::size_t j = std::max (i + 1, first_new); j < models.size();) {
      auto points = pcl::make_shared<KeypointCloud>();
      modelAsKeypoints (models[i], *points);
      auto descriptors = pcl::make_shared<SIFTDescriptorCloud> (models[i].descriptors);
      ModelInstanceDetector detector =
          makeDetector (p, std::make_shared<const ObjectModel> (models[j]));
      detector.setInputKeypoints (points);
      detector.setInputDescriptors (descriptors);
      detector.setMaxInstances (1);
      detector.setMinInliers (mergeInliers (p, models[i], models[j]));
      ModelInstances found;
      if (!detector.detect (found))
        return false;
      // found.pose maps j's frame into i's frame; mergeModel wants i -> j.
      std::vector<std::pair<int, int>> same;
      if (!found.empty())
        for (std::size_t o = 0; o < found.front().keypoints.size(); ++o)
          same.emplace_back (models[i].descriptor_landmarks[static_cast<std::size_t> (
                                 found.front().keypoints[o])],
                             found.front().landmarks[o]);
      if (found.empty() || copiesLookApart (p,
                                            surface,
                                            bestCopyLink (models[i].instances,
                                                          models[j].instances,
                                                          same,
                                                          found.front().pose))) {
        ++j;
        continue;
      }
      mergeModel (models[i],
                  models[j],
                  found.front().pose.inverse(),
                  same,
                  p.duplicate_angle,
                  p.duplicate_distance);
      refineModel (models[i], frame, p.refinement_iterations);
      models.erase (models.begin() + static_cast<std::ptrdiff_t> (j));
    }
  return true;
}

namespace {

bool
runStages (const DiscoveryParameters& p,
           DiscoveryResult& result,
           const pcl::PointCloud<pcl::PointNormal>::ConstPtr& surface,
           const KeypointSurface& frame);

/** Marks the keypoints an instance observes, and those within `margin` of the box of its
  * model's landmarks placed by its pose (all of them where boxes overlap).
  */
void
markInstances (const KeypointCloud& keypoints,
               const ObjectModels& models,
               float margin,
               std::vector<bool>& taken)
{
  for (const auto& model : models) {
    const LandmarkBox box = computeLandmarkBox (model);
    for (const auto& instance : model.instances) {
      for (const auto k : instance.keypoints)
        taken[static_cast<std::size_t> (k)] = true;
      if (!box.valid || !instance.pose.allFinite())
        continue;
      const Eigen::Affine3f to_model (instance.pose.inverse());
      for (std::size_t k = 0; k < keypoints.size(); ++k)
        if (!taken[k] &&
            box.distanceTo (to_model * keypoints[k].getVector3fMap()) <= margin)
          taken[k] = true;
    }
  }
}

/** True if the guided search can run: the frame, its grey levels and projection, and one
  * image keypoint per keypoint.
  */
bool
canSearchGuided (const KeypointSurface& surface, const DiscoveryResult& result)
{
  return canCompareLooks (surface) &&
         result.image_keypoints.size() == result.keypoints->size();
}

/** The guided search on the frame's keypoints with the pipeline's settings. */
GuidedInstanceSearch
makeGuidedSearch (const DiscoveryParameters& p,
                  const KeypointSurface& surface,
                  const DiscoveryResult& result)
{
  GuidedInstanceSearch search;
  search.setInputKeypoints (result.keypoints);
  search.setInputDescriptors (result.descriptors);
  search.setImageKeypoints (result.image_keypoints);
  search.setKeypointSurface (surface);
  search.setSeedDescriptorDistance (p.guided_seed_distance);
  search.setGuidedDescriptorDistance (p.guided_descriptor_distance);
  search.setInlierThreshold (p.inlier_threshold);
  search.setMinInliers (p.guided_min_inliers);
  search.setMinCorrelation (p.guided_min_correlation);
  search.setMaxChromaticityDifference (p.max_chromaticity_difference);
  search.setCorrelationRadius (p.verification_radius);
  search.setDepthTolerance (p.verification_depth_tolerance);
  search.setMaxHypotheses (p.guided_hypotheses);
  return search;
}

/** Look for more instances of each model from single matches
  * (DiscoveryParameters::guided_search) among the keypoints outside every instance's box and
  * not `excluded` (one flag per keypoint, or empty), when the frame, its grey levels and the
  * image keypoints are known.
  */
bool
searchGuidedInstances (const DiscoveryParameters& p,
                       const KeypointSurface& surface,
                       DiscoveryResult& result,
                       const std::vector<bool>& excluded = {})
{
  if (!p.guided_search || !canSearchGuided (surface, result) || result.models.empty())
    return true;
  GuidedInstanceSearch search = makeGuidedSearch (p, surface, result);
  for (auto& model : result.models) {
    std::vector<bool> taken = excluded;
    taken.resize (result.keypoints->size(), false);
    markInstances (*result.keypoints, result.models, p.leftover_margin, taken);
    pcl::Indices candidates;
    ModelInstances copies;
    for (std::size_t k = 0; k < taken.size(); ++k)
      if (!taken[k])
        candidates.push_back (static_cast<pcl::index_t> (k));
    for (const auto& other : result.models)
      copies.insert (copies.end(), other.instances.begin(), other.instances.end());
    search.setCandidates (candidates);
    search.setFoundInstances (copies);
    ModelInstances found;
    if (!search.search (model, found))
      return false;
    addFoundInstances (p, result, found, model);
  }
  return true;
}

/** True if `model` matches one of `models` on at least `min_inliers` RANSAC inliers. */
bool
matchesAnyModel (const DiscoveryParameters& p,
                 const ObjectModel& model,
                 const ObjectModels& models,
                 std::size_t min_inliers,
                 bool& matches)
{
  matches = false;
  const auto shared = std::make_shared<const ObjectModel> (model);
  for (const auto& other : models) {
    auto points = pcl::make_shared<KeypointCloud>();
    modelAsKeypoints (other, *points);
    ModelInstanceDetector detector = makeDetector (p, shared);
    detector.setInputKeypoints (points);
    detector.setInputDescriptors (
        pcl::make_shared<SIFTDescriptorCloud> (other.descriptors));
    detector.setMaxInstances (1);
    detector.setMinInliers (min_inliers);
    ModelInstances found;
    if (!detector.detect (found))
      return false;
    if (!found.empty()) {
      matches = true;
      return true;
    }
  }
  return true;
}

/** Models from patches of the keypoints no instance explains
  * (DiscoveryParameters::patch_discovery), when the guided search can run; times the
  * "patches" stage either way.
  */
bool
discoverFromPatches (const DiscoveryParameters& p,
                     const KeypointSurface& surface,
                     DiscoveryResult& result)
{
  pcl::StopWatch watch;
  if (p.patch_discovery && canSearchGuided (surface, result)) {
    const KeypointCloud& keypoints = *result.keypoints;
    GuidedInstanceSearch search = makeGuidedSearch (p, surface, result);
    search.setMinInliers (p.patch_min_inliers);
    search.setMinCorrelation (p.patch_min_correlation);
    search.setMaxHypotheses (p.patch_hypotheses);
    const std::size_t first_new = result.models.size();
    std::vector<bool> tried (keypoints.size(), false);
    for (std::size_t round = 0; round < p.max_patches; ++round) {
      std::vector<bool> taken (keypoints.size(), false), near (keypoints.size(), false);
      markInstances (keypoints, result.models, p.leftover_margin, taken);
      markInstances (keypoints, result.models, p.patch_margin, near);
      std::vector<bool> free (keypoints.size());
      for (std::size_t k = 0; k < keypoints.size(); ++k)
        free[k] = !near[k] && !tried[k];
      pcl::Indices patch;
      if (!densestKeypointPatch (
              keypoints, free, p.patch_radius, p.patch_min_keypoints, patch))
        return false;
      if (patch.empty())
        break;
      for (const pcl::index_t k : patch)
        tried[static_cast<std::size_t> (k)] = true;
      // Copies are looked for beyond the patch, among the keypoints no instance has.
      const Eigen::Vector3f centre =
          keypoints[static_cast<std::size_t> (patch.front())].getVector3fMap();
      pcl::Indices candidates;
      for (std::size_t k = 0; k < keypoints.size(); ++k)
        if (!taken[k] &&
            (keypoints[k].getVector3fMap() - centre).norm() >= p.patch_radius)
          candidates.push_back (static_cast<pcl::index_t> (k));
      ObjectModel model =
          modelOfKeypoints (*result.keypoints, *result.descriptors, patch);
      ModelInstances copies = model.instances;
      for (const auto& other : result.models)
        copies.insert (copies.end(), other.instances.begin(), other.instances.end());
      search.setCandidates (candidates);
      search.setFoundInstances (copies);
      ModelInstances found;
      if (!search.search (model, found))
        return false;
      if (found.empty())
        continue;
      addFoundInstances (p, result, found, model);
      bool related = false;
      if (!matchesAnyModel (p, model, result.models, p.patch_drop_inliers, related))
        return false;
      const std::size_t before = result.models.size();
      result.models.push_back (std::move (model));
      // Like another model but not merged with it: a second model of its product, or
      // another product's print; dropped.
      if (related &&
          !mergeMatchingModels (p, keypoints, result.models, before, surface))
        return false;
      if (related && result.models.size() > before)
        result.models.pop_back();
    }
    if (result.models.size() > first_new) {
      if (p.merge_models &&
          !mergeMatchingModels (p, keypoints, result.models, first_new, surface))
        return false;
      if (p.merge_through_regions && !mergeThroughRegions (p, surface, result))
        return false;
      if (p.resolve_overlaps)
        resolveOverlaps (p, keypoints, result.models);
    }
  }
  result.timing_ms.emplace_back ("patches", watch.getTime());
  return true;
}

/** Split each model whose instances fall into groups that do not look alike
  * (DiscoveryParameters::split_by_appearance), when the frame, its grey levels and the image
  * keypoints are known; each split part is refined.
  */
bool
splitByAppearance (const DiscoveryParameters& p,
                   const KeypointSurface& surface,
                   DiscoveryResult& result)
{
  if (!p.split_by_appearance || !surface.organized || !surface.intensity ||
      !surface.pinhole || result.image_keypoints.size() != result.keypoints->size() ||
      result.models.empty())
    return true;
  AppearanceModelSplitter splitter;
  splitter.setVerification (makeVerification (p, surface, p.split_min_correlation));
  ObjectModels models, parts;
  for (const auto& model : result.models) {
    if (!splitter.split (model, parts))
      return false;
    for (auto& part : parts) {
      if (parts.size() > 1)
        refineModel (part, *result.keypoints, p.refinement_iterations);
      models.push_back (std::move (part));
    }
  }
  result.models.swap (models);
  return true;
}

/** The keypoints of the frame that no instance observes and that lie farther than
  * DiscoveryParameters::leftover_margin from every instance's box, with their descriptors and
  * image keypoints; back[k] is the frame index of leftover keypoint k.
  */
void
selectLeftovers (const DiscoveryParameters& p,
                 const DiscoveryResult& result,
                 DiscoveryResult& leftovers,
                 pcl::Indices& back)
{
  std::vector<bool> taken (result.keypoints->size(), false);
  markInstances (*result.keypoints, result.models, p.leftover_margin, taken);
  const bool with_pixels = result.image_keypoints.size() == taken.size();
  leftovers = DiscoveryResult();
  leftovers.keypoints = pcl::make_shared<KeypointCloud>();
  leftovers.descriptors = pcl::make_shared<SIFTDescriptorCloud>();
  back.clear();
  for (std::size_t k = 0; k < taken.size(); ++k) {
    if (taken[k])
      continue;
    back.push_back (static_cast<pcl::index_t> (k));
    leftovers.keypoints->push_back ((*result.keypoints)[k]);
    leftovers.descriptors->push_back ((*result.descriptors)[k]);
    if (with_pixels)
      leftovers.image_keypoints.push_back (result.image_keypoints[k]);
  }
}

/** The second round on the keypoints left over (DiscoveryParameters::discover_leftovers): its
  * models join result's, merged with them where they match.
  */
bool
discoverLeftovers (const DiscoveryParameters& p,
                   const pcl::PointCloud<pcl::PointNormal>::ConstPtr& surface,
                   const KeypointSurface& keypoint_surface,
                   DiscoveryResult& result)
{
  DiscoveryResult leftovers;
  pcl::Indices back;
  selectLeftovers (p, result, leftovers, back);
  DiscoveryParameters second = p;
  second.discover_leftovers = false;
  second.patch_discovery = false;
  second.max_descriptor_distance = p.leftover_descriptor_distance;
  if (!runStages (second, leftovers, surface, keypoint_surface))
    return false;
  result.rejected_clusters += leftovers.rejected_clusters;
  if (leftovers.models.empty())
    return true;
  const std::size_t first_new = result.models.size();
  for (auto& model : leftovers.models) {
    for (auto& instance : model.instances)
      for (auto& k : instance.keypoints)
        k = back[static_cast<std::size_t> (k)];
    result.models.push_back (std::move (model));
  }
  if (p.merge_models &&
      !mergeMatchingModels (
          p, *result.keypoints, result.models, first_new, keypoint_surface))
    return false;
  if (p.resolve_overlaps)
    resolveOverlaps (p, *result.keypoints, result.models);
  return true;
}

/** The points of an organized colour frame, and, when a stage compares looks or refines on
  * the depth (the cluster verification, the look check of what joins a model, the guided
  * search, the patches, the appearance split, the surface refinement), its grey levels, colours
  * and projection (no keypoints yet); empty for none. Warns, once for both rounds, when no pinhole
  * camera fits the frame: those stages then do not run.
  */
KeypointSurface
frameSurface (const DiscoveryParameters& p,
              const pcl::PointCloud<pcl::PointXYZRGB>::ConstPtr& organized)
{
  KeypointSurface frame;
  if (!organized)
    return frame;
  auto points = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  pcl::copyPointCloud (*organized, *points);
  frame.organized = points;
  if (!p.verify_clusters && !p.verify_joins && !p.guided_search && !p.patch_discovery &&
      !p.split_by_appearance && !p.surface_refinement)
    return frame;
  frame.intensity =
      std::make_shared<const std::vector<float>> (greyLevels (*organized));
  frame.chromaticity =
      std::make_shared<const std::vector<Chromaticity>> (chromaticities (*organized));
  FramePinhole pinhole;
  if (fitFramePinhole (*points, pinhole))
    frame.pinhole = std::make_shared<const FramePinhole> (pinhole);
  else
    PCL_WARN (
        "[mid::discoverFromKeypoints] No pinhole camera fits the organized frame "
        "(not in its camera's coordinates?): no cluster verification, look check "
        "of what joins a model, guided instance search, patches, appearance split "
        "or surface refinement.\n");
  return frame;
}

/** Refine every model's instance poses on the frame's depth
  * (DiscoveryParameters::surface_refinement), when the organized frame and its projection are
  * known; times the "surface" stage either way.
  */
bool
refineOnSurface (const DiscoveryParameters& p,
                 const KeypointSurface& frame,
                 DiscoveryResult& result)
{
  pcl::StopWatch watch;
  if (p.surface_refinement && frame.organized && frame.pinhole) {
    SurfacePoseRefinement refinement;
    refinement.setInputKeypoints (result.keypoints);
    refinement.setKeypointSurface (frame);
    refinement.setSampleStep (p.surface_sample_step);
    refinement.setMaxCorrespondenceDistance (p.surface_max_distance);
    refinement.setSurfaceWeight (p.surface_weight);
    refinement.setMaxIterations (p.surface_iterations);
    for (auto& model : result.models)
      if (!refinement.refine (model))
        return false;
  }
  result.timing_ms.emplace_back ("surface", watch.getTime());
  return true;
}

/** The frame's support plane, fitted once for the steps that measure boxes on the table (the
  * first that needs it fits it; zero when the frame has none).
  */
struct FramePlane
{
  bool fitted = false;
  Eigen::Vector4f plane = Eigen::Vector4f::Zero();
  EIGEN_MAKE_ALIGNED_OPERATOR_NEW
};

/** `frame` with the pixel of each of the result's keypoints. */
KeypointSurface
withKeypointPixels (const KeypointSurface& frame, const DiscoveryResult& result)
{
  KeypointSurface keypoint_surface = frame;
  keypoint_surface.keypoint_pixels.clear();
  for (const auto& k : result.image_keypoints)
    keypoint_surface.keypoint_pixels.push_back (k.pixel_index);
  return keypoint_surface;
}

/** Give a step that measures boxes on the table the frame's keypoints, their pixels in the
  * organized frame (which `frame` must hold) and the frame's support plane (fitted here on first
  * use).
  */
void
setUpPlaneMeasurement (const KeypointSurface& frame,
                       const DiscoveryResult& result,
                       FramePlane& plane,
                       SupportPlaneMeasurement& measurement)
{
  measurement.setInputKeypoints (result.keypoints);
  measurement.setKeypointSurface (withKeypointPixels (frame, result));
  if (!plane.fitted) {
    fitSupportPlane (
        *frame.organized, kDefaultPlaneTolerance, kMinSupportPlaneShare, plane.plane);
    plane.fitted = true;
  }
  measurement.setPlaneTolerance (kDefaultPlaneTolerance);
  measurement.setSupportPlane (plane.plane);
}

/** setUpPlaneMeasurement(), and the size tolerances of a step that compares box sizes. */
void
setUpBoxMeasurement (const DiscoveryParameters& p,
                     const KeypointSurface& frame,
                     const DiscoveryResult& result,
                     FramePlane& plane,
                     ModelSizeMeasurement& measurement)
{
  setUpPlaneMeasurement (frame, result, plane, measurement);
  measurement.setSizeTolerance (p.size_tolerance, p.relative_size_tolerance);
}

/** Look for more copies of each model with the guided search, the models extended for it by
  * the keypoints their copies show inside their boxes on the table (ModelBoxExtender,
  * DiscoveryParameters::box_search), among the keypoints off the table, then keep one instance
  * per physical object (DiscoveryParameters::resolve_overlaps), when the guided search can
  * run; times the "box_search" stage either way.
  */
bool
searchFromBoxes (const DiscoveryParameters& p,
                 const KeypointSurface& frame,
                 FramePlane& plane,
                 DiscoveryResult& result)
{
  pcl::StopWatch watch;
  const KeypointSurface keypoint_surface = withKeypointPixels (frame, result);
  if (p.box_search && p.guided_search && frame.organized &&
      canSearchGuided (keypoint_surface, result) && !result.models.empty()) {
    ModelBoxExtender extender;
    setUpBoxMeasurement (p, frame, result, plane, extender);
    extender.setInputDescriptors (result.descriptors);
    extender.setMargin (p.box_search_margin);
    ModelExtension extension;
    if (!extender.extend (result.models, extension))
      return false;
    const bool extended =
        std::any_of (extension.observations.begin(),
                     extension.observations.end(),
                     [] (const auto& added) { return !added.empty(); });
    if (extended) {
      // The copies of an object with a box stand off the table: the table's keypoints (a
      // printed sheet lying on it) are no candidates.
      std::vector<bool> on_table (result.keypoints->size(), false);
      for (std::size_t k = 0; k < on_table.size(); ++k)
        on_table[k] = std::abs (planeDistance (
                          plane.plane, (*result.keypoints)[k].getVector3fMap())) <=
                      extender.getPlaneTolerance();
      DiscoveryParameters search = p;
      search.guided_hypotheses = p.box_search_hypotheses;
      if (!searchGuidedInstances (search, keypoint_surface, result, on_table) ||
          !retractModelExtension (extension, result.models))
        return false;
      // The search refined the models with the added observations in.
      for (auto& model : result.models)
        for (auto& instance : model.instances)
          updateInstanceError (model, *result.keypoints, instance);
      if (p.resolve_overlaps)
        resolveOverlaps (p, *result.keypoints, result.models);
    }
  }
  result.timing_ms.emplace_back ("box_search", watch.getTime());
  return true;
}

/** Split the models whose copies occupy boxes of two sizes (DiscoveryParameters::split_by_size),
  * when the organized frame is known; times the "size_split" stage either way.
  */
bool
splitBySize (const DiscoveryParameters& p,
             const KeypointSurface& frame,
             FramePlane& plane,
             DiscoveryResult& result)
{
  pcl::StopWatch watch;
  if (p.split_by_size && frame.organized) {
    ModelSizeSplitter splitter;
    setUpBoxMeasurement (p, frame, result, plane, splitter);
    std::size_t added = 0;
    if (!splitter.split (result.models, added))
      return false;
  }
  result.timing_ms.emplace_back ("size_split", watch.getTime());
  return true;
}

/** Merge the models of one size (DiscoveryParameters::merge_by_size), when the organized
  * frame is known; times the "size_merge" stage either way.
  */
bool
mergeBySize (const DiscoveryParameters& p,
             const KeypointSurface& frame,
             FramePlane& plane,
             DiscoveryResult& result)
{
  pcl::StopWatch watch;
  if (p.merge_by_size && frame.organized) {
    ModelSizeMerger merger;
    setUpBoxMeasurement (p, frame, result, plane, merger);
    merger.setDuplicateThresholds (p.duplicate_angle, p.duplicate_distance);
    if (!merger.merge (result.models))
      return false;
  }
  result.timing_ms.emplace_back ("size_merge", watch.getTime());
  return true;
}

/** Remove the instances that repeat a print on one object with another of their model
  * (DiscoveryParameters::remove_repeated_prints), when the organized frame is known; times the
  * "repeated_prints" stage either way.
  */
bool
removeRepeatedPrints (const DiscoveryParameters& p,
                      const KeypointSurface& frame,
                      FramePlane& plane,
                      DiscoveryResult& result)
{
  pcl::StopWatch watch;
  if (p.remove_repeated_prints && frame.organized) {
    RepeatedPrintFilter filter;
    setUpPlaneMeasurement (frame, result, plane, filter);
    filter.setMaxRotation (p.repeated_print_max_rotation);
    filter.setMaxShiftRatio (p.repeated_print_max_shift);
    filter.setMaxShiftAlongWidth (p.repeated_print_max_shift_along);
    filter.setMinInsideShare (p.repeated_print_min_inside);
    std::size_t removed = 0;
    if (!filter.filter (result.models, removed))
      return false;
  }
  result.timing_ms.emplace_back ("repeated_prints", watch.getTime());
  return true;
}

/** Find the copies of a model that show none of its landmarks by their size
  * (DiscoveryParameters::size_search), and the objects that repeat by size alone
  * (DiscoveryParameters::size_discovery), when the organized frame is known; times the
  * "size_search" stage either way.
  */
bool
searchBySize (const DiscoveryParameters& p,
              const KeypointSurface& frame,
              FramePlane& plane,
              DiscoveryResult& result)
{
  pcl::StopWatch watch;
  if (p.size_search && frame.organized) {
    SizeInstanceSearch search;
    setUpBoxMeasurement (p, frame, result, plane, search);
    search.setInputDescriptors (result.descriptors);
    search.setMinAgreeing (p.size_search_min_agreeing);
    search.setMinKeypoints (p.size_search_min_keypoints);
    search.setDiscoverModels (p.size_discovery);
    search.setMaxSurroundedShare (p.size_discovery_max_surrounded);
    search.setMinModelEdge (p.size_discovery_min_edge);
    std::size_t found = 0;
    if (!search.search (result.models, found))
      return false;
  }
  result.timing_ms.emplace_back ("size_search", watch.getTime());
  return true;
}

/** Remove the instances whose box would interpenetrate another instance's box of their model
  * (DiscoveryParameters::remove_interpenetrating), when the organized frame is known; times
  * the "interpenetration" stage either way.
  */
bool
removeInterpenetrating (const DiscoveryParameters& p,
                        const KeypointSurface& frame,
                        FramePlane& plane,
                        DiscoveryResult& result)
{
  pcl::StopWatch watch;
  if (p.remove_interpenetrating && frame.organized) {
    InterpenetrationFilter filter;
    setUpBoxMeasurement (p, frame, result, plane, filter);
    filter.setMaxCentreDistance (p.interpenetration_max_centre_distance);
    std::size_t removed = 0;
    if (!filter.filter (result.models, removed))
      return false;
  }
  result.timing_ms.emplace_back ("interpenetration", watch.getTime());
  return true;
}

/** Drop the observations that the instances' poses do not explain
  * (DiscoveryParameters::prune_observations); times the "observations" stage either way.
  */
bool
pruneObservations (const DiscoveryParameters& p, DiscoveryResult& result)
{
  pcl::StopWatch watch;
  if (p.prune_observations)
    for (auto& model : result.models) {
      std::size_t dropped = 0;
      if (!pruneUnexplainedObservations (*result.keypoints,
                                         p.observation_max_residual,
                                         p.observation_box_margin,
                                         model,
                                         dropped))
        return false;
    }
  result.timing_ms.emplace_back ("observations", watch.getTime());
  return true;
}

/** discoverFromKeypoints() without its cleanup on failure. */
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
    for (const auto& k : result.image_keypoints)
      keypoint_surface.keypoint_pixels.push_back (k.pixel_index);
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
    if (!detail::groupWithPeer (
            p, result.keypoints, surface, result.matches, *clusters))
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

} // namespace

bool
discoverFromKeypoints (const DiscoveryParameters& p,
                       DiscoveryResult& result,
                       const pcl::PointCloud<pcl::PointNormal>::ConstPtr& surface,
                       const pcl::PointCloud<pcl::PointXYZRGB>::ConstPtr& organized)
{
  const std::size_t timed = result.timing_ms.size();
  const KeypointSurface frame = frameSurface (p, organized);
  FramePlane plane;
  if (runStages (p, result, surface, frame) &&
      searchFromBoxes (p, frame, plane, result) && refineOnSurface (p, frame, result) &&
      splitBySize (p, frame, plane, result) && mergeBySize (p, frame, plane, result) &&
      removeRepeatedPrints (p, frame, plane, result) &&
      searchBySize (p, frame, plane, result) &&
      removeInterpenetrating (p, frame, plane, result) &&
      pruneObservations (p, result)) {
    // Merges add landmarks in the frame of the model they join: every model is centred again.
    for (auto& model : result.models)
      centerModelFrame (model);
    return true;
  }
  // No partial output: the stages' results go, the given keypoints and descriptors stay.
  result.matches.clear();
  result.triplets = result.clusters = result.rejected_clusters = 0;
  result.models.clear();
  result.timing_ms.resize (timed);
  return false;
}

} // namespace mid
