// The shared surface of annotated instances, on depth images ray-cast from square patches of
// a model frame under known poses: which cubes two copies both show, and from which views.

#include "temporary_folder.h"

#include <mid/evaluation/ground_truth.h>
#include <mid/evaluation/shared_surface.h>

#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <cmath>
#include <fstream>

namespace {

using mid::evaluation::GroundTruthFrame;
using mid::evaluation::GroundTruthInstance;

constexpr int kWidth = 640, kHeight = 480;
constexpr float kCell = 0.01f;

Eigen::Matrix3f
intrinsics ()
{
  Eigen::Matrix3f k;
  k << 538.0f, 0.0f, 319.5f, 0.0f, 538.0f, 239.5f, 0.0f, 0.0f, 1.0f;
  return k;
}

/** A pose 0.8 m in front of the camera, `x` metres to the side, its model z axis towards the
  * camera, then turned by `tilt` degrees about the camera's x axis.
  */
Eigen::Matrix4f
pose (float x, float tilt)
{
  Eigen::Matrix4f p = Eigen::Matrix4f::Identity();
  p.topLeftCorner<3, 3>() =
      (Eigen::AngleAxisf (tilt * static_cast<float> (M_PI) / 180.0f,
                          Eigen::Vector3f::UnitX()) *
       Eigen::AngleAxisf (static_cast<float> (M_PI), Eigen::Vector3f::UnitX()))
          .toRotationMatrix();
  p.topRightCorner<3, 1>() = Eigen::Vector3f (x, 0.0f, 0.8f);
  return p;
}

/** The grey level of a patch at model point (x, y): a checkerboard of 4 mm squares (60 and
  * 200) where x < 0, plain 128 elsewhere, unless the whole patch is plain.
  */
unsigned char
patchGrey (const Eigen::Vector3f& model, bool printed)
{
  if (!printed || model.x() >= 0.0f)
    return 128;
  const auto square = [] (float v) {
    return static_cast<int> (std::floor (v / 0.004f));
  };
  return (square (model.x()) + square (model.y())) % 2 == 0 ? 60 : 200;
}

/** The scene: instances that each show one square patch of their model frame, 100 x 100 mm at
  * height z_model (the patch faces +z), ray-cast into one depth image, one grey image (printed
  * patches: patchGrey()) and their masks.
  */
struct PatchScene
{
  GroundTruthFrame frame;
  cv::Mat depth = cv::Mat::zeros (kHeight, kWidth, CV_32FC1);
  cv::Mat grey = cv::Mat (kHeight, kWidth, CV_8UC1, cv::Scalar (128));

  void
  add (int type,
       const Eigen::Matrix4f& model_to_camera,
       float z_model,
       bool printed = true)
  {
    GroundTruthInstance instance = annotation (type, model_to_camera);
    castPatch (instance,
               model_to_camera,
               z_model,
               -0.05f,
               0.05f,
               [printed] (const auto& model) { return patchGrey (model, printed); });
    frame.instances.push_back (instance);
  }

private:
  static GroundTruthInstance
  annotation (int type, const Eigen::Matrix4f& model_to_camera)
  {
    GroundTruthInstance instance;
    instance.object_id = type;
    instance.pose = model_to_camera;
    instance.mask_visible = cv::Mat::zeros (kHeight, kWidth, CV_8UC1);
    return instance;
  }

  /** Ray-cast the part of the plane z = z_patch of a patch frame with |x| <= 50 mm and y from
    * y_from to y_to, greyed by grey_of (point in the patch frame), into the instance's mask.
    */
  template <typename Grey>
  void
  castPatch (GroundTruthInstance& instance,
             const Eigen::Matrix4f& patch_to_camera,
             float z_patch,
             float y_from,
             float y_to,
             const Grey& grey_of)
  {
    const Eigen::Matrix3f r = patch_to_camera.topLeftCorner<3, 3>();
    const Eigen::Vector3f t = patch_to_camera.topRightCorner<3, 1>();
    const Eigen::Vector3f normal = r.col (2);
    const Eigen::Vector3f on_plane = r * Eigen::Vector3f (0.0f, 0.0f, z_patch) + t;
    const Eigen::Matrix3f k_inverse = intrinsics().inverse();
    for (int v = 0; v < kHeight; ++v)
      for (int u = 0; u < kWidth; ++u) {
        const Eigen::Vector3f ray =
            k_inverse *
            Eigen::Vector3f (static_cast<float> (u), static_cast<float> (v), 1.0f);
        const float along = normal.dot (on_plane) / normal.dot (ray);
        const Eigen::Vector3f local = r.transpose() * (along * ray - t);
        if (!(along > 0.0f) || std::abs (local.x()) > 0.05f || local.y() < y_from ||
            local.y() > y_to)
          continue;
        auto& z = depth.at<float> (v, u);
        if (z == 0.0f || ray.z() * along < z) {
          z = ray.z() * along;
          instance.mask_visible.at<unsigned char> (v, u) = 255;
          grey.at<unsigned char> (v, u) = grey_of (local);
        }
      }
  }

public:
  std::vector<int>
  measure (float max_tilt = 2.0f, float min_contrast = 0.0f)
  {
    EXPECT_TRUE (mid::evaluation::measureSharedSurface (
        depth, grey, intrinsics(), kCell, max_tilt, min_contrast, frame));
    std::vector<int> cells;
    for (const auto& instance : frame.instances)
      cells.push_back (instance.shared_surface_cells);
    return cells;
  }
};

} // namespace

TEST (SharedSurface, TwoCopiesShowingTheSameFaceShareIt)
{
  // The patch lies in the middle of a layer of cubes (z = 5 mm) and covers 10 x 10 of them;
  // the eroded border and the normals' stencil cost a few of the outermost ones at most.
  PatchScene scene;
  scene.add (1, pose (-0.12f, 10.0f), 0.005f);
  scene.add (1, pose (0.12f, -5.0f), 0.005f);
  const auto cells = scene.measure();
  EXPECT_EQ (cells[0], cells[1]);
  EXPECT_GE (cells[0], 80);
  EXPECT_LE (cells[0], 100);
}

TEST (SharedSurface, CopiesShowingDifferentFacesOrOfDifferentTypesShareNothing)
{
  PatchScene faces;
  faces.add (1, pose (-0.12f, 0.0f), 0.005f);
  faces.add (1, pose (0.12f, 0.0f), 0.055f); // another face, 50 mm higher in the model
  EXPECT_EQ (faces.measure(), (std::vector<int>{0, 0}));

  PatchScene types;
  types.add (1, pose (-0.12f, 0.0f), 0.005f);
  types.add (2, pose (0.12f, 0.0f), 0.005f);
  EXPECT_EQ (types.measure(), (std::vector<int>{0, 0}));
}

TEST (SharedSurface, AViewTooSlantedForSiftSharesNothingUnlessTheTiltLimitAllowsIt)
{
  // Frontal against 65 deg: a transition tilt of 1 / cos 65 deg = 2.37.
  PatchScene scene;
  scene.add (1, pose (-0.12f, 0.0f), 0.005f);
  scene.add (1, pose (0.12f, 65.0f), 0.005f);
  EXPECT_EQ (scene.measure (2.0f), (std::vector<int>{0, 0}));
  const auto allowed = scene.measure (3.0f);
  EXPECT_GE (allowed[0], 50);
  EXPECT_EQ (allowed[0], allowed[1]);
}

TEST (SharedSurface, MirroredSlantedViewsShareTheFace)
{
  // 45 deg to either side of the normal: the views are 90 deg apart, but both foreshorten the
  // patch alike (transition tilt 1), so SIFT could match them.
  PatchScene scene;
  scene.add (1, pose (-0.12f, 45.0f), 0.005f);
  scene.add (1, pose (0.12f, -45.0f), 0.005f);
  const auto cells = scene.measure (1.2f);
  EXPECT_GE (cells[0], 70);
  EXPECT_EQ (cells[0], cells[1]);
}

TEST (SharedSurface, TheTextureTestCountsOnlyTheCubesThatShowContrastInBothViews)
{
  // The checkered half (x < 0) of the shared face is textured: 50 of its 100 cubes. The plain
  // half's column of 10 cubes next to the checkerboard sees it in its contrast windows.
  PatchScene scene;
  scene.add (1, pose (-0.12f, 10.0f), 0.005f);
  scene.add (1, pose (0.12f, -5.0f), 0.005f);
  const auto all = scene.measure (2.0f, 0.0f);
  const auto textured = scene.measure (2.0f, 4.0f);
  EXPECT_GE (all[0], 80);
  EXPECT_EQ (textured[0], textured[1]);
  EXPECT_GE (textured[0], 45);
  EXPECT_LE (textured[0], 62);
  // The same with the (identical) colour image.
  cv::Mat colour;
  cv::cvtColor (scene.grey, colour, cv::COLOR_GRAY2BGR);
  ASSERT_TRUE (mid::evaluation::measureSharedSurface (
      scene.depth, colour, intrinsics(), kCell, 2.0f, 4.0f, scene.frame));
  EXPECT_EQ (scene.frame.instances[0].shared_surface_cells, textured[0]);

  // A face plain in both copies shares nothing textured, as does a face printed in one view
  // and plain in the other.
  PatchScene plain;
  plain.add (1, pose (-0.12f, 10.0f), 0.005f, false);
  plain.add (1, pose (0.12f, -5.0f), 0.005f, false);
  EXPECT_GE (plain.measure (2.0f, 0.0f)[0], 80);
  EXPECT_EQ (plain.measure (2.0f, 4.0f), (std::vector<int>{0, 0}));
  PatchScene mixed;
  mixed.add (1, pose (-0.12f, 10.0f), 0.005f, true);
  mixed.add (1, pose (0.12f, -5.0f), 0.005f, false);
  EXPECT_EQ (mixed.measure (2.0f, 4.0f), (std::vector<int>{0, 0}));
}

TEST (SharedSurface, RefusesUnusableInputAndClearsTheMeasurements)
{
  PatchScene scene;
  scene.add (1, pose (-0.12f, 0.0f), 0.005f);
  scene.add (1, pose (0.12f, 0.0f), 0.005f);
  const auto refused = [&scene] (const cv::Mat& depth, float cell, float tilt) {
    scene.measure();
    const bool ok = mid::evaluation::measureSharedSurface (
        depth, intrinsics(), cell, tilt, scene.frame);
    return !ok && scene.frame.instances[0].shared_surface_cells == -1 &&
           scene.frame.instances[1].shared_surface_cells == -1;
  };
  cv::Mat millimetres;
  scene.depth.convertTo (millimetres, CV_16UC1, 1000.0);
  EXPECT_TRUE (refused (millimetres, kCell, 2.0f));
  EXPECT_TRUE (refused (cv::Mat(), kCell, 2.0f));
  EXPECT_TRUE (refused (scene.depth (cv::Rect (0, 0, 320, 240)).clone(), kCell, 2.0f));
  EXPECT_TRUE (refused (scene.depth, 0.0f, 2.0f));
  EXPECT_TRUE (refused (scene.depth, kCell, 0.5f));
  EXPECT_FALSE (refused (scene.depth, kCell, 2.0f));

  // The texture test: a negative contrast, and no image, a smaller one or a 16-bit one.
  const auto refused_image = [&scene] (const cv::Mat& image, float min_contrast) {
    scene.measure();
    const bool ok = mid::evaluation::measureSharedSurface (
        scene.depth, image, intrinsics(), kCell, 2.0f, min_contrast, scene.frame);
    return !ok && scene.frame.instances[0].shared_surface_cells == -1;
  };
  cv::Mat wide;
  scene.grey.convertTo (wide, CV_16UC1);
  EXPECT_TRUE (refused_image (scene.grey, -1.0f));
  EXPECT_TRUE (refused_image (cv::Mat(), 4.0f));
  EXPECT_TRUE (refused_image (scene.grey (cv::Rect (0, 0, 320, 240)).clone(), 4.0f));
  EXPECT_TRUE (refused_image (wide, 4.0f));
  EXPECT_FALSE (refused_image (cv::Mat(), 0.0f));
  EXPECT_FALSE (refused_image (scene.grey, 4.0f));
}

TEST (SharedSurface, ReadsTheDepthAndCameraOfABopSceneFolder)
{
  PatchScene scene;
  scene.add (1, pose (-0.12f, 10.0f), 0.005f);
  scene.add (1, pose (0.12f, -5.0f), 0.005f);
  const auto expected = scene.measure();

  const mid::test::TemporaryFolder folder;
  std::ofstream gt (folder.file ("scene_gt.json"));
  gt << R"({"7": [)";
  for (std::size_t k = 0; k < 2; ++k) {
    const Eigen::Matrix4f& p = scene.frame.instances[k].pose;
    gt << (k > 0 ? "," : "") << R"({"obj_id": 1, "cam_R_m2c": [)";
    for (int i = 0; i < 9; ++i)
      gt << (i > 0 ? "," : "") << p (i / 3, i % 3);
    gt << R"(], "cam_t_m2c": [)" << p (0, 3) * 1000.0f << "," << p (1, 3) * 1000.0f
       << "," << p (2, 3) * 1000.0f << "]}";
    std::filesystem::create_directories (folder.path() / "mask_visib");
    ASSERT_TRUE (cv::imwrite (
        (folder.path() / "mask_visib" / ("000007_00000" + std::to_string (k) + ".png"))
            .string(),
        scene.frame.instances[k].mask_visible));
  }
  gt << "]}";
  gt.close();
  std::ofstream (folder.file ("scene_camera.json"))
      << R"({"7": {"cam_K": [538, 0, 319.5, 0, 538, 239.5, 0, 0, 1], "depth_scale": 0.1}})";
  mid::evaluation::GroundTruthScene truth;
  ASSERT_TRUE (mid::evaluation::loadBopScene (folder.path().string(), truth));
  // No depth image yet: refused, nothing measured.
  EXPECT_FALSE (mid::evaluation::measureSharedSurface (
      folder.path().string(), kCell, 2.0f, 0.0f, truth));
  EXPECT_EQ (truth.at (7).instances[0].shared_surface_cells, -1);

  cv::Mat tenths_of_mm;
  scene.depth.convertTo (tenths_of_mm, CV_16UC1, 10000.0);
  std::filesystem::create_directories (folder.path() / "depth");
  ASSERT_TRUE (
      cv::imwrite ((folder.path() / "depth" / "000007.png").string(), tenths_of_mm));
  ASSERT_TRUE (mid::evaluation::measureSharedSurface (
      folder.path().string(), kCell, 2.0f, 0.0f, truth));
  // The 0.1 mm steps of the stored depth may move a point across a cube's border.
  EXPECT_NEAR (truth.at (7).instances[0].shared_surface_cells, expected[0], 3);
  EXPECT_NEAR (truth.at (7).instances[1].shared_surface_cells, expected[1], 3);

  // The texture test reads rgb/000007.png, and refuses without it.
  const auto textured = scene.measure (2.0f, 4.0f);
  EXPECT_FALSE (mid::evaluation::measureSharedSurface (
      folder.path().string(), kCell, 2.0f, 4.0f, truth));
  EXPECT_EQ (truth.at (7).instances[0].shared_surface_cells, -1);
  std::filesystem::create_directories (folder.path() / "rgb");
  ASSERT_TRUE (
      cv::imwrite ((folder.path() / "rgb" / "000007.png").string(), scene.grey));
  ASSERT_TRUE (mid::evaluation::measureSharedSurface (
      folder.path().string(), kCell, 2.0f, 4.0f, truth));
  EXPECT_NEAR (truth.at (7).instances[0].shared_surface_cells, textured[0], 3);
  EXPECT_LT (truth.at (7).instances[0].shared_surface_cells, expected[0] - 20);
}
