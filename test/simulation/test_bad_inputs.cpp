#include "simulation_test_utils.h"

#include <mid/simulation/cylinder_shape.h>
#include <mid/simulation/frame_io.h>
#include <mid/simulation/scene_renderer.h>
#include <mid/simulation/sensor_model.h>
#include <mid/simulation/tabletop_scene.h>
#include <mid/simulation/texture.h>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <pcl/point_types.h>

#include <limits>

using namespace mid::simulation;
using mid::simulation::test::makeColoredBox;
using mid::simulation::test::makePose;

namespace {

/** A frame with content, to check that a failed call clears it. */
RenderedFrame
makeFilledFrame ()
{
  Scene scene;
  scene.addObject (makeColoredBox (0.1, 0.1, 0.1),
                   makePose (Eigen::Vector3d (0.0, 0.0, 1.0)));
  SceneRenderer renderer;
  RenderedFrame frame;
  EXPECT_TRUE (renderer.render (scene, frame));
  return frame;
}

bool
isCleared (const RenderedFrame& frame)
{
  return frame.color.empty() && frame.depth.empty() && frame.instances.empty() &&
         frame.normals.empty() && frame.instance_stats.empty();
}

/** Render a scene holding only the given object; expect failure and cleared output. */
void
expectRenderFails (
    const Shape::ConstPtr& shape,
    const Eigen::Isometry3d& pose = makePose (Eigen::Vector3d (0.0, 0.0, 1.0)))
{
  Scene scene;
  scene.addObject (shape, pose);
  SceneRenderer renderer;
  RenderedFrame frame = makeFilledFrame();
  EXPECT_FALSE (renderer.render (scene, frame));
  EXPECT_TRUE (isCleared (frame));
}

} // namespace

TEST (SimulationBadInput, EmptyOrWrongTextureIsRefused)
{
  auto box = makeColoredBox (0.1, 0.1, 0.1);
  box->setFaceTexture (BoxShape::POS_Y, cv::Mat());
  expectRenderFails (box);
  box->setFaceTexture (BoxShape::POS_Y, cv::Mat (4, 4, CV_32FC3));
  expectRenderFails (box);
  auto can = std::make_shared<CylinderShape> (0.03, 0.1);
  expectRenderFails (can); // no texture at all
  auto table = std::make_shared<TablePlane> (0.5, 0.5);
  expectRenderFails (table);
  std::string problem;
  EXPECT_FALSE (box->validate (problem));
  EXPECT_NE (problem.find ("+y"), std::string::npos) << problem;
}

TEST (SimulationBadInput, NonPositiveSizesAreRefused)
{
  expectRenderFails (makeColoredBox (0.1, 0.0, 0.1));
  expectRenderFails (makeColoredBox (-0.1, 0.1, 0.1));
  expectRenderFails (
      makeColoredBox (0.1, 0.1, std::numeric_limits<double>::quiet_NaN()));
  auto can = std::make_shared<CylinderShape> (0.0, 0.1);
  can->setTexture (makeUniformTexture (cv::Vec3b (1, 2, 3)));
  expectRenderFails (can);
  can->setRadius (0.03);
  can->setHeight (-1.0);
  expectRenderFails (can);
  auto table = std::make_shared<TablePlane> (0.0, 0.5);
  table->setTexture (makeUniformTexture (cv::Vec3b (1, 2, 3)));
  expectRenderFails (table);
  table->setTileSize (0.5, 0.5);
  table->setExtent (-1.0, 1.0);
  expectRenderFails (table);
}

TEST (SimulationBadInput, BadCameraPoseOrParametersAreRefused)
{
  Scene scene;
  scene.addObject (makeColoredBox (0.1, 0.1, 0.1),
                   makePose (Eigen::Vector3d (0.0, 0.0, 1.0)));
  SceneRenderer renderer;
  RenderedFrame frame = makeFilledFrame();

  PinholeCamera camera;
  camera.width = 0;
  renderer.setCamera (camera);
  EXPECT_FALSE (renderer.render (scene, frame));
  EXPECT_TRUE (isCleared (frame));
  camera = PinholeCamera();
  camera.fy = 0.0;
  renderer.setCamera (camera);
  EXPECT_FALSE (renderer.render (scene, frame));
  renderer.setCamera (PinholeCamera());

  renderer.setAmbient (1.5);
  EXPECT_FALSE (renderer.render (scene, frame));
  renderer.setAmbient (0.5);
  renderer.setSupersampling (0);
  EXPECT_FALSE (renderer.render (scene, frame));
  renderer.setSupersampling (1);
  renderer.setLightDirection (Eigen::Vector3d::Zero());
  EXPECT_FALSE (renderer.render (scene, frame));
  renderer.setLightDirection (Eigen::Vector3d::UnitZ());
  EXPECT_TRUE (renderer.render (scene, frame));

  // A scaled (non-rigid) pose, and a missing shape.
  Eigen::Isometry3d scaled = makePose (Eigen::Vector3d (0.0, 0.0, 1.0));
  scaled.linear() *= 2.0;
  expectRenderFails (makeColoredBox (0.1, 0.1, 0.1), scaled);
  expectRenderFails (nullptr);
}

TEST (SimulationBadInput, SensorModelAndFrameChecks)
{
  const RenderedFrame exact = makeFilledFrame();
  RenderedFrame output = makeFilledFrame();
  SensorModel model;
  model.noise_sigma_base = -1.0;
  EXPECT_FALSE (applySensorModel (exact, model, 1, output));
  EXPECT_TRUE (isCleared (output));
  model = SensorModel();
  model.random_dropout = 2.0;
  EXPECT_FALSE (applySensorModel (exact, model, 1, output));
  model = SensorModel();
  model.hole_count = 3; // radius left at 0
  EXPECT_FALSE (applySensorModel (exact, model, 1, output));
  model = SensorModel();
  model.image_blur_sigma = std::numeric_limits<double>::infinity();
  EXPECT_FALSE (applySensorModel (exact, model, 1, output));
  std::string problem;
  EXPECT_TRUE (validateSensorModel (kinectSensorModel(), problem)) << problem;

  // An empty frame, and the incidence angle without normals.
  EXPECT_FALSE (applySensorModel (RenderedFrame(), SensorModel(), 1, output));
  RenderedFrame no_normals = exact;
  no_normals.normals.release();
  model = SensorModel();
  model.max_incidence_angle = 70.0;
  EXPECT_FALSE (applySensorModel (no_normals, model, 1, output));

  pcl::PointCloud<pcl::PointXYZRGB> cloud;
  cloud.resize (3);
  EXPECT_FALSE (frameToCloud (RenderedFrame(), 0.001, cloud));
  EXPECT_TRUE (cloud.empty());
  EXPECT_FALSE (frameToCloud (exact, -1.0, cloud));
  // A frame without any depth has no usable point.
  Scene empty;
  RenderedFrame nothing;
  ASSERT_TRUE (SceneRenderer().render (empty, nothing));
  EXPECT_FALSE (frameToCloud (nothing, 0.001, cloud));
}

TEST (SimulationBadInput, MissingTexturesAndBadRecipes)
{
  cv::Mat texture (2, 2, CV_8UC3);
  EXPECT_FALSE (loadTexture ("/nonexistent/texture.png", texture));
  EXPECT_TRUE (texture.empty());

  Scene scene;
  scene.addObject (makeColoredBox (0.1, 0.1, 0.1),
                   makePose (Eigen::Vector3d (0.0, 0.0, 1.0)));
  TabletopSceneOptions options;
  EXPECT_FALSE (makeTabletopScene (options, "/nonexistent", scene));
  EXPECT_TRUE (scene.getObjects().empty());
  const std::string textures = std::string (MID_TEST_DATA_DIR) + "/textures";
  options.instances = 0;
  EXPECT_FALSE (makeTabletopScene (options, textures, scene));
  options.instances = 11;
  EXPECT_FALSE (makeTabletopScene (options, textures, scene));
  options.instances = 3;
  options.distractors = 3;
  EXPECT_FALSE (makeTabletopScene (options, textures, scene));
  options.distractors = 2;
  options.camera_distance = 0.0;
  EXPECT_FALSE (makeTabletopScene (options, textures, scene));
  EXPECT_TRUE (scene.getObjects().empty());
}
