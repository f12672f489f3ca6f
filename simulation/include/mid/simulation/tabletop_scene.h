#pragma once

#include <mid/simulation/pinhole_camera.h>
#include <mid/simulation/scene.h>

#include <cstdint>
#include <string>

namespace mid {
namespace simulation {

/** \brief Recipe of makeTabletopScene(). */
struct TabletopSceneOptions
{
  /** \brief Number of identical juice cartons (70 x 70 x 200 mm, lying), 1 to 10 (with many
    * instances, a seed may find no room for all of them: makeTabletopScene() then fails).
    */
  int instances = 5;
  /** \brief Number of objects that appear once, 0 to 2: a flat cookie box, then a soy milk can.
    */
  int distractors = 2;
  /** \brief Seed of the layout (positions, headings, which carton face is up). */
  std::uint32_t seed = 1;
  /** \brief Distance from the camera centre to the table centre, metres. */
  double camera_distance = 0.85;
  /** \brief Angle of the viewing direction below the horizontal, degrees (90 = top-down). */
  double camera_elevation = 50.0;
  /** \brief The camera that will render the scene: objects are placed entirely in its view. */
  PinholeCamera camera;
};

/** \brief Names of the textures makeTabletopScene() reads from its texture folder (the
  * repository's data/textures). */
constexpr const char* TABLETOP_CARTON_FRONT_TEXTURE = "tropicana_apple_juice_front.jpg";
constexpr const char* TABLETOP_CARTON_BACK_TEXTURE =
    "god_morgon_orange_juice_front.jpg";
constexpr const char* TABLETOP_COOKIE_BOX_TEXTURE = "bastoncini_cookie_box.png";
constexpr const char* TABLETOP_CAN_LABEL_TEXTURE = "alpro_soya_front.jpg";

/** \brief Build the standard multi-instance test scene: a wood-textured table (1.6 x 1.2 m,
  * procedural, non-repeating) seen obliquely by options.camera, identical juice
  * cartons ("juice_carton") lying in random, non-touching poses, and distractors that appear
  * once ("cookie_box", "soy_milk_can").
  *
  * The objects are the scene's instances 0 .. instances - 1 (cartons), then the distractors;
  * the table is its only background object, its pose being the table-to-camera transform
  * (table frame: z up, table top at z = 0). The same options give the same scene everywhere.
  * \param[in] options the recipe
  * \param[in] texture_dir folder holding the TABLETOP_*_TEXTURE files
  * \param[out] scene the scene; cleared when false is returned
  * \return false (with a PCL_ERROR) if an option is out of range, a texture cannot be read, or
  * the objects cannot be placed without touching
  */
bool
makeTabletopScene (const TabletopSceneOptions& options,
                   const std::string& texture_dir,
                   Scene& scene);

} // namespace simulation
} // namespace mid
