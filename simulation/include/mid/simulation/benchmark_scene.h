#pragma once

#include <mid/simulation/pinhole_camera.h>
#include <mid/simulation/product_catalog.h>
#include <mid/simulation/scene.h>

#include <cstdint>
#include <string>
#include <vector>

namespace mid {
namespace simulation {

/** \brief The scenarios of the synthetic benchmark: the four of Abbeloos et al. (3DV 2017,
  * Table 2) and two more.
  */
enum class BenchmarkScenario {
  /** \brief "S-ez": one product type, 2 to 9 instances apart from each other, low resting
    * poses, nothing else on the table. */
  SINGLE_EASY,
  /** \brief "S-d": one product type, 2 to 9 instances in any resting pose, most of them
    * touching another object, 1 to 3 distractors that appear once. */
  SINGLE_DIFFICULT,
  /** \brief "M-ez": 2 or 3 product types, 2 to 6 (two types) or 2 to 4 (three types)
    * instances each, placed as in S-ez. */
  MULTI_EASY,
  /** \brief "M-d": the product types and counts of M-ez, placed as in S-d with 1 or 2
    * distractors. */
  MULTI_DIFFICULT,
  /** \brief "rows": one or two regular rows (different types) of 3 to 7 instances with the
    * same orientation and equal spacing, as on a shelf. */
  ROWS,
  /** \brief "none": 3 to 6 objects, all of different types: nothing repeats. */
  NONE
};

/** \brief Number of scenarios. */
constexpr int BENCHMARK_SCENARIO_COUNT = 6;

/** \brief Short name of a scenario: "S-ez", "S-d", "M-ez", "M-d", "rows" or "none". */
std::string
getScenarioName (BenchmarkScenario scenario);

/** \brief The scenario of a short name; false if the name is unknown. */
bool
parseScenarioName (const std::string& name, BenchmarkScenario& scenario);

/** \brief Recipe of makeBenchmarkScene(). */
struct BenchmarkSceneOptions
{
  BenchmarkScenario scenario = BenchmarkScenario::SINGLE_EASY;
  /** \brief Seed of everything drawn: products, counts, resting poses, layout, camera, table. */
  std::uint32_t seed = 1;
  /** \brief The camera that will render the scene: objects are placed entirely in its view. */
  PinholeCamera camera;
  /** \brief Instances of each repeated product type in S-ez, S-d, M-ez and M-d: 0 draws the
    * count (2 to 9 with one type, 2 to 6 or 2 to 4 with two or three); 2 to 9 fixes it (at
    * most 6 with two types, 4 with three). 2 gives the paper's pair subset, the scenes in which
    * every repeated type appears exactly twice (190 of its 234 images). Rows and none ignore
    * it. */
  int instances_per_type = 0;
};

/** \brief Build one random frame of a benchmark scenario: products of the catalog resting on a
  * large wood-textured table in front of a wall, seen from 0.7 to 0.95 m, 40 to 65 deg below
  * the horizontal, turned by up to 20 deg about the table's vertical.
  *
  * The scene's objects are the instances of the repeated product types (grouped by type), then
  * the distractors; object i is an instance of product product_ids[i] (its BOP obj_id). No
  * two products in one scene show the same photograph (ProductType::photos), so an object that
  * appears once looks like nothing else. Easy placements keep 40 mm between objects; difficult
  * ones put about three in four objects in contact (0.5 mm) with an object placed before,
  * aligned with it. Background objects: the table (pose = table-to-camera, table frame z up,
  * top at z = 0), then the wall. The same options and catalog give the same scene everywhere;
  * how much of each object is visible is not checked here (render and decide, see
  * pcl_multi_instance_bench_synth).
  * \param[in] options the recipe
  * \param[in] catalog the products, from makeProductCatalog()
  * \param[out] scene the scene; cleared when false is returned
  * \param[out] product_ids per scene object, its product id
  * \return false (with a PCL_ERROR) if the camera, the catalog or instances_per_type is
  * invalid, or no layout was found (not expected with the default camera)
  */
bool
makeBenchmarkScene (const BenchmarkSceneOptions& options,
                    const ProductCatalog& catalog,
                    Scene& scene,
                    std::vector<int>& product_ids);

} // namespace simulation
} // namespace mid
