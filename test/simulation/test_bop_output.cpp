#include "surface_samples.h"
#include "temporary_folder.h"

#include <mid/evaluation/ground_truth.h>
#include <mid/evaluation/object_symmetry.h>
#include <mid/io/organized_cloud_io.h>
#include <mid/io/staged_files.h>
#include <mid/simulation/benchmark_frame.h>
#include <mid/simulation/bop_scene_writer.h>
#include <mid/simulation/scene_renderer.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <pcl/point_types.h>

#include <cmath>
#include <filesystem>
#include <fstream>

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

/** A difficult frame (several products, distractors, contact, occlusion). */
BenchmarkFrame
makeFrame (bool sensor_noise)
{
  BenchmarkFrameOptions options;
  options.scene.scenario = BenchmarkScenario::MULTI_DIFFICULT;
  options.scene.seed = 3;
  options.supersampling = 1;
  options.sensor_noise = sensor_noise;
  BenchmarkFrame frame;
  EXPECT_TRUE (makeBenchmarkFrame (options, catalog(), frame));
  return frame;
}

/** Write one frame as image 0 of scene folder 000000 and commit. */
std::string
writeScene (const mid::test::TemporaryFolder& folder, const BenchmarkFrame& frame)
{
  std::string scene = folder.file ("000000");
  mid::io::StagedFiles files;
  BopSceneWriter writer (scene, files);
  EXPECT_TRUE (
      writer.addFrame (0, frame.frame, frame.scene, frame.product_ids, frame.info));
  EXPECT_TRUE (writer.stageJSON());
  EXPECT_TRUE (files.commit());
  return scene;
}

nlohmann::json
readJson (const std::string& path)
{
  std::ifstream file (path);
  nlohmann::json json;
  file >> json;
  return json;
}

std::string
maskPath (const std::string& scene, std::size_t k)
{
  char name[64];
  std::snprintf (name, sizeof (name), "/mask_visib/000000_%06zu.png", k);
  return scene + name;
}

/** Model-to-camera pose of ground-truth entry k as scene_gt.json says (mm -> m). */
Eigen::Isometry3d
poseFromJson (const nlohmann::json& entry)
{
  const auto r = entry.at ("cam_R_m2c").get<std::vector<double>>();
  const auto t = entry.at ("cam_t_m2c").get<std::vector<double>>();
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  for (std::size_t row = 0; row < 3; ++row) {
    for (std::size_t col = 0; col < 3; ++col)
      pose.linear() (static_cast<Eigen::Index> (row), static_cast<Eigen::Index> (col)) =
          r[3 * row + col];
    pose.translation()[static_cast<Eigen::Index> (row)] = t[row] / 1000.0;
  }
  return pose;
}

cv::Rect
rectFromJson (const nlohmann::json& box)
{
  const auto v = box.get<std::vector<int>>();
  return cv::Rect (v[0], v[1], v[2], v[3]);
}

} // namespace

TEST (SimulationBopOutput, FilesMatchTheRenderedFrame)
{
  const BenchmarkFrame frame = makeFrame (true);
  const mid::test::TemporaryFolder folder;
  const std::string scene = writeScene (folder, frame);
  for (const char* name : {"scene_camera.json",
                           "scene_gt.json",
                           "scene_gt_info.json",
                           "rgb/000000.png",
                           "depth/000000.png",
                           "pcd/000000.pcd"})
    EXPECT_TRUE (std::filesystem::exists (scene + "/" + name)) << name;
  for (const auto& entry : std::filesystem::recursive_directory_iterator (scene))
    EXPECT_EQ (entry.path().string().find (".partial."), std::string::npos);

  const cv::Mat color = cv::imread (scene + "/rgb/000000.png", cv::IMREAD_UNCHANGED);
  EXPECT_EQ (cv::norm (color, frame.frame.color, cv::NORM_INF), 0.0);
  const cv::Mat depth = cv::imread (scene + "/depth/000000.png", cv::IMREAD_UNCHANGED);
  ASSERT_EQ (depth.type(), CV_16UC1);
  const nlohmann::json camera = readJson (scene + "/scene_camera.json").at ("0");
  const double unit_m = camera.at ("depth_scale").get<double>() / 1000.0;
  EXPECT_EQ (camera.at ("cam_K").get<std::vector<double>>(),
             (std::vector<double>{538, 0, 319.5, 0, 538, 239.5, 0, 0, 1}));
  cv::Mat metres;
  depth.convertTo (metres, CV_32F, unit_m);
  const cv::Mat measured = frame.frame.depth > 0.0f;
  EXPECT_EQ (cv::countNonZero (measured != (depth > 0)), 0);
  EXPECT_LE (cv::norm (metres, frame.frame.depth, cv::NORM_INF), 0.5 * unit_m + 1e-6);

  pcl::PointCloud<pcl::PointXYZRGB> cloud;
  ASSERT_TRUE (mid::io::loadOrganizedPCD (scene + "/pcd/000000.pcd", cloud));
  ASSERT_EQ (cloud.width, 640u);
  ASSERT_EQ (cloud.height, 480u);
  for (int v = 0; v < 480; v += 7)
    for (int u = 0; u < 640; u += 7) {
      const auto& point = cloud.at (u, v);
      if (depth.at<std::uint16_t> (v, u) == 0)
        EXPECT_FALSE (std::isfinite (point.z));
      else
        EXPECT_NEAR (point.z, metres.at<float> (v, u), 1e-6);
    }

  // Masks: exactly the instance map; statistics: exactly the masks.
  const nlohmann::json gt = readJson (scene + "/scene_gt.json").at ("0");
  const nlohmann::json info = readJson (scene + "/scene_gt_info.json").at ("0");
  ASSERT_EQ (gt.size(), frame.scene.getObjects().size());
  ASSERT_EQ (info.size(), gt.size());
  for (std::size_t k = 0; k < gt.size(); ++k) {
    SCOPED_TRACE ("object " + std::to_string (k));
    const cv::Mat mask = cv::imread (maskPath (scene, k), cv::IMREAD_UNCHANGED);
    ASSERT_EQ (mask.type(), CV_8UC1);
    EXPECT_EQ (
        cv::countNonZero (mask != (frame.frame.instances == static_cast<int> (k))), 0);
    EXPECT_EQ (gt[k].at ("obj_id").get<int>(), frame.product_ids[k]);
    EXPECT_EQ (info[k].at ("px_count_visib").get<int>(), cv::countNonZero (mask));
    EXPECT_EQ (rectFromJson (info[k].at ("bbox_visib")), cv::boundingRect (mask));
    const int all = info[k].at ("px_count_all").get<int>();
    const int valid = info[k].at ("px_count_valid").get<int>();
    EXPECT_GE (all, cv::countNonZero (mask));
    EXPECT_LE (valid, all);
    EXPECT_GT (valid, 0);
    EXPECT_NEAR (info[k].at ("visib_fract").get<double>(),
                 static_cast<double> (cv::countNonZero (mask)) / all,
                 1e-9);
  }
}

TEST (SimulationBopOutput, SilhouettesAreThoseOfEachObjectRenderedAlone)
{
  const BenchmarkFrame frame = makeFrame (true);
  const auto& objects = frame.scene.getObjects();
  bool some_occluded = false;
  for (std::size_t k = 0; k < objects.size(); ++k) {
    Scene alone;
    alone.addObject (objects[k].shape, objects[k].pose);
    SceneRenderer renderer;
    RenderedFrame single;
    ASSERT_TRUE (renderer.render (alone, single));
    const cv::Mat silhouette = single.instances == 0;
    const cv::Mat visible = frame.frame.instances == static_cast<int> (k);
    const BopInstanceInfo& info = frame.info[k];
    EXPECT_EQ (info.px_count_all, cv::countNonZero (silhouette));
    EXPECT_EQ (info.bbox_obj, cv::boundingRect (silhouette));
    EXPECT_EQ (info.px_count_valid,
               cv::countNonZero (silhouette & (frame.frame.depth > 0.0f)));
    EXPECT_EQ (cv::countNonZero (visible & ~silhouette),
               0); // visible part of the silhouette
    some_occluded = some_occluded || info.visib_fract < 0.95;
  }
  EXPECT_TRUE (some_occluded); // a difficult frame
}

TEST (SimulationBopOutput, PosesPutTheModelsOnTheirMasks)
{
  const BenchmarkFrame frame = makeFrame (false); // exact depth
  const mid::test::TemporaryFolder folder;
  const std::string scene = writeScene (folder, frame);
  const nlohmann::json gt = readJson (scene + "/scene_gt.json").at ("0");
  const nlohmann::json info = readJson (scene + "/scene_gt_info.json").at ("0");
  const PinholeCamera& camera = frame.frame.camera;
  for (std::size_t k = 0; k < gt.size(); ++k) {
    SCOPED_TRACE ("object " + std::to_string (k));
    const Eigen::Isometry3d pose = poseFromJson (gt[k]);
    const ProductType& product = getProduct (catalog(), gt[k].at ("obj_id").get<int>());
    const cv::Mat mask = cv::imread (maskPath (scene, k), cv::IMREAD_UNCHANGED);

    // The model's bounding box corners enclose its whole silhouette (bbox_obj).
    double min_u = 1e9, min_v = 1e9, max_u = -1e9, max_v = -1e9;
    for (int corner = 0; corner < 8; ++corner) {
      const Eigen::Vector3d point =
          0.5 * product.size.cwiseProduct (Eigen::Vector3d ((corner & 1) ? 1 : -1,
                                                            (corner & 2) ? 1 : -1,
                                                            (corner & 4) ? 1 : -1));
      Eigen::Vector2d pixel;
      ASSERT_TRUE (projectPoint (camera, pose * point, pixel));
      min_u = std::min (min_u, pixel.x());
      min_v = std::min (min_v, pixel.y());
      max_u = std::max (max_u, pixel.x());
      max_v = std::max (max_v, pixel.y());
    }
    const cv::Rect box = rectFromJson (info[k].at ("bbox_obj"));
    EXPECT_GE (box.x, min_u - 0.5);
    EXPECT_GE (box.y, min_v - 0.5);
    EXPECT_LE (box.x + box.width - 1, max_u + 0.5);
    EXPECT_LE (box.y + box.height - 1, max_v + 0.5);

    // Every masked pixel, back-projected with its depth, lies on the posed model.
    const Eigen::Isometry3d to_model = pose.inverse();
    int on_surface = 0, masked = 0;
    for (int v = 0; v < mask.rows; ++v)
      for (int u = 0; u < mask.cols; ++u) {
        if (mask.at<std::uint8_t> (v, u) == 0)
          continue;
        ++masked;
        const Eigen::Vector3d point =
            frame.frame.depth.at<float> (v, u) * pixelRay (camera, u, v);
        on_surface +=
            std::abs (product.shape->signedDistance (to_model * point)) < 2e-4;
      }
    EXPECT_GT (masked, 0);
    EXPECT_EQ (on_surface, masked);

    // Model points the camera sees (same depth as rendered there) project onto the mask.
    int seen = 0, on_mask = 0;
    for (const Eigen::Vector3d& model_point : test::sampleSurface (*product.shape)) {
      const Eigen::Vector3d point = pose * model_point;
      Eigen::Vector2d pixel;
      if (!projectPoint (camera, point, pixel))
        continue;
      const int u = static_cast<int> (std::lround (pixel.x()));
      const int v = static_cast<int> (std::lround (pixel.y()));
      if (u < 0 || v < 0 || u >= camera.width || v >= camera.height ||
          std::abs (frame.frame.depth.at<float> (v, u) - point.z()) > 0.002 ||
          (pixel - Eigen::Vector2d (u, v)).norm() > 0.25)
        continue;
      ++seen;
      on_mask += mask.at<std::uint8_t> (v, u) != 0;
    }
    EXPECT_GT (seen, 5);
    EXPECT_GE (on_mask, seen * 95 / 100) << on_mask << " of " << seen;
  }
}

TEST (SimulationBopOutput, RoundTripsThroughTheEvaluationReader)
{
  const BenchmarkFrame frame = makeFrame (true);
  const mid::test::TemporaryFolder folder;
  const std::string scene = writeScene (folder, frame);
  mid::evaluation::GroundTruthScene truth;
  ASSERT_TRUE (mid::evaluation::loadBopScene (scene, truth));
  ASSERT_EQ (truth.size(), 1u);
  const mid::evaluation::GroundTruthFrame& loaded = truth.at (0);
  ASSERT_EQ (loaded.instances.size(), frame.scene.getObjects().size());
  for (std::size_t k = 0; k < loaded.instances.size(); ++k) {
    const auto& instance = loaded.instances[k];
    EXPECT_EQ (instance.object_id, frame.product_ids[k]);
    EXPECT_TRUE (instance.pose.cast<double>().isApprox (
        frame.scene.getObjects()[k].pose.matrix(), 1e-6));
    EXPECT_EQ (instance.visible_pixels, frame.info[k].px_count_visib);
    EXPECT_EQ (instance.bbox_visible, frame.info[k].bbox_visib);
    ASSERT_FALSE (instance.mask_visible.empty());
    EXPECT_EQ (cv::countNonZero (instance.mask_visible !=
                                 (frame.frame.instances == static_cast<int> (k))),
               0);
  }
}

TEST (SimulationBopOutput, ModelsInfoListsEveryProduct)
{
  const nlohmann::json models = nlohmann::json::parse (formatBopModelsInfo (catalog()));
  ASSERT_EQ (models.size(), static_cast<std::size_t> (PRODUCT_COUNT));
  const nlohmann::json& carton = models.at ("1");
  EXPECT_EQ (carton.at ("name"), "juice_carton");
  EXPECT_NEAR (carton.at ("size_z").get<double>(), 200.0, 1e-9);
  EXPECT_NEAR (carton.at ("min_x").get<double>(), -35.0, 1e-9);
  EXPECT_NEAR (carton.at ("diameter").get<double>(),
               std::sqrt (70.0 * 70 * 2 + 200 * 200),
               1e-9);
}

TEST (SimulationBopOutput, ModelsInfoGivesTheEvaluatorEachShapesSymmetries)
{
  const mid::test::TemporaryFolder folder;
  const std::string path = folder.file ("models_info.json");
  std::ofstream (path) << formatBopModelsInfo (catalog());
  mid::evaluation::ObjectSymmetryTable table;
  ASSERT_TRUE (mid::evaluation::loadBopModelSymmetries (path, table));
  ASSERT_EQ (table.size(), static_cast<std::size_t> (PRODUCT_COUNT));
  std::size_t boxes = 0, cylinders = 0;
  for (const ProductType& product : catalog()) {
    const ShapeSymmetries shape = product.shape->getSymmetries();
    const mid::evaluation::ObjectSymmetries& read = table.at (product.id);
    ASSERT_EQ (read.discrete.size(), shape.discrete.size()) << product.shape->getName();
    for (std::size_t i = 0; i < shape.discrete.size(); ++i)
      EXPECT_TRUE (read.discrete[i].isApprox (shape.discrete[i]));
    ASSERT_EQ (read.continuous_axes.size(), shape.continuous_axes.size());
    for (std::size_t i = 0; i < shape.continuous_axes.size(); ++i)
      EXPECT_TRUE (read.continuous_axes[i].isApprox (shape.continuous_axes[i]));
    (shape.continuous_axes.empty() ? boxes : cylinders) += 1;
  }
  // The catalog: six boxes (each with at least its three half turns), a can and a mug.
  EXPECT_EQ (boxes, 6u);
  EXPECT_EQ (cylinders, 2u);
  EXPECT_EQ (table.at (1).discrete.size(),
             7u); // the juice carton's square cross-section
}

TEST (SimulationBopOutput, BadFramesAndEmptyScenesAreRefused)
{
  const BenchmarkFrame frame = makeFrame (true);
  const mid::test::TemporaryFolder folder;
  {
    mid::io::StagedFiles files;
    BopSceneWriter writer (folder.file ("000000"), files);
    EXPECT_FALSE (writer.stageJSON()); // no frame
    std::vector<int> ids = frame.product_ids;
    ids.pop_back();
    EXPECT_FALSE (writer.addFrame (0, frame.frame, frame.scene, ids, frame.info));
    EXPECT_FALSE (
        writer.addFrame (-1, frame.frame, frame.scene, frame.product_ids, frame.info));
    EXPECT_TRUE (
        writer.addFrame (4, frame.frame, frame.scene, frame.product_ids, frame.info));
    EXPECT_FALSE (writer.addFrame (
        4, frame.frame, frame.scene, frame.product_ids, frame.info)); // twice
  } // not committed: nothing but empty folders is left
  for (const auto& entry :
       std::filesystem::recursive_directory_iterator (folder.path()))
    EXPECT_TRUE (entry.is_directory()) << entry.path();
}
