#include <mid/simulation/benchmark_frame.h>
#include <mid/simulation/frame_preview.h>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

using namespace mid::simulation;

namespace {

const std::string kTextureDir = std::string (MID_TEST_DATA_DIR) + "/textures";

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

BenchmarkFrameOptions
quickOptions (BenchmarkScenario scenario, std::uint32_t seed)
{
  BenchmarkFrameOptions options;
  options.scene.scenario = scenario;
  options.scene.seed = seed;
  options.supersampling = 1;
  return options;
}

} // namespace

TEST (SimulationBenchmarkFrame, EveryObjectIsVisibleEnoughInEveryScenario)
{
  for (int s = 0; s < BENCHMARK_SCENARIO_COUNT; ++s) {
    const auto scenario = static_cast<BenchmarkScenario> (s);
    for (std::uint32_t seed = 1; seed <= 2; ++seed) {
      SCOPED_TRACE (getScenarioName (scenario) + " seed " + std::to_string (seed));
      BenchmarkFrame frame;
      ASSERT_TRUE (
          makeBenchmarkFrame (quickOptions (scenario, seed), catalog(), frame));
      ASSERT_EQ (frame.info.size(), frame.scene.getObjects().size());
      ASSERT_EQ (frame.product_ids.size(), frame.info.size());
      for (std::size_t k = 0; k < frame.info.size(); ++k) {
        EXPECT_GE (frame.info[k].visib_fract, getMinimumVisibleFraction (scenario));
        EXPECT_GE (frame.info[k].px_count_visib, 300);
        EXPECT_EQ (frame.info[k].px_count_visib,
                   cv::countNonZero (frame.frame.instances == static_cast<int> (k)));
      }
      // The sensor model removed some depth, never the instance map's truth.
      EXPECT_LT (cv::countNonZero (frame.frame.depth > 0.0f), 640 * 480);
    }
  }
}

TEST (SimulationBenchmarkFrame, SameOptionsSameFrame)
{
  BenchmarkFrame a, b, c;
  ASSERT_TRUE (makeBenchmarkFrame (
      quickOptions (BenchmarkScenario::SINGLE_DIFFICULT, 5), catalog(), a));
  ASSERT_TRUE (makeBenchmarkFrame (
      quickOptions (BenchmarkScenario::SINGLE_DIFFICULT, 5), catalog(), b));
  ASSERT_TRUE (makeBenchmarkFrame (
      quickOptions (BenchmarkScenario::SINGLE_DIFFICULT, 6), catalog(), c));
  EXPECT_EQ (a.seed, b.seed);
  EXPECT_EQ (cv::norm (a.frame.color, b.frame.color, cv::NORM_INF), 0.0);
  EXPECT_EQ (cv::norm (a.frame.depth, b.frame.depth, cv::NORM_INF), 0.0);
  EXPECT_GT (cv::norm (a.frame.color, c.frame.color, cv::NORM_L1), 0.0);
}

TEST (SimulationBenchmarkFrame, ImpossibleVisibilityFailsCleanly)
{
  BenchmarkFrameOptions options = quickOptions (BenchmarkScenario::NONE, 1);
  options.min_visible_fraction = 2.0;
  BenchmarkFrame frame;
  EXPECT_FALSE (makeBenchmarkFrame (options, catalog(), frame));
  EXPECT_TRUE (frame.scene.getObjects().empty());
  EXPECT_TRUE (frame.frame.color.empty());
}

TEST (SimulationBenchmarkFrame, PreviewShowsColourDepthAndMasksSideBySide)
{
  BenchmarkFrame frame;
  ASSERT_TRUE (makeBenchmarkFrame (
      quickOptions (BenchmarkScenario::MULTI_EASY, 1), catalog(), frame));
  const cv::Mat preview = makeFramePreview (frame.frame);
  ASSERT_EQ (preview.size(), cv::Size (3 * 640, 480));
  ASSERT_EQ (preview.type(), CV_8UC3);
  EXPECT_EQ (cv::norm (preview.colRange (0, 640), frame.frame.color, cv::NORM_INF),
             0.0);
  const cv::Mat depth = preview.colRange (640, 1280),
                masks = preview.colRange (1280, 1920);
  for (int v = 0; v < 480; v += 5)
    for (int u = 0; u < 640; u += 5) {
      const bool measured = frame.frame.depth.at<float> (v, u) > 0.0f;
      EXPECT_EQ (depth.at<cv::Vec3b> (v, u) != cv::Vec3b (0, 0, 0), measured);
      const int id = frame.frame.instances.at<int> (v, u);
      EXPECT_EQ (masks.at<cv::Vec3b> (v, u) != cv::Vec3b (0, 0, 0), id >= 0);
    }
  // Two instances, two colours.
  std::vector<cv::Vec3b> colors;
  for (int id = 0; id < 2; ++id) {
    cv::Point where;
    cv::minMaxLoc (frame.frame.instances == id, nullptr, nullptr, nullptr, &where);
    colors.push_back (masks.at<cv::Vec3b> (where));
  }
  EXPECT_NE (colors[0], colors[1]);

  const cv::Mat half = makeFramePreview (frame.frame, 0.5);
  EXPECT_EQ (half.size(), cv::Size (960, 240));
  EXPECT_EQ (stackPreviews ({half, half}).size(), cv::Size (960, 480));
  EXPECT_TRUE (stackPreviews ({half, preview}).empty());
  EXPECT_TRUE (makeFramePreview (frame.frame, 0.0).empty());
  EXPECT_TRUE (makeFramePreview (RenderedFrame()).empty());
}
