#pragma once

// The discovery pipeline's stages on the organized frame: its grey levels and projection, the
// refinement on its depth, the boxes the copies occupy on its support plane, and the last
// pruning of the observations.

#include <mid/discovery/discovery_parameters.h>
#include <mid/discovery/discovery_result.h>
#include <mid/segmentation/surface_gap.h>

#include <Eigen/Core>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

namespace mid {
namespace detail {

/** The frame's support plane, fitted once for the steps that measure boxes on the table (the
  * first that needs it fits it; zero when the frame has none).
  */
struct FramePlane
{
  bool fitted = false;
  Eigen::Vector4f plane = Eigen::Vector4f::Zero();
  EIGEN_MAKE_ALIGNED_OPERATOR_NEW
};

/** The points of an organized colour frame, and, when a stage compares looks or refines on
  * the depth (the cluster verification, the look check of what joins a model, the guided
  * search, the patches, the appearance split, the surface refinement), its grey levels, colours
  * and projection (no keypoints yet); empty for none. Warns, once for both rounds, when no pinhole
  * camera fits the frame: those stages then do not run.
  */
KeypointSurface
frameSurface (const DiscoveryParameters& p,
              const pcl::PointCloud<pcl::PointXYZRGB>::ConstPtr& organized);

/** Refine every model's instance poses on the frame's depth
  * (DiscoveryParameters::surface_refinement), when the organized frame and its projection are
  * known; times the "surface" stage either way.
  */
bool
refineOnSurface (const DiscoveryParameters& p,
                 const KeypointSurface& frame,
                 DiscoveryResult& result);

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
                 DiscoveryResult& result);

/** Split the models whose copies occupy boxes of two sizes (DiscoveryParameters::split_by_size),
  * when the organized frame is known; times the "size_split" stage either way.
  */
bool
splitBySize (const DiscoveryParameters& p,
             const KeypointSurface& frame,
             FramePlane& plane,
             DiscoveryResult& result);

/** Merge the models of one size (DiscoveryParameters::merge_by_size), when the organized
  * frame is known; times the "size_merge" stage either way.
  */
bool
mergeBySize (const DiscoveryParameters& p,
             const KeypointSurface& frame,
             FramePlane& plane,
             DiscoveryResult& result);

/** Drop the observations outside the box a model's copies occupy on the table
  * (DiscoveryParameters::prune_outside_box), when the organized frame is known; times the
  * "box_pruning" stage either way.
  */
bool
pruneOutsideBoxes (const DiscoveryParameters& p,
                   const KeypointSurface& frame,
                   FramePlane& plane,
                   DiscoveryResult& result);

/** Remove the instances that repeat a print on one object with another of their model
  * (DiscoveryParameters::remove_repeated_prints), when the organized frame is known; times the
  * "repeated_prints" stage either way.
  */
bool
removeRepeatedPrints (const DiscoveryParameters& p,
                      const KeypointSurface& frame,
                      FramePlane& plane,
                      DiscoveryResult& result);

/** Find the copies of a model that show none of its landmarks by their size
  * (DiscoveryParameters::size_search), and the objects that repeat by size alone
  * (DiscoveryParameters::size_discovery), when the organized frame is known; times the
  * "size_search" stage either way.
  */
bool
searchBySize (const DiscoveryParameters& p,
              const KeypointSurface& frame,
              FramePlane& plane,
              DiscoveryResult& result);

/** Remove the instances whose box would interpenetrate another instance's box of their model
  * (DiscoveryParameters::remove_interpenetrating), when the organized frame is known; times
  * the "interpenetration" stage either way.
  */
bool
removeInterpenetrating (const DiscoveryParameters& p,
                        const KeypointSurface& frame,
                        FramePlane& plane,
                        DiscoveryResult& result);

/** Remove the models whose copies stand alone and agree on no size
  * (DiscoveryParameters::remove_disagreeing_sizes), when the organized frame is known; times
  * the "size_disagreement" stage either way.
  */
bool
removeDisagreeingSizes (const DiscoveryParameters& p,
                        const KeypointSurface& frame,
                        FramePlane& plane,
                        DiscoveryResult& result);

/** Turn the groups of a model's copies posed by their box alone to the turn their print
  * confirms (DiscoveryParameters::resolve_box_turns), when the organized frame, its grey levels
  * and projection are known; times the "box_turns" stage either way.
  */
bool
resolveBoxTurns (const DiscoveryParameters& p,
                 const KeypointSurface& frame,
                 FramePlane& plane,
                 DiscoveryResult& result);

/** Remove the instances that lie flat in the support plane, prints on the table
  * (DiscoveryParameters::remove_support_prints), when the organized frame is known; times the
  * "support_prints" stage either way.
  */
bool
removeSupportPrints (const DiscoveryParameters& p,
                     const KeypointSurface& frame,
                     FramePlane& plane,
                     DiscoveryResult& result);

/** Drop the observations that the instances' poses do not explain
  * (DiscoveryParameters::prune_observations); times the "observations" stage either way.
  */
bool
pruneObservations (const DiscoveryParameters& p, DiscoveryResult& result);

/** Measure the box each model's copies occupy on the table (result.model_sizes, one per
  * model, in the models' present frames: the last step, after the frames are centred), with
  * the size tolerances of the steps that compare sizes; all invalid without the organized
  * frame or a support plane. Times the "box_sizes" stage.
  */
bool
measureObjectBoxes (const DiscoveryParameters& p,
                    const KeypointSurface& frame,
                    FramePlane& plane,
                    DiscoveryResult& result);

} // namespace detail
} // namespace mid
