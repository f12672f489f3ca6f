#include "rendered_objects_scene.h"

#include <mid/simulation/box_shape.h>
#include <mid/simulation/frame_io.h>
#include <mid/simulation/procedural_texture.h>
#include <mid/simulation/scene.h>
#include <mid/simulation/scene_renderer.h>
#include <mid/simulation/table_plane.h>
#include <mid/simulation/texture.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace mid {
namespace test {

Eigen::Isometry3d
boxPose (double x, double y, double z, double roll, double tilt)
{
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = (Eigen::AngleAxisd (tilt * M_PI / 180.0, Eigen::Vector3d::UnitX()) *
                   Eigen::AngleAxisd (roll * M_PI / 180.0, Eigen::Vector3d::UnitZ()))
                      .toRotationMatrix();
  pose.translation() = Eigen::Vector3d (x, y, z);
  return pose;
}

std::vector<BoxSpec>
boxesLyingApart (const BoxSpec& box, const std::vector<std::size_t>& at)
{
  const double table = 0.95;
  // x, y (metres) and turn (degrees) of each place.
  const double places[4][3] = {{-0.16, -0.1, 10.0},
                               {0.16, -0.12, -35.0},
                               {-0.15, 0.12, 70.0},
                               {0.17, 0.11, 160.0}};
  std::vector<BoxSpec> boxes;
  for (const std::size_t p : at) {
    if (p >= 4)
      throw std::out_of_range ("no place " + std::to_string (p) + " on the table");
    BoxSpec copy = box;
    copy.pose =
        boxPose (places[p][0], places[p][1], table - 0.5 * box.size.z(), places[p][2]);
    boxes.push_back (copy);
  }
  return boxes;
}

RenderedObjectsScene
boxesLyingOnATable (const std::vector<const char*>& prints,
                    const std::vector<std::size_t>& at)
{
  BoxSpec box;
  box.size = Eigen::Vector3d (0.12, 0.09, 0.04);
  const std::size_t count = std::min (prints.size(), at.size());
  auto boxes = boxesLyingApart (
      box,
      std::vector<std::size_t> (at.begin(),
                                at.begin() + static_cast<std::ptrdiff_t> (count)));
  for (std::size_t b = 0; b < count; ++b)
    boxes[b].texture = prints[b];
  return renderBoxes (boxes, 0.95);
}

double
shareOfBoxEdgesOn (const cv::Mat& mask,
                   const BoxSpec& box,
                   double fx,
                   double fy,
                   double cx,
                   double cy,
                   std::size_t* samples)
{
  // Corner k has the sign of axis a's half edge in bit a of k.
  const auto corner = [&] (int k) {
    const Eigen::Vector3d local ((k & 1) ? 0.5 * box.size.x() : -0.5 * box.size.x(),
                                 (k & 2) ? 0.5 * box.size.y() : -0.5 * box.size.y(),
                                 (k & 4) ? 0.5 * box.size.z() : -0.5 * box.size.z());
    const Eigen::Vector3d p = box.pose * local;
    return Eigen::Vector2d (fx * p.x() / p.z() + cx, fy * p.y() / p.z() + cy);
  };
  std::size_t on = 0, inside = 0;
  for (int c = 0; c < 8; ++c)
    for (int axis = 1; axis < 8; axis <<= 1) {
      if ((c & axis) != 0)
        continue; // each edge once, from its corner on the negative side
      const Eigen::Vector2d a = corner (c), b = corner (c | axis);
      for (int step = 0; step <= 20; ++step) {
        const Eigen::Vector2d q = a + (b - a) * (step / 20.0);
        const int u = static_cast<int> (std::lround (q.x())),
                  v = static_cast<int> (std::lround (q.y()));
        if (u < 0 || v < 0 || u >= mask.cols || v >= mask.rows)
          continue;
        ++inside;
        on += mask.at<uchar> (v, u) != 0 ? 1 : 0;
      }
    }
  if (samples)
    *samples = inside;
  return inside > 0 ? static_cast<double> (on) / static_cast<double> (inside) : 0.0;
}

RenderedObjectsScene
renderBoxes (const std::vector<BoxSpec>& boxes, double table_depth, double view_tilt)
{
  const Eigen::Isometry3d turn =
      Eigen::Translation3d (0.0, 0.0, table_depth) *
      Eigen::AngleAxisd (view_tilt * M_PI / 180.0, Eigen::Vector3d::UnitX()) *
      Eigen::Translation3d (0.0, 0.0, -table_depth);
  RenderedObjectsScene result;
  result.boxes = boxes;
  for (auto& box : result.boxes)
    box.pose = turn * box.pose;
  mid::simulation::Scene scene;
  std::map<std::string, cv::Mat> textures;
  const auto texture = [&textures] (const std::string& name) {
    if (textures.count (name) == 0) {
      cv::Mat image;
      if (!mid::simulation::loadTexture (
              std::string (MID_TEST_DATA_DIR) + "/textures/" + name, image))
        throw std::runtime_error ("cannot read texture " + name);
      textures[name] = image;
    }
    return textures[name];
  };
  for (const auto& box : result.boxes) {
    auto shape = std::make_shared<mid::simulation::BoxShape> (
        box.size.x(), box.size.y(), box.size.z());
    shape->setTexture (box.printed_all_around ? texture (box.texture)
                                              : mid::simulation::makeUniformTexture (
                                                    cv::Vec3b (200, 200, 200)));
    shape->setFaceTexture (mid::simulation::BoxShape::NEG_Z, texture (box.texture));
    if (!box.side_texture.empty())
      shape->setFaceTexture (mid::simulation::BoxShape::NEG_Y,
                             texture (box.side_texture));
    scene.addObject (shape, box.pose);
  }
  if (table_depth > 0.0) {
    auto table = std::make_shared<mid::simulation::TablePlane> (1.0, 1.0);
    table->setTexture (mid::simulation::makeUniformTexture (cv::Vec3b (120, 120, 120)));
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation().z() = table_depth;
    scene.addBackgroundObject (table, turn * pose);
  }
  mid::simulation::SceneRenderer renderer;
  if (!renderer.render (scene, result.frame))
    throw std::runtime_error ("rendering failed");
  result.cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZRGBA>>();
  // A 0.1 mm depth step: a noise-free frame, as exact as a 16-bit PNG can hold it.
  if (!mid::simulation::frameToCloud (result.frame, 1e-4, *result.cloud))
    throw std::runtime_error ("no cloud");
  return result;
}

int
boxUnderKeypoints (const RenderedObjectsScene& scene,
                   const std::vector<Eigen::Vector2f>& pixels,
                   double* share)
{
  std::map<int, int> votes;
  for (const auto& p : pixels) {
    const int u = static_cast<int> (std::lround (p.x())),
              v = static_cast<int> (std::lround (p.y()));
    if (u >= 0 && v >= 0 && u < scene.frame.instances.cols &&
        v < scene.frame.instances.rows)
      ++votes[scene.frame.instances.at<int> (v, u)];
  }
  int best = -1, count = 0;
  for (const auto& [box, n] : votes)
    if (n > count) {
      best = box;
      count = n;
    }
  const int box = 2 * count > static_cast<int> (pixels.size()) ? best : -1;
  if (share != nullptr)
    *share = box >= 0
                 ? static_cast<double> (count) / static_cast<double> (pixels.size())
                 : 0.0;
  return box;
}

namespace {

/** A pixel's grey level (0.299 r + 0.587 g + 0.114 b). */
template <typename PointT>
float
greyOf (const PointT& p)
{
  return 0.299f * static_cast<float> (p.r) + 0.587f * static_cast<float> (p.g) +
         0.114f * static_cast<float> (p.b);
}

/** The pixels of box `box` in the scene's frame (column, row). */
std::vector<std::pair<std::size_t, std::size_t>>
boxPixels (const RenderedObjectsScene& scene, int box)
{
  std::vector<std::pair<std::size_t, std::size_t>> pixels;
  for (int v = 0; v < scene.frame.instances.rows; ++v)
    for (int u = 0; u < scene.frame.instances.cols; ++u)
      if (scene.frame.instances.at<int> (v, u) == box)
        pixels.emplace_back (static_cast<std::size_t> (u),
                             static_cast<std::size_t> (v));
  return pixels;
}

/** Tint one pixel's colour blue, keeping its grey level. */
template <typename PointT>
void
tintPixel (PointT& p)
{
  const float grey = greyOf (p);
  const float r = 0.5f * grey, b = std::min (255.0f, 1.6f * grey);
  const float g = std::clamp ((grey - 0.299f * r - 0.114f * b) / 0.587f, 0.0f, 255.0f);
  p.r = static_cast<std::uint8_t> (std::lround (r));
  p.g = static_cast<std::uint8_t> (std::lround (g));
  p.b = static_cast<std::uint8_t> (std::lround (b));
}

/** Tint every pixel of box `box` in an organized cloud of the scene's frame. */
template <typename PointT>
std::size_t
tintBox (const RenderedObjectsScene& scene, int box, pcl::PointCloud<PointT>& cloud)
{
  const auto pixels = boxPixels (scene, box);
  for (const auto& [u, v] : pixels)
    tintPixel (cloud (u, v));
  return pixels.size();
}

} // namespace

std::size_t
tintKeepingGreyLevels (const RenderedObjectsScene& scene,
                       int box,
                       pcl::PointCloud<pcl::PointXYZRGB>& cloud)
{
  return tintBox (scene, box, cloud);
}

std::size_t
tintKeepingGreyLevels (RenderedObjectsScene& scene, int box)
{
  return tintBox (scene, box, *scene.cloud);
}

void
paintInkKeepingGreyLevels (const RenderedObjectsScene& scene,
                           int box,
                           const Eigen::Vector3f& ink,
                           pcl::PointCloud<pcl::PointXYZRGB>& cloud)
{
  const auto pixels = boxPixels (scene, box);
  if (pixels.empty())
    return;
  std::vector<float> grey;
  grey.reserve (pixels.size());
  for (const auto& [u, v] : pixels)
    grey.push_back (greyOf ((*scene.cloud) (u, v)));
  const auto fifth = static_cast<std::ptrdiff_t> (grey.size() / 5);
  std::nth_element (grey.begin(), grey.begin() + fifth, grey.end());
  const float ink_below = grey[static_cast<std::size_t> (fifth)];
  const float ink_grey = 0.299f * ink.x() + 0.587f * ink.y() + 0.114f * ink.z();
  for (const auto& [u, v] : pixels) {
    auto& p = cloud (u, v);
    const float y = greyOf ((*scene.cloud) (u, v));
    const Eigen::Vector3f c = y < ink_below ? Eigen::Vector3f (ink * (y / ink_grey))
                                            : Eigen::Vector3f (y, y, y);
    p.r = static_cast<std::uint8_t> (std::lround (std::min (c.x(), 255.0f)));
    p.g = static_cast<std::uint8_t> (std::lround (std::min (c.y(), 255.0f)));
    p.b = static_cast<std::uint8_t> (std::lround (std::min (c.z(), 255.0f)));
  }
}

std::size_t
mirrorPrintPart (RenderedObjectsScene& scene, int box, double x_from, double x_to)
{
  const auto& spec = scene.boxes.at (static_cast<std::size_t> (box));
  const auto& camera = scene.frame.camera;
  const Eigen::Isometry3d to_box = spec.pose.inverse();
  const pcl::PointCloud<pcl::PointXYZRGBA> original = *scene.cloud;
  std::size_t changed = 0;
  for (const auto& [u, v] : boxPixels (scene, box)) {
    auto& p = (*scene.cloud) (u, v);
    Eigen::Vector3d q = to_box * p.getVector3fMap().cast<double>();
    if (std::abs (q.z() + 0.5 * spec.size.z()) > 1e-3 || q.x() < x_from || q.x() > x_to)
      continue;
    q.x() = x_from + x_to - q.x();
    const Eigen::Vector3d there = spec.pose * q;
    const auto mu = std::lround (camera.fx * there.x() / there.z() + camera.cx),
               mv = std::lround (camera.fy * there.y() / there.z() + camera.cy);
    if (mu < 0 || mv < 0 || mu >= camera.width || mv >= camera.height)
      continue;
    const auto& mirrored =
        original (static_cast<std::size_t> (mu), static_cast<std::size_t> (mv));
    p.r = mirrored.r;
    p.g = mirrored.g;
    p.b = mirrored.b;
    ++changed;
  }
  return changed;
}

} // namespace test
} // namespace mid
