#include <mid/simulation/benchmark_frame.h>
#include <mid/simulation/deterministic_random.h>
#include <mid/simulation/scene_renderer.h>
#include <mid/simulation/sensor_model.h>

#include <pcl/console/print.h>

#include <algorithm>

namespace mid {
namespace simulation {

namespace {

/** Scenes drawn before giving up, and the stream that derives the next seed. */
constexpr int kMaxScenes = 100;
constexpr std::uint32_t kRetryStream = 29;

bool
fail (const std::string& message, BenchmarkFrame& result)
{
  PCL_ERROR ("[mid::simulation::makeBenchmarkFrame] %s\n", message.c_str());
  result = BenchmarkFrame();
  return false;
}

bool
visibleEnough (const std::vector<BopInstanceInfo>& info,
               double min_fraction,
               int min_pixels)
{
  return std::all_of (info.begin(),
                      info.end(),
                      [min_fraction, min_pixels] (const BopInstanceInfo& entry) {
                        return entry.visib_fract >= min_fraction &&
                               entry.px_count_visib >= min_pixels;
                      });
}

} // namespace

double
getMinimumVisibleFraction (BenchmarkScenario scenario)
{
  switch (scenario) {
  case BenchmarkScenario::SINGLE_EASY:
  case BenchmarkScenario::MULTI_EASY:
    return 0.75;
  case BenchmarkScenario::SINGLE_DIFFICULT:
  case BenchmarkScenario::MULTI_DIFFICULT:
    return 0.25;
  case BenchmarkScenario::ROWS:
  case BenchmarkScenario::NONE:
    break;
  }
  return 0.3;
}

bool
makeBenchmarkFrame (const BenchmarkFrameOptions& options,
                    const ProductCatalog& catalog,
                    BenchmarkFrame& result)
{
  result = BenchmarkFrame();
  const double min_fraction = options.min_visible_fraction >= 0.0
                                  ? options.min_visible_fraction
                                  : getMinimumVisibleFraction (options.scene.scenario);
  if (min_fraction > 1.0 || options.min_visible_pixels < 0)
    return fail ("the minimum visible share must be at most 1 and the minimum visible "
                 "pixels not negative",
                 result);
  SceneRenderer renderer;
  renderer.setCamera (options.scene.camera);
  BenchmarkSceneOptions scene_options = options.scene;
  for (int attempt = 0; attempt < kMaxScenes; ++attempt) {
    if (attempt > 0)
      scene_options.seed =
          DeterministicRandom (scene_options.seed, kRetryStream).next();
    if (!makeBenchmarkScene (scene_options, catalog, result.scene, result.product_ids))
      return fail ("no scene", result);
    // Visibility first, with one ray per pixel: the instance map does not depend on the
    // colour supersampling.
    renderer.setSupersampling (1);
    if (!renderer.render (result.scene, result.frame) ||
        !computeBopInstanceInfo (result.scene, result.frame, result.info))
      return fail ("the scene cannot be rendered", result);
    if (!visibleEnough (result.info, min_fraction, options.min_visible_pixels))
      continue;
    renderer.setSupersampling (options.supersampling);
    if (options.supersampling != 1 && !renderer.render (result.scene, result.frame))
      return fail ("the scene cannot be rendered", result);
    if (options.sensor_noise &&
        !applySensorModel (
            result.frame, kinectSensorModel(), scene_options.seed, result.frame))
      return fail ("the sensor model failed", result);
    // px_count_valid counts the measured depth.
    if (!computeBopInstanceInfo (result.scene, result.frame, result.info))
      return fail ("the scene cannot be measured", result);
    result.seed = scene_options.seed;
    return true;
  }
  return fail ("no scene of scenario " + getScenarioName (options.scene.scenario) +
                   " with seed " + std::to_string (options.scene.seed) +
                   " shows every object well enough",
               result);
}

} // namespace simulation
} // namespace mid
