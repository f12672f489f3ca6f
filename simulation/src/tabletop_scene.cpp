#include <mid/simulation/box_shape.h>
#include <mid/simulation/cylinder_shape.h>
#include <mid/simulation/deterministic_random.h>
#include <mid/simulation/procedural_texture.h>
#include <mid/simulation/table_plane.h>
#include <mid/simulation/tabletop_scene.h>
#include <mid/simulation/texture.h>

#include <opencv2/core.hpp>
#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace mid {
namespace simulation {

namespace {

constexpr double kPi = 3.14159265358979323846;

/** Juice carton (about 1 l): square section, lying on a long side. */
const Eigen::Vector3d kCartonSize (0.07, 0.07, 0.2);
/** Cookie box: flat, its top face shows the (324 x 223) cookie box photo. */
const Eigen::Vector3d kCookieBoxSize (0.16, 0.11, 0.05);
constexpr double kCanRadius = 0.035;
constexpr double kCanHeight = 0.16;

/** Table top, and the area of it the objects are placed in (table frame, y away from the
  * camera); only the part of the area whose objects are entirely in view is used.
  */
constexpr double kTableSizeX = 1.6;
constexpr double kTableSizeY = 1.2;
constexpr double kAreaMinX = -0.45, kAreaMaxX = 0.45;
constexpr double kAreaMinY = -0.3, kAreaMaxY = 0.4;
/** Smallest distance of an object's projection to the image border, pixels. */
constexpr double kViewMargin = 8.0;
/** Smallest gap between the footprints of two objects, metres. */
constexpr double kMinGap = 0.02;
/** Random positions tried per object, and fresh starts of the whole layout. */
constexpr int kMaxPlacementAttempts = 300;
constexpr int kMaxLayoutRestarts = 300;
constexpr int kMaxInstances = 10;

/** Stream of DeterministicRandom used by the layout. */
constexpr std::uint32_t kLayoutStream = 11;

/** Rotated rectangle an object covers on the table, and the object's height. */
struct Footprint
{
  Eigen::Vector2d center = Eigen::Vector2d::Zero();
  double yaw = 0.0;
  Eigen::Vector2d half = Eigen::Vector2d::Zero();
  double height = 0.0;
};

/** Where the objects may go: the placement area, as seen by the camera. */
struct PlacementView
{
  PinholeCamera camera;
  Eigen::Isometry3d table_to_camera;
};

bool
footprintsOverlap (const Footprint& a, const Footprint& b, double gap)
{
  const Eigen::Vector2d axes[4] = {{std::cos (a.yaw), std::sin (a.yaw)},
                                   {-std::sin (a.yaw), std::cos (a.yaw)},
                                   {std::cos (b.yaw), std::sin (b.yaw)},
                                   {-std::sin (b.yaw), std::cos (b.yaw)}};
  const Eigen::Vector2d offset = b.center - a.center;
  // Separating axis test: the rectangles (grown by half the gap) overlap unless one of the
  // four edge directions separates their projections.
  return std::all_of (
      std::begin (axes), std::end (axes), [&] (const Eigen::Vector2d& axis) {
        const double reach_a =
            std::abs ((a.half.x() + 0.5 * gap) * axes[0].dot (axis)) +
            std::abs ((a.half.y() + 0.5 * gap) * axes[1].dot (axis));
        const double reach_b =
            std::abs ((b.half.x() + 0.5 * gap) * axes[2].dot (axis)) +
            std::abs ((b.half.y() + 0.5 * gap) * axes[3].dot (axis));
        return std::abs (offset.dot (axis)) <= reach_a + reach_b;
      });
}

/** Whether the footprint's box (footprint times height) lies in the area and in view. */
bool
footprintAllowed (const Footprint& footprint, const PlacementView& view)
{
  const double c = std::cos (footprint.yaw), s = std::sin (footprint.yaw);
  for (int corner = 0; corner < 8; ++corner) {
    const double x = ((corner & 1) ? 1.0 : -1.0) * footprint.half.x();
    const double y = ((corner & 2) ? 1.0 : -1.0) * footprint.half.y();
    const Eigen::Vector3d point (footprint.center.x() + c * x - s * y,
                                 footprint.center.y() + s * x + c * y,
                                 (corner & 4) ? footprint.height : 0.0);
    if (point.x() < kAreaMinX || point.x() > kAreaMaxX || point.y() < kAreaMinY ||
        point.y() > kAreaMaxY)
      return false;
    Eigen::Vector2d pixel;
    if (!projectPoint (view.camera, view.table_to_camera * point, pixel) ||
        pixel.x() < kViewMargin || pixel.y() < kViewMargin ||
        pixel.x() > view.camera.width - 1 - kViewMargin ||
        pixel.y() > view.camera.height - 1 - kViewMargin)
      return false;
  }
  return true;
}

/** Draw a free spot for a footprint of the given half extents; false if none was found. */
bool
placeFootprint (const Footprint& shape,
                const PlacementView& view,
                DeterministicRandom& random,
                std::vector<Footprint>& placed)
{
  for (int attempt = 0; attempt < kMaxPlacementAttempts; ++attempt) {
    Footprint candidate = shape;
    candidate.center = Eigen::Vector2d (random.uniform (kAreaMinX, kAreaMaxX),
                                        random.uniform (kAreaMinY, kAreaMaxY));
    candidate.yaw = random.uniform (0.0, 2.0 * kPi);
    if (!footprintAllowed (candidate, view))
      continue;
    bool free = true;
    for (const Footprint& other : placed)
      free = free && !footprintsOverlap (candidate, other, kMinGap);
    if (free) {
      placed.push_back (candidate);
      return true;
    }
  }
  return false;
}

/** Place the footprints (sizes given, positions drawn), largest first, starting over when one
  * does not fit; layout[i] belongs to shapes[i]. False if no layout was found.
  */
bool
layoutFootprints (const std::vector<Footprint>& shapes,
                  const PlacementView& view,
                  DeterministicRandom& random,
                  std::vector<Footprint>& layout)
{
  std::vector<std::size_t> order (shapes.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  std::stable_sort (
      order.begin(), order.end(), [&shapes] (std::size_t a, std::size_t b) {
        return shapes[a].half.prod() > shapes[b].half.prod();
      });
  for (int restart = 0; restart < kMaxLayoutRestarts; ++restart) {
    std::vector<Footprint> placed;
    layout.assign (shapes.size(), Footprint());
    bool complete = true;
    for (const std::size_t index : order) {
      if (!placeFootprint (shapes[index], view, random, placed)) {
        complete = false;
        break;
      }
      layout[index] = placed.back();
    }
    if (complete)
      return true;
  }
  return false;
}

/** Table-to-camera transform of a camera at the given distance from the table centre, looking
  * at it from the -y side, the given angle below the horizontal, without roll.
  */
Eigen::Isometry3d
tableToCamera (double distance, double elevation_deg)
{
  const double elevation = elevation_deg * kPi / 180.0;
  const Eigen::Vector3d eye (
      0.0, -distance * std::cos (elevation), distance * std::sin (elevation));
  const Eigen::Vector3d forward = (-eye).normalized();
  const Eigen::Vector3d right = forward.cross (Eigen::Vector3d::UnitZ()).normalized();
  const Eigen::Vector3d down = forward.cross (right);
  Eigen::Isometry3d camera_to_table = Eigen::Isometry3d::Identity();
  camera_to_table.linear() << right, down, forward;
  camera_to_table.translation() = eye;
  return camera_to_table.inverse();
}

/** The label centred on a canvas of its border colour, as wide as aspect times its height:
  * a can's side texture that shows the label once, undistorted.
  */
cv::Mat
makeLabelTexture (const cv::Mat& label, double aspect)
{
  const int width =
      std::max (label.cols, static_cast<int> (std::lround (aspect * label.rows)));
  const cv::Scalar border =
      cv::mean (label.colRange (0, 1)) * 0.5 +
      cv::mean (label.colRange (label.cols - 1, label.cols)) * 0.5;
  cv::Mat canvas (label.rows, width, CV_8UC3, border);
  label.copyTo (canvas.colRange ((width - label.cols) / 2,
                                 (width - label.cols) / 2 + label.cols));
  return canvas;
}

bool
loadTextures (const std::string& texture_dir, std::vector<cv::Mat>& textures)
{
  const char* const names[] = {TABLETOP_CARTON_FRONT_TEXTURE,
                               TABLETOP_CARTON_BACK_TEXTURE,
                               TABLETOP_COOKIE_BOX_TEXTURE,
                               TABLETOP_CAN_LABEL_TEXTURE};
  textures.clear();
  for (const char* name : names) {
    cv::Mat texture;
    if (!loadTexture (texture_dir + "/" + name, texture))
      return false;
    textures.push_back (texture);
  }
  return true;
}

BoxShape::Ptr
makeCarton (const cv::Mat& front, const cv::Mat& back)
{
  auto carton =
      std::make_shared<BoxShape> (kCartonSize.x(), kCartonSize.y(), kCartonSize.z());
  carton->setName ("juice_carton");
  carton->setTexture (makeUniformTexture (cv::Vec3b (225, 230, 232)));
  carton->setFaceTexture (BoxShape::NEG_Y, front);
  carton->setFaceTexture (BoxShape::POS_Y, back);
  carton->setFaceTexture (BoxShape::POS_X,
                          makeNoiseTexture (120,
                                            343,
                                            24.0,
                                            24.0,
                                            cv::Vec3b (40, 120, 50),
                                            cv::Vec3b (215, 235, 235),
                                            101));
  carton->setFaceTexture (BoxShape::NEG_X,
                          makeNoiseTexture (120,
                                            343,
                                            24.0,
                                            24.0,
                                            cv::Vec3b (20, 80, 190),
                                            cv::Vec3b (210, 230, 240),
                                            102));
  return carton;
}

BoxShape::Ptr
makeCookieBox (const cv::Mat& top)
{
  auto box = std::make_shared<BoxShape> (
      kCookieBoxSize.x(), kCookieBoxSize.y(), kCookieBoxSize.z());
  box->setName ("cookie_box");
  box->setTexture (makeUniformTexture (cv::Vec3b (120, 150, 175)));
  box->setFaceTexture (BoxShape::POS_Z, top);
  return box;
}

CylinderShape::Ptr
makeCan (const cv::Mat& label)
{
  auto can = std::make_shared<CylinderShape> (kCanRadius, kCanHeight);
  can->setName ("soy_milk_can");
  can->setTexture (makeUniformTexture (cv::Vec3b (200, 205, 210)));
  can->setFaceTexture (CylinderShape::SIDE,
                       makeLabelTexture (label, 2.0 * kPi * kCanRadius / kCanHeight));
  return can;
}

TablePlane::Ptr
makeTable (std::uint32_t seed)
{
  auto table = std::make_shared<TablePlane> (kTableSizeX, kTableSizeY);
  table->setName ("table");
  table->setExtent (kTableSizeX, kTableSizeY);
  table->setTexture (makeNoiseTexture (1024,
                                       768,
                                       200.0,
                                       24.0,
                                       cv::Vec3b (40, 75, 120),
                                       cv::Vec3b (120, 170, 215),
                                       seed));
  return table;
}

/** Pose on the table of an object resting at height z, turned by the footprint's yaw. */
Eigen::Isometry3d
restingPose (const Footprint& footprint, double z, const Eigen::Matrix3d& orientation)
{
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() =
      Eigen::AngleAxisd (footprint.yaw, Eigen::Vector3d::UnitZ()) * orientation;
  pose.translation() = Eigen::Vector3d (footprint.center.x(), footprint.center.y(), z);
  return pose;
}

bool
fail (const std::string& message, Scene& scene)
{
  PCL_ERROR ("[mid::simulation::makeTabletopScene] %s\n", message.c_str());
  scene.clear();
  return false;
}

} // namespace

bool
makeTabletopScene (const TabletopSceneOptions& options,
                   const std::string& texture_dir,
                   Scene& scene)
{
  scene.clear();
  if (options.instances < 1 || options.instances > kMaxInstances)
    return fail ("the number of instances must be in [1, " +
                     std::to_string (kMaxInstances) + "], got " +
                     std::to_string (options.instances),
                 scene);
  if (options.distractors < 0 || options.distractors > 2)
    return fail ("the number of distractors must be in [0, 2], got " +
                     std::to_string (options.distractors),
                 scene);
  std::string problem;
  if (!validateCamera (options.camera, problem))
    return fail (problem, scene);
  if (!(options.camera_distance >= 0.4 && options.camera_distance <= 3.0) ||
      !(options.camera_elevation >= 20.0 && options.camera_elevation <= 90.0))
    return fail (
        "the camera distance must be in [0.4, 3] m and its elevation in [20, 90] deg",
        scene);
  std::vector<cv::Mat> textures;
  if (!loadTextures (texture_dir, textures))
    return fail ("cannot read the textures in '" + texture_dir + "'", scene);

  // Footprints: the cartons (long axis along the footprint's x), then the distractors.
  std::vector<Footprint> shapes (options.instances);
  for (Footprint& shape : shapes) {
    shape.half = Eigen::Vector2d (0.5 * kCartonSize.z(), 0.5 * kCartonSize.x());
    shape.height = kCartonSize.x();
  }
  if (options.distractors >= 1) {
    shapes.emplace_back();
    shapes.back().half =
        Eigen::Vector2d (0.5 * kCookieBoxSize.x(), 0.5 * kCookieBoxSize.y());
    shapes.back().height = kCookieBoxSize.z();
  }
  if (options.distractors >= 2) {
    shapes.emplace_back();
    shapes.back().half = Eigen::Vector2d (kCanRadius, kCanRadius);
    shapes.back().height = kCanHeight;
  }
  const Eigen::Isometry3d table_to_camera =
      tableToCamera (options.camera_distance, options.camera_elevation);
  const PlacementView view{options.camera, table_to_camera};
  DeterministicRandom random (options.seed, kLayoutStream);
  std::vector<Footprint> placed;
  if (!layoutFootprints (shapes, view, random, placed))
    return fail (
        "cannot place " + std::to_string (shapes.size()) +
            " objects on the table in view without contact; use fewer instances",
        scene);
  std::vector<int> spins;
  spins.reserve (options.instances);
  for (int i = 0; i < options.instances; ++i)
    spins.push_back (random.uniformInt (4));
  const BoxShape::Ptr carton = makeCarton (textures[0], textures[1]);
  for (int i = 0; i < options.instances; ++i) {
    // Long axis (model z) along the footprint's x; spinning about it picks the face that is up.
    const Eigen::Matrix3d lying =
        Eigen::AngleAxisd (0.5 * kPi, Eigen::Vector3d::UnitY()).toRotationMatrix() *
        Eigen::AngleAxisd (0.5 * kPi * spins[i], Eigen::Vector3d::UnitZ())
            .toRotationMatrix();
    scene.addObject (carton,
                     table_to_camera *
                         restingPose (placed[i], 0.5 * kCartonSize.x(), lying));
  }
  if (options.distractors >= 1)
    scene.addObject (makeCookieBox (textures[2]),
                     table_to_camera * restingPose (placed[options.instances],
                                                    0.5 * kCookieBoxSize.z(),
                                                    Eigen::Matrix3d::Identity()));
  if (options.distractors >= 2) {
    // The label (model +x) turned roughly towards the camera (table -y); a circle fits its
    // square footprint whatever the heading.
    Footprint can = placed[options.instances + 1];
    can.yaw = -0.5 * kPi + random.uniform (-0.6, 0.6);
    scene.addObject (makeCan (textures[3]),
                     table_to_camera * restingPose (can,
                                                    0.5 * kCanHeight,
                                                    Eigen::Matrix3d::Identity()));
  }
  scene.addBackgroundObject (makeTable (options.seed), table_to_camera);
  return true;
}

} // namespace simulation
} // namespace mid
