#include "round_stages.h"

#include "model_stages.h"
#include "stage_tools.h"

#include <mid/discovery/discovery_stages.h>
#include <mid/registration/model_instance_detector.h>
#include <mid/segmentation/guided_instance_search.h>
#include <mid/segmentation/keypoint_patch.h>

#include <pcl/common/time.h>

#include <memory>

namespace mid {

namespace detail {

namespace {

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
    ModelInstanceDetector detector = makeModelMatcher (p, shared, min_inliers);
    detector.setInputKeypoints (points);
    detector.setInputDescriptors (
        pcl::make_shared<SIFTDescriptorCloud> (other.descriptors));
    detector.setMaxInstances (1);
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

} // namespace

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
    // A patch is one copy's keypoints: what it finds joins it whatever its neighbourhoods
    // say (asking them lost copies on the benchmark, doc/benchmark.md, session 59).
    search.setMaxDisagreeingShare (1.0f);
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

} // namespace detail

} // namespace mid
