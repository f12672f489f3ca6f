#pragma once

// Placing objects on a table seen by a camera: footprints, overlap and visibility tests, poses.
// Shared by the scene recipes (tabletop_scene.cpp, benchmark_scene.cpp); not installed.

#include <mid/simulation/deterministic_random.h>
#include <mid/simulation/pinhole_camera.h>

#include <Eigen/Geometry>

#include <vector>

namespace mid {
namespace simulation {

/** Rotated rectangle an object covers on the table (table frame: z up, top at z = 0), and the
  * object's height.
  */
struct Footprint
{
  Eigen::Vector2d center = Eigen::Vector2d::Zero();
  double yaw = 0.0;
  Eigen::Vector2d half = Eigen::Vector2d::Zero();
  double height = 0.0;
};

/** Where the objects may go: a rectangle of the table, and only where the camera sees them
  * whole (at least margin pixels from the image border).
  */
struct PlacementView
{
  PinholeCamera camera;
  Eigen::Isometry3d table_to_camera = Eigen::Isometry3d::Identity();
  double min_x = -0.45, max_x = 0.45;
  double min_y = -0.3, max_y = 0.4;
  double margin = 8.0;
};

/** Whether two footprints, each grown by half the gap, overlap (separating axis test). */
bool
footprintsOverlap (const Footprint& a, const Footprint& b, double gap);

/** Whether the footprint's box (footprint times height) lies in the area and in view. */
bool
footprintAllowed (const Footprint& footprint, const PlacementView& view);

/** Whether the footprint is allowed and at least gap away from every placed one. */
bool
footprintFree (const Footprint& footprint,
               const PlacementView& view,
               const std::vector<Footprint>& placed,
               double gap);

/** Place footprints of the given sizes at random free spots (uniform position and yaw),
  * largest first, starting over when one does not fit; layout[i] belongs to shapes[i].
  * False if no layout was found within the attempts.
  */
bool
layoutFootprints (const std::vector<Footprint>& shapes,
                  const PlacementView& view,
                  double gap,
                  DeterministicRandom& random,
                  std::vector<Footprint>& layout);

/** Table-to-camera transform of a camera at the given distance from the table centre, looking
  * at it the given angle below the horizontal, without roll, from the -y side turned by the
  * azimuth about the table's z axis (degrees, counter-clockwise seen from above).
  */
Eigen::Isometry3d
tableToCamera (double distance, double elevation_deg, double azimuth_deg = 0.0);

/** Footprint half extents and height of a box of the given edge lengths (model frame) turned
  * by an orientation that maps model axes onto table axes (a signed permutation).
  */
Footprint
restingFootprint (const Eigen::Vector3d& size, const Eigen::Matrix3d& orientation);

/** Object-to-table pose of an object resting at height z (its centre), oriented, then turned
  * by the footprint's yaw and moved to its centre.
  */
Eigen::Isometry3d
restingPose (const Footprint& footprint, double z, const Eigen::Matrix3d& orientation);

} // namespace simulation
} // namespace mid
