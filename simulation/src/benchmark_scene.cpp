#include "benchmark_layout.h"

#include <mid/simulation/benchmark_scene.h>
#include <mid/simulation/deterministic_random.h>
#include <mid/simulation/procedural_texture.h>
#include <mid/simulation/table_plane.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace mid {
namespace simulation {

namespace {

const char* const kScenarioNames[BENCHMARK_SCENARIO_COUNT] = {
    "S-ez", "S-d", "M-ez", "M-d", "rows", "none"};

/** Stream of DeterministicRandom used by the recipe. */
constexpr std::uint32_t kSceneStream = 23;
/** Compositions drawn before giving up (each with its own layout restarts). */
constexpr int kMaxCompositions = 20;

/** The products whose instances may repeat (those with a photograph), and all products. */
const std::vector<int> kRepeatable = {PRODUCT_JUICE_CARTON,
                                      PRODUCT_COOKIE_BOX,
                                      PRODUCT_SOY_MILK_CAN,
                                      PRODUCT_APPLE_JUICE_SMALL,
                                      PRODUCT_ORANGE_JUICE_LARGE,
                                      PRODUCT_SOY_MILK_CARTON};
const std::vector<int> kAnyProduct = {PRODUCT_JUICE_CARTON,
                                      PRODUCT_COOKIE_BOX,
                                      PRODUCT_SOY_MILK_CAN,
                                      PRODUCT_APPLE_JUICE_SMALL,
                                      PRODUCT_ORANGE_JUICE_LARGE,
                                      PRODUCT_SOY_MILK_CARTON,
                                      PRODUCT_TEA_BOX,
                                      PRODUCT_MUG};

/** Table top (table frame: z up, y away from the camera), its texture, and the wall behind. */
constexpr double kTableSizeX = 2.4, kTableSizeY = 1.8;
constexpr int kTableTextureWidth = 1536, kTableTextureHeight = 1152;
constexpr double kWallY = 1.2, kWallBottom = -0.8, kWallSizeX = 4.0, kWallSizeZ = 2.5;

/** What goes on the table: per object its product and resting orientation (index into the
  * product's rests), repeated products first.
  */
struct Composition
{
  std::vector<int> products;
  std::vector<int> rests;
  /** For ROWS: objects per row (the objects are listed row after row). */
  std::vector<int> row_counts;
  std::vector<double> row_gaps;
};

/** Up to count products drawn from candidates (in random order), skipping any that shows a
  * photograph of one already taken; taken grows by those drawn.
  */
std::vector<int>
drawProducts (const ProductCatalog& catalog,
              std::vector<int> candidates,
              int count,
              DeterministicRandom& random,
              std::vector<int>& taken)
{
  for (std::size_t i = candidates.size(); i > 1; --i)
    std::swap (candidates[i - 1],
               candidates[static_cast<std::size_t> (
                   random.uniformInt (static_cast<int> (i)))]);
  std::set<std::string> photos;
  for (const int id : taken)
    photos.insert (getProduct (catalog, id).photos.begin(),
                   getProduct (catalog, id).photos.end());
  std::vector<int> drawn;
  for (const int id : candidates) {
    if (static_cast<int> (drawn.size()) == count)
      break;
    const ProductType& product = getProduct (catalog, id);
    if (std::find (taken.begin(), taken.end(), id) != taken.end() ||
        std::any_of (
            product.photos.begin(),
            product.photos.end(),
            [&photos] (const std::string& photo) { return photos.count (photo) > 0; }))
      continue;
    drawn.push_back (id);
    taken.push_back (id);
    photos.insert (product.photos.begin(), product.photos.end());
  }
  return drawn;
}

/** A random resting orientation of a product: any, or only the easy ones. */
int
drawRest (const ProductType& product, bool easy_only, DeterministicRandom& random)
{
  std::vector<int> allowed;
  for (std::size_t r = 0; r < product.rests.size(); ++r)
    if (!easy_only || product.rests[r].easy)
      allowed.push_back (static_cast<int> (r));
  if (allowed.empty())
    return 0;
  return allowed[static_cast<std::size_t> (
      random.uniformInt (static_cast<int> (allowed.size())))];
}

/** An integer in [low, high]. */
int
drawCount (int low, int high, DeterministicRandom& random)
{
  return low + random.uniformInt (high - low + 1);
}

/** The products, their counts and resting poses of one scene (`instances_per_type`: see
  * BenchmarkSceneOptions; the count is still drawn when fixed, after the product types, which
  * stay those the drawn scene starts with).
  */
Composition
drawComposition (BenchmarkScenario scenario,
                 int instances_per_type,
                 const ProductCatalog& catalog,
                 DeterministicRandom& random)
{
  Composition composition;
  std::vector<int> taken;
  const auto add = [&] (int id, int count, bool easy_only) {
    for (int i = 0; i < count; ++i) {
      composition.products.push_back (id);
      composition.rests.push_back (
          drawRest (getProduct (catalog, id), easy_only, random));
    }
  };
  const bool single = scenario == BenchmarkScenario::SINGLE_EASY ||
                      scenario == BenchmarkScenario::SINGLE_DIFFICULT;
  const bool easy = scenario == BenchmarkScenario::SINGLE_EASY ||
                    scenario == BenchmarkScenario::MULTI_EASY;
  switch (scenario) {
  case BenchmarkScenario::SINGLE_EASY:
  case BenchmarkScenario::SINGLE_DIFFICULT:
  case BenchmarkScenario::MULTI_EASY:
  case BenchmarkScenario::MULTI_DIFFICULT: {
    const int types = single ? 1 : drawCount (2, 3, random);
    const int most = single ? 9 : (types == 2 ? 6 : 4);
    for (const int id : drawProducts (catalog, kRepeatable, types, random, taken)) {
      const int drawn = drawCount (2, most, random);
      add (id,
           instances_per_type > 0 ? std::min (instances_per_type, most) : drawn,
           easy);
    }
    if (!easy) {
      const int distractors = drawCount (1, single ? 3 : 2, random);
      for (const int id :
           drawProducts (catalog, kAnyProduct, distractors, random, taken))
        add (id, 1, false);
    }
    break;
  }
  case BenchmarkScenario::ROWS: {
    for (const int id :
         drawProducts (catalog, kRepeatable, drawCount (1, 2, random), random, taken)) {
      const int count = drawCount (3, 7, random);
      const int rest = drawRest (getProduct (catalog, id), false, random);
      composition.products.insert (
          composition.products.end(), static_cast<std::size_t> (count), id);
      composition.rests.insert (
          composition.rests.end(), static_cast<std::size_t> (count), rest);
      composition.row_counts.push_back (count);
      composition.row_gaps.push_back (random.uniform (0.005, 0.03));
    }
    break;
  }
  case BenchmarkScenario::NONE:
    for (const int id :
         drawProducts (catalog, kAnyProduct, drawCount (3, 6, random), random, taken))
      add (id, 1, false);
    break;
  }
  return composition;
}

LayoutItem
makeLayoutItem (const ProductType& product, const RestingOrientation& rest)
{
  LayoutItem item;
  item.shape = restingFootprint (product.size, rest.rotation);
  if (!rest.front.isZero()) {
    const Eigen::Vector3d front = rest.rotation * rest.front;
    item.has_front = true;
    item.front_angle = std::atan2 (front.y(), front.x());
  }
  return item;
}

bool
layoutComposition (BenchmarkScenario scenario,
                   const Composition& composition,
                   const ProductCatalog& catalog,
                   const PlacementView& view,
                   DeterministicRandom& random,
                   std::vector<Footprint>& layout)
{
  std::vector<LayoutItem> items;
  for (std::size_t i = 0; i < composition.products.size(); ++i) {
    const ProductType& product = getProduct (catalog, composition.products[i]);
    items.push_back (makeLayoutItem (
        product, product.rests[static_cast<std::size_t> (composition.rests[i])]));
  }
  if (scenario == BenchmarkScenario::ROWS) {
    std::vector<RowSpec> rows;
    std::size_t first = 0;
    for (std::size_t r = 0; r < composition.row_counts.size(); ++r) {
      rows.push_back (
          {items[first], composition.row_counts[r], composition.row_gaps[r]});
      first += static_cast<std::size_t> (composition.row_counts[r]);
    }
    return layoutRows (rows, view, random, layout);
  }
  ScatterStyle style;
  if (scenario == BenchmarkScenario::SINGLE_DIFFICULT ||
      scenario == BenchmarkScenario::MULTI_DIFFICULT) {
    style.gap = 0.005;
    style.touch_probability = 0.75;
  }
  else if (scenario == BenchmarkScenario::NONE)
    style.gap = 0.02;
  return layoutScattered (items, view, style, random, layout);
}

void
addBackground (std::uint32_t seed,
               const Eigen::Isometry3d& table_to_camera,
               Scene& scene)
{
  auto table = std::make_shared<TablePlane> (kTableSizeX, kTableSizeY);
  table->setName ("table");
  table->setExtent (kTableSizeX, kTableSizeY);
  table->setTexture (makeNoiseTexture (kTableTextureWidth,
                                       kTableTextureHeight,
                                       200.0,
                                       24.0,
                                       cv::Vec3b (40, 75, 120),
                                       cv::Vec3b (120, 170, 215),
                                       seed));
  scene.addBackgroundObject (table, table_to_camera);

  // A plastered wall behind the table, facing the camera: its plane's +z along table -y.
  auto wall = std::make_shared<TablePlane> (kWallSizeX, kWallSizeZ);
  wall->setName ("wall");
  wall->setExtent (kWallSizeX, kWallSizeZ);
  wall->setTexture (makeNoiseTexture (512,
                                      320,
                                      80.0,
                                      80.0,
                                      cv::Vec3b (170, 180, 185),
                                      cv::Vec3b (205, 215, 220),
                                      seed + 1));
  Eigen::Isometry3d wall_to_table = Eigen::Isometry3d::Identity();
  wall_to_table.linear() << 1.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0, 1.0, 0.0;
  wall_to_table.translation() =
      Eigen::Vector3d (0.0, kWallY, kWallBottom + 0.5 * kWallSizeZ);
  scene.addBackgroundObject (wall, table_to_camera * wall_to_table);
}

bool
fail (const std::string& message, Scene& scene, std::vector<int>& product_ids)
{
  PCL_ERROR ("[mid::simulation::makeBenchmarkScene] %s\n", message.c_str());
  scene.clear();
  product_ids.clear();
  return false;
}

} // namespace

std::string
getScenarioName (BenchmarkScenario scenario)
{
  return kScenarioNames[static_cast<int> (scenario)];
}

bool
parseScenarioName (const std::string& name, BenchmarkScenario& scenario)
{
  for (int i = 0; i < BENCHMARK_SCENARIO_COUNT; ++i)
    if (name == kScenarioNames[i]) {
      scenario = static_cast<BenchmarkScenario> (i);
      return true;
    }
  return false;
}

bool
makeBenchmarkScene (const BenchmarkSceneOptions& options,
                    const ProductCatalog& catalog,
                    Scene& scene,
                    std::vector<int>& product_ids)
{
  scene.clear();
  product_ids.clear();
  std::string problem;
  if (!validateCamera (options.camera, problem))
    return fail (problem, scene, product_ids);
  if (catalog.size() != static_cast<std::size_t> (PRODUCT_COUNT))
    return fail ("the catalog must hold the products of makeProductCatalog()",
                 scene,
                 product_ids);
  if (options.instances_per_type != 0 &&
      (options.instances_per_type < 2 || options.instances_per_type > 9))
    return fail ("instances_per_type must be 0 (drawn) or 2 to 9, got " +
                     std::to_string (options.instances_per_type),
                 scene,
                 product_ids);

  DeterministicRandom random (options.seed, kSceneStream);
  PlacementView view;
  view.camera = options.camera;
  view.table_to_camera = tableToCamera (random.uniform (0.7, 0.95),
                                        random.uniform (40.0, 65.0),
                                        random.uniform (-20.0, 20.0));
  view.min_x = -0.5;
  view.max_x = 0.5;
  view.min_y = -0.35;
  view.max_y = 0.4;
  Composition composition;
  std::vector<Footprint> layout;
  bool placed = false;
  for (int attempt = 0; attempt < kMaxCompositions && !placed; ++attempt) {
    composition =
        drawComposition (options.scenario, options.instances_per_type, catalog, random);
    placed = layoutComposition (
        options.scenario, composition, catalog, view, random, layout);
  }
  if (!placed)
    return fail ("no layout found for scenario " + getScenarioName (options.scenario) +
                     " with seed " + std::to_string (options.seed),
                 scene,
                 product_ids);
  for (std::size_t i = 0; i < composition.products.size(); ++i) {
    const ProductType& product = getProduct (catalog, composition.products[i]);
    const RestingOrientation& rest =
        product.rests[static_cast<std::size_t> (composition.rests[i])];
    scene.addObject (product.shape,
                     view.table_to_camera * restingPose (layout[i],
                                                         0.5 * layout[i].height,
                                                         rest.rotation));
    product_ids.push_back (product.id);
  }
  addBackground (random.next(), view.table_to_camera, scene);
  return true;
}

} // namespace simulation
} // namespace mid
