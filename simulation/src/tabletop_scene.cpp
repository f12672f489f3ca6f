#include "table_layout.h"

#include <mid/simulation/deterministic_random.h>
#include <mid/simulation/procedural_texture.h>
#include <mid/simulation/product_catalog.h>
#include <mid/simulation/table_plane.h>
#include <mid/simulation/tabletop_scene.h>

#include <opencv2/core.hpp>
#include <pcl/console/print.h>

#include <vector>

namespace mid {
namespace simulation {

namespace {

constexpr double kPi = 3.14159265358979323846;

/** Juice carton (about 1 l): square section, lying on a long side. */
const Eigen::Vector3d kCartonSize (0.07, 0.07, 0.2);
/** Table top (table frame, y away from the camera). */
constexpr double kTableSizeX = 1.6;
constexpr double kTableSizeY = 1.2;
/** Smallest gap between the footprints of two objects, metres. */
constexpr double kMinGap = 0.02;
constexpr int kMaxInstances = 10;

/** Stream of DeterministicRandom used by the layout. */
constexpr std::uint32_t kLayoutStream = 11;

TablePlane::Ptr
makeTable (std::uint32_t seed)
{
  auto table = std::make_shared<TablePlane> (kTableSizeX, kTableSizeY);
  table->setName ("table");
  table->setExtent (kTableSizeX, kTableSizeY);
  table->setTexture (makeNoiseTexture (1024,
                                       768,
                                       200.0,
                                       24.0,
                                       cv::Vec3b (40, 75, 120),
                                       cv::Vec3b (120, 170, 215),
                                       seed));
  return table;
}

bool
fail (const std::string& message, Scene& scene)
{
  PCL_ERROR ("[mid::simulation::makeTabletopScene] %s\n", message.c_str());
  scene.clear();
  return false;
}

} // namespace

bool
makeTabletopScene (const TabletopSceneOptions& options,
                   const std::string& texture_dir,
                   Scene& scene)
{
  scene.clear();
  if (options.instances < 1 || options.instances > kMaxInstances)
    return fail ("the number of instances must be in [1, " +
                     std::to_string (kMaxInstances) + "], got " +
                     std::to_string (options.instances),
                 scene);
  if (options.distractors < 0 || options.distractors > 2)
    return fail ("the number of distractors must be in [0, 2], got " +
                     std::to_string (options.distractors),
                 scene);
  std::string problem;
  if (!validateCamera (options.camera, problem))
    return fail (problem, scene);
  if (!(options.camera_distance >= 0.4 && options.camera_distance <= 3.0) ||
      !(options.camera_elevation >= 20.0 && options.camera_elevation <= 90.0))
    return fail (
        "the camera distance must be in [0.4, 3] m and its elevation in [20, 90] deg",
        scene);
  ProductCatalog catalog;
  if (!makeProductCatalog (texture_dir, catalog))
    return fail ("cannot read the textures in '" + texture_dir + "'", scene);
  const ProductType& cookie_box = getProduct (catalog, PRODUCT_COOKIE_BOX);
  const ProductType& can = getProduct (catalog, PRODUCT_SOY_MILK_CAN);

  // Footprints: the cartons (long axis along the footprint's x), then the distractors.
  std::vector<Footprint> shapes (options.instances);
  for (Footprint& shape : shapes) {
    shape.half = Eigen::Vector2d (0.5 * kCartonSize.z(), 0.5 * kCartonSize.x());
    shape.height = kCartonSize.x();
  }
  if (options.distractors >= 1) {
    shapes.emplace_back();
    shapes.back() =
        restingFootprint (cookie_box.size, cookie_box.rests.front().rotation);
  }
  if (options.distractors >= 2) {
    shapes.emplace_back();
    shapes.back() = restingFootprint (can.size, can.rests.front().rotation);
  }
  const Eigen::Isometry3d table_to_camera =
      tableToCamera (options.camera_distance, options.camera_elevation);
  PlacementView view;
  view.camera = options.camera;
  view.table_to_camera = table_to_camera;
  DeterministicRandom random (options.seed, kLayoutStream);
  std::vector<Footprint> placed;
  if (!layoutFootprints (shapes, view, kMinGap, random, placed))
    return fail (
        "cannot place " + std::to_string (shapes.size()) +
            " objects on the table in view without contact; use fewer instances",
        scene);
  std::vector<int> spins;
  spins.reserve (options.instances);
  for (int i = 0; i < options.instances; ++i)
    spins.push_back (random.uniformInt (4));
  const Shape::Ptr carton = getProduct (catalog, PRODUCT_JUICE_CARTON).shape;
  for (int i = 0; i < options.instances; ++i) {
    // Long axis (model z) along the footprint's x; spinning about it picks the face that is up.
    const Eigen::Matrix3d lying =
        Eigen::AngleAxisd (0.5 * kPi, Eigen::Vector3d::UnitY()).toRotationMatrix() *
        Eigen::AngleAxisd (0.5 * kPi * spins[i], Eigen::Vector3d::UnitZ())
            .toRotationMatrix();
    scene.addObject (carton,
                     table_to_camera *
                         restingPose (placed[i], 0.5 * kCartonSize.x(), lying));
  }
  if (options.distractors >= 1)
    scene.addObject (cookie_box.shape,
                     table_to_camera * restingPose (placed[options.instances],
                                                    0.5 * cookie_box.size.z(),
                                                    Eigen::Matrix3d::Identity()));
  if (options.distractors >= 2) {
    // The label (model +x) turned roughly towards the camera (table -y); a circle fits its
    // square footprint whatever the heading.
    Footprint footprint = placed[options.instances + 1];
    footprint.yaw = -0.5 * kPi + random.uniform (-0.6, 0.6);
    scene.addObject (can.shape,
                     table_to_camera * restingPose (footprint,
                                                    0.5 * can.size.z(),
                                                    Eigen::Matrix3d::Identity()));
  }
  scene.addBackgroundObject (makeTable (options.seed), table_to_camera);
  return true;
}

} // namespace simulation
} // namespace mid
