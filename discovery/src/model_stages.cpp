#include "model_stages.h"

#include "stage_tools.h"

#include <mid/discovery/discovery_stages.h>
#include <mid/registration/model_merging.h>
#include <mid/registration/model_refinement.h>
#include <mid/registration/region_model_merger.h>
#include <mid/segmentation/appearance_model_splitter.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <set>
#include <string>

namespace mid {

namespace {

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

} // namespace

using detail::bestCopyLink;
using detail::copiesLookApart;
using detail::makeModelMatcher;
using detail::modelAsKeypoints;

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
          makeModelMatcher (p,
                            std::make_shared<const ObjectModel> (models[j]),
                            mergeInliers (p, models[i], models[j]));
      detector.setInputKeypoints (points);
      detector.setInputDescriptors (descriptors);
      detector.setMaxInstances (1);
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

namespace detail {

bool
mergeThroughRegions (const DiscoveryParameters& p,
                     const KeypointSurface& surface,
                     DiscoveryResult& result)
{
  ModelInstanceDetector detector =
      makeModelMatcher (p, nullptr, p.min_region_merge_inliers);
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

bool
searchGuidedInstances (const DiscoveryParameters& p,
                       const KeypointSurface& surface,
                       DiscoveryResult& result,
                       const std::vector<bool>& excluded)
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
    ModelInstances found, unconfirmed;
    if (!search.search (model, found, unconfirmed))
      return false;
    addFoundInstances (p, result, found, model, unconfirmed);
  }
  return true;
}

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

} // namespace detail

} // namespace mid
