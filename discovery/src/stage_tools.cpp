#include "stage_tools.h"

#include <mid/registration/instance_overlap.h>
#include <mid/registration/landmark_box.h>
#include <mid/registration/model_merging.h>
#include <mid/registration/model_refinement.h>

#include <algorithm>
#include <map>

namespace mid {

namespace detail {

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
  detector.setMinInlierSpread (p.min_inlier_spread);
  detector.setMaxIterations (p.ransac_iterations);
  detector.setSeed (p.seed);
  return detector;
}

ModelInstanceDetector
makeModelMatcher (const DiscoveryParameters& p,
                  const std::shared_ptr<const ObjectModel>& model,
                  std::size_t min_inliers)
{
  ModelInstanceDetector detector = makeDetector (p, model);
  detector.setMinInliers (min_inliers);
  detector.setMinInlierSpread (0.0f);
  return detector;
}

void
modelAsKeypoints (const ObjectModel& b, KeypointCloud& keypoints)
{
  keypoints.clear();
  for (const int l : b.descriptor_landmarks)
    keypoints.push_back (b.landmarks[static_cast<std::size_t> (l)]);
}

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
  verification.setMaxVividChromaticityDifference (p.max_vivid_chromaticity_difference);
  return verification;
}

bool
canCompareLooks (const KeypointSurface& surface)
{
  return surface.organized && surface.intensity && surface.pinhole;
}

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

void
addFoundInstances (const DiscoveryParameters& p,
                   const DiscoveryResult& result,
                   const ModelInstances& found,
                   ObjectModel& model,
                   const ModelInstances& unconfirmed)
{
  for (const auto& instance : found)
    addInstance (
        model, instance, *result.descriptors, p.duplicate_angle, p.duplicate_distance);
  for (const auto& copy : unconfirmed)
    addInstanceOfKeypoints (
        *result.keypoints, *result.descriptors, copy.keypoints, copy.pose, model);
  if (!found.empty() || !unconfirmed.empty())
    refineModel (model, *result.keypoints, p.refinement_iterations);
}

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

bool
canSearchGuided (const KeypointSurface& surface, const DiscoveryResult& result)
{
  return canCompareLooks (surface) &&
         result.image_keypoints.size() == result.keypoints->size();
}

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
  search.setMinNeighbourhoodCorrelation (p.guided_neighbourhood_correlation);
  search.setMaxDisagreeingShare (p.guided_max_disagreeing);
  search.setMaxChromaticityDifference (p.max_chromaticity_difference);
  search.setMaxVividChromaticityDifference (p.max_vivid_chromaticity_difference);
  search.setCorrelationRadius (p.verification_radius);
  search.setDepthTolerance (p.verification_depth_tolerance);
  search.setMaxHypotheses (p.guided_hypotheses);
  return search;
}

} // namespace detail

} // namespace mid
