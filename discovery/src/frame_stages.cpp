#include "frame_stages.h"

#include "model_stages.h"
#include "stage_tools.h"

#include <mid/registration/observation_pruning.h>
#include <mid/segmentation/box_turn_resolver.h>
#include <mid/segmentation/frame_pinhole.h>
#include <mid/segmentation/instance_extent.h>
#include <mid/segmentation/interpenetration_filter.h>
#include <mid/segmentation/model_box_extension.h>
#include <mid/segmentation/model_box_pruning.h>
#include <mid/segmentation/model_size.h>
#include <mid/segmentation/model_size_merger.h>
#include <mid/segmentation/model_size_splitter.h>
#include <mid/segmentation/photometric_verification.h>
#include <mid/segmentation/repeated_print_filter.h>
#include <mid/segmentation/size_disagreement_filter.h>
#include <mid/segmentation/size_instance_search.h>
#include <mid/segmentation/support_print_filter.h>
#include <mid/segmentation/surface_pose_refinement.h>

#include <pcl/common/io.h>
#include <pcl/common/time.h>
#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace mid {

namespace detail {

namespace {

/** `frame` with the pixel of each of the result's keypoints. */
KeypointSurface
withKeypointPixels (const KeypointSurface& frame, const DiscoveryResult& result)
{
  KeypointSurface keypoint_surface = frame;
  keypoint_surface.keypoint_pixels = pixelIndices (result.image_keypoints);
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

/** The refinement of the instances' poses on the frame's depth with the pipeline's settings. */
SurfacePoseRefinement
makeSurfaceRefinement (const DiscoveryParameters& p,
                       const KeypointSurface& frame,
                       const DiscoveryResult& result)
{
  SurfacePoseRefinement refinement;
  refinement.setInputKeypoints (result.keypoints);
  refinement.setKeypointSurface (frame);
  refinement.setSampleStep (p.surface_sample_step);
  refinement.setMaxCorrespondenceDistance (p.surface_max_distance);
  refinement.setSurfaceWeight (p.surface_weight);
  refinement.setMaxIterations (p.surface_iterations);
  return refinement;
}

/** True if an instance of `model` has another pose than in `before` (its instances then). */
bool
modelTurned (const ObjectModel& model, const ModelInstances& before)
{
  for (std::size_t i = 0; i < model.instances.size(); ++i)
    if (model.instances[i].pose != before[i].pose)
      return true;
  return false;
}

/** Run a step that removes instances from the models (`Filter::filter (models, removed)`)
  * when `enabled` and the organized frame is known, after `configure` gave it its inputs and
  * settings; times `stage` either way.
  */
template <typename Filter, typename Configure>
bool
removeByFilter (const char* stage,
                bool enabled,
                const KeypointSurface& frame,
                DiscoveryResult& result,
                const Configure& configure)
{
  pcl::StopWatch watch;
  if (enabled && frame.organized) {
    Filter filter;
    configure (filter);
    std::size_t removed = 0;
    if (!filter.filter (result.models, removed))
      return false;
  }
  result.timing_ms.emplace_back (stage, watch.getTime());
  return true;
}

} // namespace

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
      !p.split_by_appearance && !p.surface_refinement && !p.resolve_box_turns)
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

bool
refineOnSurface (const DiscoveryParameters& p,
                 const KeypointSurface& frame,
                 DiscoveryResult& result)
{
  pcl::StopWatch watch;
  if (p.surface_refinement && frame.organized && frame.pinhole) {
    const SurfacePoseRefinement refinement = makeSurfaceRefinement (p, frame, result);
    for (auto& model : result.models)
      if (!refinement.refine (model))
        return false;
  }
  result.timing_ms.emplace_back ("surface", watch.getTime());
  return true;
}

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
    merger.setConsensusRadius (p.size_merge_consensus_radius);
    if (!merger.merge (result.models))
      return false;
  }
  result.timing_ms.emplace_back ("size_merge", watch.getTime());
  return true;
}

bool
pruneOutsideBoxes (const DiscoveryParameters& p,
                   const KeypointSurface& frame,
                   FramePlane& plane,
                   DiscoveryResult& result)
{
  pcl::StopWatch watch;
  if (p.prune_outside_box && frame.organized) {
    ModelBoxPruning pruning;
    setUpBoxMeasurement (p, frame, result, plane, pruning);
    pruning.setMargin (p.observation_box_margin);
    std::size_t dropped = 0;
    if (!pruning.prune (result.models, dropped))
      return false;
  }
  result.timing_ms.emplace_back ("box_pruning", watch.getTime());
  return true;
}

bool
removeRepeatedPrints (const DiscoveryParameters& p,
                      const KeypointSurface& frame,
                      FramePlane& plane,
                      DiscoveryResult& result)
{
  return removeByFilter<RepeatedPrintFilter> (
      "repeated_prints",
      p.remove_repeated_prints,
      frame,
      result,
      [&] (RepeatedPrintFilter& filter) {
        setUpPlaneMeasurement (frame, result, plane, filter);
        filter.setMaxRotation (p.repeated_print_max_rotation);
        filter.setMaxShiftRatio (p.repeated_print_max_shift);
        filter.setMaxShiftAlongWidth (p.repeated_print_max_shift_along);
        filter.setMinInsideShare (p.repeated_print_min_inside);
      });
}

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

bool
removeInterpenetrating (const DiscoveryParameters& p,
                        const KeypointSurface& frame,
                        FramePlane& plane,
                        DiscoveryResult& result)
{
  return removeByFilter<InterpenetrationFilter> (
      "interpenetration",
      p.remove_interpenetrating,
      frame,
      result,
      [&] (InterpenetrationFilter& filter) {
        setUpBoxMeasurement (p, frame, result, plane, filter);
        filter.setMaxCentreDistance (p.interpenetration_max_centre_distance);
      });
}

bool
removeDisagreeingSizes (const DiscoveryParameters& p,
                        const KeypointSurface& frame,
                        FramePlane& plane,
                        DiscoveryResult& result)
{
  return removeByFilter<SizeDisagreementFilter> (
      "size_disagreement",
      p.remove_disagreeing_sizes,
      frame,
      result,
      [&] (SizeDisagreementFilter& filter) {
        setUpBoxMeasurement (p, frame, result, plane, filter);
        filter.setMaxSurroundedShare (p.size_disagreement_max_surrounded);
        filter.setMinCopies (p.size_disagreement_min_copies);
      });
}

bool
resolveBoxTurns (const DiscoveryParameters& p,
                 const KeypointSurface& frame,
                 FramePlane& plane,
                 DiscoveryResult& result)
{
  pcl::StopWatch watch;
  if (p.resolve_box_turns && canCompareLooks (frame) && !result.models.empty()) {
    BoxTurnResolver resolver;
    setUpBoxMeasurement (p, frame, result, plane, resolver);
    resolver.setVerification (makeVerification (
        p, withKeypointPixels (frame, result), p.min_join_correlation));
    resolver.setMinGain (p.box_turn_min_gain);
    std::vector<ModelInstances> before;
    for (const auto& model : result.models)
      before.push_back (model.instances);
    std::size_t turned = 0;
    if (!resolver.resolve (result.models, turned))
      return false;
    // A turned copy rests on its box about the measured centre: its surface, now facing the
    // same way as the other copies', aligns it with theirs.
    if (turned > 0 && p.surface_refinement) {
      const SurfacePoseRefinement refinement = makeSurfaceRefinement (p, frame, result);
      for (std::size_t m = 0; m < result.models.size(); ++m)
        if (modelTurned (result.models[m], before[m]) &&
            !refinement.refine (result.models[m]))
          return false;
    }
  }
  result.timing_ms.emplace_back ("box_turns", watch.getTime());
  return true;
}

bool
removeSupportPrints (const DiscoveryParameters& p,
                     const KeypointSurface& frame,
                     FramePlane& plane,
                     DiscoveryResult& result)
{
  return removeByFilter<SupportPrintFilter> (
      "support_prints",
      p.remove_support_prints,
      frame,
      result,
      [&] (SupportPrintFilter& filter) {
        setUpPlaneMeasurement (frame, result, plane, filter);
        filter.setMinShareOnPlane (p.support_print_min_share);
      });
}

bool
pruneObservations (const DiscoveryParameters& p, DiscoveryResult& result)
{
  pcl::StopWatch watch;
  if (p.prune_observations)
    for (auto& model : result.models) {
      std::size_t dropped = 0;
      if (!pruneObservationsOnOtherCopies (*result.keypoints, model, dropped) ||
          !pruneUnexplainedObservations (*result.keypoints,
                                         p.observation_max_residual,
                                         p.observation_box_margin,
                                         model,
                                         dropped))
        return false;
    }
  result.timing_ms.emplace_back ("observations", watch.getTime());
  return true;
}

bool
measureObjectBoxes (const DiscoveryParameters& p,
                    const KeypointSurface& frame,
                    FramePlane& plane,
                    DiscoveryResult& result)
{
  pcl::StopWatch watch;
  result.model_sizes.assign (result.models.size(), ModelSize());
  if (frame.organized && !result.models.empty()) {
    ModelSizeMeasurement measurement;
    setUpBoxMeasurement (p, frame, result, plane, measurement);
    if (!measurement.measure (result.models, result.model_sizes))
      return false;
  }
  result.timing_ms.emplace_back ("box_sizes", watch.getTime());
  return true;
}

} // namespace detail

} // namespace mid
