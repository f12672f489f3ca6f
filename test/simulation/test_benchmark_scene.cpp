#include "surface_samples.h"

#include <mid/simulation/benchmark_scene.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <vector>

using namespace mid::simulation;

namespace {

const std::string kTextureDir = std::string (MID_TEST_DATA_DIR) + "/textures";
constexpr int kSeeds = 6;

const ProductCatalog&
catalog ()
{
  static const ProductCatalog products = [] {
    ProductCatalog made;
    EXPECT_TRUE (makeProductCatalog (kTextureDir, made));
    return made;
  }();
  return products;
}

std::map<int, int>
countProducts (const std::vector<int>& product_ids)
{
  std::map<int, int> counts;
  for (const int id : product_ids)
    ++counts[id];
  return counts;
}

/** Smallest distance between two objects' surfaces, from points sampled on each. */
double
closestDistance (const SceneObject& a,
                 const std::vector<Eigen::Vector3d>& a_points,
                 const SceneObject& b)
{
  const Eigen::Isometry3d a_to_b = b.pose.inverse() * a.pose;
  double closest = std::numeric_limits<double>::max();
  for (const Eigen::Vector3d& point : a_points)
    closest = std::min (closest, b.shape->signedDistance (a_to_b * point));
  return closest;
}

/** Per pair of objects, the smallest sampled distance between them (symmetric). */
std::vector<std::vector<double>>
pairDistances (const Scene& scene)
{
  const auto& objects = scene.getObjects();
  std::vector<std::vector<Eigen::Vector3d>> samples;
  samples.reserve (objects.size());
  for (const SceneObject& object : objects)
    samples.push_back (test::sampleSurface (*object.shape));
  std::vector<std::vector<double>> distance (objects.size(),
                                             std::vector<double> (objects.size(), 0.0));
  for (std::size_t a = 0; a < objects.size(); ++a)
    for (std::size_t b = a + 1; b < objects.size(); ++b)
      distance[a][b] = distance[b][a] =
          std::min (closestDistance (objects[a], samples[a], objects[b]),
                    closestDistance (objects[b], samples[b], objects[a]));
  return distance;
}

Scene
makeScene (BenchmarkScenario scenario,
           std::uint32_t seed,
           std::vector<int>& product_ids,
           int instances_per_type = 0)
{
  BenchmarkSceneOptions options;
  options.scenario = scenario;
  options.seed = seed;
  options.instances_per_type = instances_per_type;
  Scene scene;
  EXPECT_TRUE (makeBenchmarkScene (options, catalog(), scene, product_ids));
  return scene;
}

} // namespace

TEST (SimulationBenchmarkScene, ScenarioNamesRoundTrip)
{
  for (int i = 0; i < BENCHMARK_SCENARIO_COUNT; ++i) {
    const auto scenario = static_cast<BenchmarkScenario> (i);
    BenchmarkScenario parsed = BenchmarkScenario::NONE;
    ASSERT_TRUE (parseScenarioName (getScenarioName (scenario), parsed));
    EXPECT_EQ (parsed, scenario);
  }
  EXPECT_EQ (getScenarioName (BenchmarkScenario::MULTI_DIFFICULT), "M-d");
  BenchmarkScenario parsed;
  EXPECT_FALSE (parseScenarioName ("S-easy", parsed));
}

TEST (SimulationBenchmarkScene, CatalogProductsHaveRealisticSizesAndDistinctIds)
{
  ASSERT_EQ (catalog().size(), static_cast<std::size_t> (PRODUCT_COUNT));
  std::set<std::string> names;
  for (std::size_t i = 0; i < catalog().size(); ++i) {
    const ProductType& product = catalog()[i];
    EXPECT_EQ (product.id, static_cast<int> (i) + 1);
    names.insert (product.shape->getName());
    EXPECT_GE (product.size.minCoeff(), 0.04) << product.shape->getName();
    EXPECT_LE (product.size.maxCoeff(), 0.25) << product.shape->getName();
    ASSERT_FALSE (product.rests.empty());
    EXPECT_TRUE (product.rests.front().easy);
    for (const RestingOrientation& rest : product.rests)
      EXPECT_TRUE ((rest.rotation * rest.rotation.transpose())
                       .isApprox (Eigen::Matrix3d::Identity(), 1e-12));
  }
  EXPECT_EQ (names.size(), catalog().size());
  EXPECT_EQ (catalog()[0].shape->getName(), "juice_carton");
}

TEST (SimulationBenchmarkScene, CompositionFollowsTheScenario)
{
  for (int s = 0; s < BENCHMARK_SCENARIO_COUNT; ++s) {
    const auto scenario = static_cast<BenchmarkScenario> (s);
    for (std::uint32_t seed = 1; seed <= kSeeds; ++seed) {
      std::vector<int> ids;
      const Scene scene = makeScene (scenario, seed, ids);
      SCOPED_TRACE (getScenarioName (scenario) + " seed " + std::to_string (seed));
      ASSERT_EQ (ids.size(), scene.getObjects().size());
      ASSERT_EQ (scene.getBackgroundObjects().size(), 2u); // table, wall
      int repeated = 0, once = 0, smallest = 100, largest = 0;
      std::set<std::string> photos;
      std::size_t photo_count = 0;
      for (const auto& [id, count] : countProducts (ids)) {
        ASSERT_GE (id, 1);
        ASSERT_LE (id, PRODUCT_COUNT);
        (count >= 2 ? repeated : once) += 1;
        if (count >= 2) {
          smallest = std::min (smallest, count);
          largest = std::max (largest, count);
        }
        photos.insert (getProduct (catalog(), id).photos.begin(),
                       getProduct (catalog(), id).photos.end());
        photo_count += getProduct (catalog(), id).photos.size();
      }
      // No photograph on two products: what appears once looks like nothing else.
      EXPECT_EQ (photos.size(), photo_count);
      for (std::size_t i = 0; i < ids.size(); ++i)
        EXPECT_EQ (scene.getObjects()[i].shape, getProduct (catalog(), ids[i]).shape);
      // Repeated products come first, grouped.
      for (std::size_t i = 1; i < ids.size(); ++i) {
        if (ids[i] != ids[i - 1]) {
          for (std::size_t j = i; j < ids.size(); ++j)
            EXPECT_NE (ids[j], ids[i - 1]);
        }
      }
      switch (scenario) {
      case BenchmarkScenario::SINGLE_EASY:
      case BenchmarkScenario::SINGLE_DIFFICULT:
        EXPECT_EQ (repeated, 1);
        EXPECT_GE (smallest, 2);
        EXPECT_LE (largest, 9);
        if (scenario == BenchmarkScenario::SINGLE_EASY)
          EXPECT_EQ (once, 0);
        else {
          EXPECT_GE (once, 1);
          EXPECT_LE (once, 3);
        }
        break;
      case BenchmarkScenario::MULTI_EASY:
      case BenchmarkScenario::MULTI_DIFFICULT:
        EXPECT_GE (repeated, 2);
        EXPECT_LE (repeated, 3);
        EXPECT_GE (smallest, 2);
        EXPECT_LE (largest, repeated == 2 ? 6 : 4);
        EXPECT_EQ (once == 0, scenario == BenchmarkScenario::MULTI_EASY);
        EXPECT_LE (once, 2);
        break;
      case BenchmarkScenario::ROWS:
        EXPECT_GE (repeated, 1);
        EXPECT_LE (repeated, 2);
        EXPECT_GE (smallest, 3);
        EXPECT_LE (largest, 7);
        EXPECT_EQ (once, 0);
        break;
      case BenchmarkScenario::NONE:
        EXPECT_EQ (repeated, 0);
        EXPECT_GE (once, 3);
        EXPECT_LE (once, 6);
        break;
      }
    }
  }
}

TEST (SimulationBenchmarkScene, ObjectsRestOnTheTableApartOrTouchingNeverInside)
{
  int difficult_frames = 0, frames_with_contact = 0;
  for (int s = 0; s < BENCHMARK_SCENARIO_COUNT; ++s) {
    const auto scenario = static_cast<BenchmarkScenario> (s);
    const bool easy = scenario == BenchmarkScenario::SINGLE_EASY ||
                      scenario == BenchmarkScenario::MULTI_EASY;
    const bool difficult = scenario == BenchmarkScenario::SINGLE_DIFFICULT ||
                           scenario == BenchmarkScenario::MULTI_DIFFICULT;
    for (std::uint32_t seed = 1; seed <= 3; ++seed) {
      std::vector<int> ids;
      const Scene scene = makeScene (scenario, seed, ids);
      SCOPED_TRACE (getScenarioName (scenario) + " seed " + std::to_string (seed));
      const SceneObject& table = scene.getBackgroundObjects()[0];
      for (const SceneObject& object : scene.getObjects()) {
        const Eigen::Isometry3d to_table = table.pose.inverse() * object.pose;
        double lowest = std::numeric_limits<double>::max();
        for (const Eigen::Vector3d& point : test::sampleSurface (*object.shape))
          lowest = std::min (lowest, table.shape->signedDistance (to_table * point));
        EXPECT_GT (lowest, -1e-9); // resting on it, not sunk in
        EXPECT_LT (lowest, 1e-3);
      }
      const auto distance = pairDistances (scene);
      double closest = std::numeric_limits<double>::max();
      for (std::size_t a = 0; a < distance.size(); ++a)
        for (std::size_t b = a + 1; b < distance.size(); ++b) {
          EXPECT_GT (distance[a][b], 1e-4) << "objects " << a << " and " << b;
          closest = std::min (closest, distance[a][b]);
        }
      if (easy) {
        EXPECT_GT (closest, 0.035);
      }
      if (difficult) {
        ++difficult_frames;
        frames_with_contact += closest < 0.002 ? 1 : 0;
      }
    }
  }
  // Difficult frames put objects in contact (0.5 mm apart) nearly always.
  EXPECT_GE (frames_with_contact, difficult_frames - 1);
}

TEST (SimulationBenchmarkScene, RowsAreRegularWithOneOrientation)
{
  for (std::uint32_t seed = 1; seed <= kSeeds; ++seed) {
    std::vector<int> ids;
    const Scene scene = makeScene (BenchmarkScenario::ROWS, seed, ids);
    const auto& objects = scene.getObjects();
    std::size_t first = 0;
    while (first < ids.size()) {
      std::size_t end = first;
      while (end < ids.size() && ids[end] == ids[first])
        ++end;
      ASSERT_GE (end - first, 3u);
      const Eigen::Vector3d step =
          objects[first + 1].pose.translation() - objects[first].pose.translation();
      for (std::size_t i = first + 1; i < end; ++i) {
        EXPECT_TRUE (
            objects[i].pose.linear().isApprox (objects[first].pose.linear(), 1e-12));
        const Eigen::Vector3d gap =
            objects[i].pose.translation() - objects[i - 1].pose.translation();
        EXPECT_LT ((gap - step).norm(), 1e-9) << "seed " << seed << " object " << i;
      }
      first = end;
    }
  }
}

TEST (SimulationBenchmarkScene, SameSeedSameSceneOtherSeedOtherScene)
{
  std::vector<int> ids_a, ids_b, ids_c;
  const Scene a = makeScene (BenchmarkScenario::MULTI_DIFFICULT, 11, ids_a);
  const Scene b = makeScene (BenchmarkScenario::MULTI_DIFFICULT, 11, ids_b);
  const Scene c = makeScene (BenchmarkScenario::MULTI_DIFFICULT, 12, ids_c);
  ASSERT_EQ (ids_a, ids_b);
  for (std::size_t i = 0; i < ids_a.size(); ++i)
    EXPECT_TRUE (a.getObjects()[i].pose.isApprox (b.getObjects()[i].pose, 0.0));
  EXPECT_TRUE (a.getBackgroundObjects()[0].pose.isApprox (
      b.getBackgroundObjects()[0].pose, 0.0));
  EXPECT_FALSE (a.getBackgroundObjects()[0].pose.isApprox (
      c.getBackgroundObjects()[0].pose, 1e-3));
}

TEST (SimulationBenchmarkScene, FixedCopiesPerTypeGiveThePairSubset)
{
  for (const auto scenario : {BenchmarkScenario::SINGLE_EASY,
                              BenchmarkScenario::SINGLE_DIFFICULT,
                              BenchmarkScenario::MULTI_EASY,
                              BenchmarkScenario::MULTI_DIFFICULT})
    for (std::uint32_t seed = 1; seed <= kSeeds; ++seed) {
      SCOPED_TRACE (getScenarioName (scenario) + " seed " + std::to_string (seed));
      for (const int copies : {2, 5}) {
        std::vector<int> ids;
        const Scene scene = makeScene (scenario, seed, ids, copies);
        ASSERT_EQ (ids.size(), scene.getObjects().size());
        const std::map<int, int> counts = countProducts (ids);
        const auto once = std::count_if (
            counts.begin(), counts.end(), [] (const auto& c) { return c.second == 1; });
        const auto repeated = static_cast<long> (counts.size()) - once;
        // Five copies of each of three types would leave the drawn range: 4 at most.
        for (const auto& [id, count] : counts)
          if (count > 1) {
            EXPECT_EQ (count, copies == 5 && repeated == 3 ? 4 : copies) << id;
          }
        const bool single = scenario == BenchmarkScenario::SINGLE_EASY ||
                            scenario == BenchmarkScenario::SINGLE_DIFFICULT;
        EXPECT_EQ (repeated == 1, single);
        EXPECT_EQ (once == 0,
                   scenario == BenchmarkScenario::SINGLE_EASY ||
                       scenario == BenchmarkScenario::MULTI_EASY);
      }
    }
  // Rows and none ignore the setting.
  std::vector<int> drawn, fixed;
  makeScene (BenchmarkScenario::ROWS, 3, drawn);
  makeScene (BenchmarkScenario::ROWS, 3, fixed, 2);
  EXPECT_EQ (drawn, fixed);
}

TEST (SimulationBenchmarkScene, RefusesAnInvalidCopyCount)
{
  for (const int copies : {-1, 1, 10}) {
    BenchmarkSceneOptions options;
    options.instances_per_type = copies;
    std::vector<int> ids;
    Scene scene = makeScene (BenchmarkScenario::SINGLE_EASY, 1, ids);
    EXPECT_FALSE (makeBenchmarkScene (options, catalog(), scene, ids)) << copies;
    EXPECT_TRUE (scene.getObjects().empty());
    EXPECT_TRUE (ids.empty());
  }
}

TEST (SimulationBenchmarkScene, RefusesAnIncompleteCatalog)
{
  BenchmarkSceneOptions options;
  ProductCatalog partial (catalog().begin(), catalog().begin() + 3);
  Scene scene;
  std::vector<int> ids;
  EXPECT_FALSE (makeBenchmarkScene (options, partial, scene, ids));
  EXPECT_TRUE (scene.getObjects().empty());
  options.camera.fx = 0.0;
  EXPECT_FALSE (makeBenchmarkScene (options, catalog(), scene, ids));
}
