#pragma once

#include <mid/simulation/benchmark_scene.h>
#include <mid/simulation/bop_ground_truth.h>
#include <mid/simulation/rendered_frame.h>

#include <cstdint>
#include <vector>

namespace mid {
namespace simulation {

/** \brief Recipe of makeBenchmarkFrame(). */
struct BenchmarkFrameOptions
{
  /** \brief The scene: scenario, seed, camera. */
  BenchmarkSceneOptions scene;
  /** \brief Colour rays per pixel along each axis (SceneRenderer::setSupersampling()). */
  int supersampling = 3;
  /** \brief Apply kinectSensorModel() (seeded with the frame's seed); exact depth otherwise. */
  bool sensor_noise = true;
  /** \brief Smallest visible share (BopInstanceInfo::visib_fract) of every object, or a
    * negative value for getMinimumVisibleFraction() of the scenario.
    */
  double min_visible_fraction = -1.0;
  /** \brief Smallest number of visible pixels of every object. */
  int min_visible_pixels = 300;
};

/** \brief One frame of the benchmark with everything its ground truth needs. */
struct BenchmarkFrame
{
  Scene scene;
  /** \brief BOP obj_id (product id) of each scene object. */
  std::vector<int> product_ids;
  /** \brief The frame as measured (colour, depth after the sensor model) with the exact
    * instance map. */
  RenderedFrame frame;
  /** \brief computeBopInstanceInfo() of the frame. */
  std::vector<BopInstanceInfo> info;
  /** \brief Seed of the scene that was kept (see makeBenchmarkFrame()). */
  std::uint32_t seed = 0;
};

/** \brief Smallest visible share of an object a scenario allows: 0.75 in the easy ones (apart,
  * nearly unoccluded), 0.25 in the difficult ones, 0.3 in rows and none.
  */
double
getMinimumVisibleFraction (BenchmarkScenario scenario);

/** \brief Make, render and measure one benchmark frame in which every object is visible
  * enough: the scene of options.scene is rejected when an object shows less than the minimum
  * share or pixels, and the next one is drawn (seed s becomes DeterministicRandom (s, 29)
  * .next ()), up to 100 scenes. Deterministic for the options.
  * \param[in] options the recipe
  * \param[in] catalog the products, from makeProductCatalog()
  * \param[out] result the frame; cleared when false is returned
  * \return false (with a PCL_ERROR) on an invalid option or when no scene qualified
  */
bool
makeBenchmarkFrame (const BenchmarkFrameOptions& options,
                    const ProductCatalog& catalog,
                    BenchmarkFrame& result);

} // namespace simulation
} // namespace mid
