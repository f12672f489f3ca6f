#include <mid/segmentation/instance_extent.h>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <numeric>
#include <random>
#include <vector>

namespace mid {

namespace {

/** Plane hypotheses tried; every how many rows and columns the points are taken from, and
  * every how many of those a hypothesis is scored on.
  */
constexpr int kPlaneHypotheses = 200;
constexpr std::uint32_t kPixelStride = 4;
constexpr std::size_t kScoreStride = 4;

/** Fewest surface points a box is fitted to. */
constexpr int kMinExtentPoints = 30;

/** Share of the surface points allowed above the box's top (noise, mixed depth). */
constexpr float kHeightQuantile = 0.98f;

bool
isFinite (const pcl::PointXYZ& p)
{
  return std::isfinite (p.x) && std::isfinite (p.y) && std::isfinite (p.z);
}

float
planeDistance (const Eigen::Vector4f& plane, const Eigen::Vector3f& p)
{
  return plane.head<3>().dot (p) + plane[3];
}

} // namespace

bool
fitSupportPlane (const pcl::PointCloud<pcl::PointXYZ>& organized,
                 float tolerance,
                 float min_share,
                 Eigen::Vector4f& plane)
{
  plane.setZero();
  std::vector<Eigen::Vector3f, Eigen::aligned_allocator<Eigen::Vector3f>> points;
  const std::uint32_t stride = organized.height > 1 ? kPixelStride : 1;
  for (std::uint32_t row = 0; row < organized.height; row += stride)
    for (std::uint32_t column = 0; column < organized.width; column += stride) {
      const auto& p = organized.points[row * organized.width + column];
      if (isFinite (p))
        points.emplace_back (p.x, p.y, p.z);
    }
  if (points.size() < 3)
    return false;
  std::mt19937 random (0);
  std::uniform_int_distribution<std::size_t> draw (0, points.size() - 1);
  std::size_t best_count = 0;
  for (int h = 0; h < kPlaneHypotheses; ++h) {
    const Eigen::Vector3f a = points[draw (random)];
    const Eigen::Vector3f ab = points[draw (random)] - a;
    const Eigen::Vector3f ac = points[draw (random)] - a;
    Eigen::Vector3f n (ab.y() * ac.z() - ab.z() * ac.y(),
                       ab.z() * ac.x() - ab.x() * ac.z(),
                       ab.x() * ac.y() - ab.y() * ac.x());
    if (n.norm() < 1e-9f)
      continue;
    n.normalize();
    const Eigen::Vector4f candidate (n.x(), n.y(), n.z(), -n.dot (a));
    std::size_t count = 0;
    for (std::size_t i = 0; i < points.size(); i += kScoreStride)
      if (std::abs (planeDistance (candidate, points[i])) < tolerance)
        ++count;
    if (count > best_count) {
      best_count = count;
      plane = candidate;
    }
  }
  // Hypotheses were scored on every kScoreStride-th point, rounded up.
  const std::size_t scored_points = (points.size() + kScoreStride - 1) / kScoreStride;
  const auto scored = static_cast<float> (scored_points);
  if (static_cast<float> (best_count) < min_share * scored) {
    plane.setZero();
    return false;
  }
  // The camera (the origin) lies above the plane.
  if (plane[3] < 0.0f)
    plane = -plane;
  return true;
}

bool
measureInstanceExtent (const pcl::PointCloud<pcl::PointXYZ>& organized,
                       const Eigen::Vector4f& plane,
                       const pcl::Indices& seeds,
                       float max_step,
                       float max_radius,
                       float plane_tolerance,
                       InstanceExtent& extent)
{
  extent = InstanceExtent();
  const int width = static_cast<int> (organized.width);
  const int height = static_cast<int> (organized.height);
  if (seeds.empty() || width * height != static_cast<int> (organized.size()))
    return false;
  Eigen::Vector3f centroid = Eigen::Vector3f::Zero();
  int seeded = 0;
  for (const int s : seeds)
    if (s >= 0 && s < width * height && isFinite (organized[s])) {
      centroid += organized[s].getVector3fMap();
      ++seeded;
    }
  if (seeded == 0)
    return false;
  centroid /= static_cast<float> (seeded);

  const auto inside = [&] (int pixel) {
    const auto& p = organized[pixel];
    return isFinite (p) &&
           planeDistance (plane, p.getVector3fMap()) > plane_tolerance &&
           (p.getVector3fMap() - centroid).norm() < max_radius;
  };
  std::vector<char> reached (organized.size(), 0);
  std::deque<int> queue;
  for (const int s : seeds)
    if (s >= 0 && s < width * height && !reached[s] && inside (s)) {
      reached[s] = 1;
      queue.push_back (s);
    }
  pcl::Indices& surface = extent.surface;
  while (!queue.empty()) {
    const int pixel = queue.front();
    queue.pop_front();
    surface.push_back (pixel);
    const int row = pixel / width, column = pixel % width;
    const std::array<int, 4> next = {row > 0 ? pixel - width : -1,
                                     row + 1 < height ? pixel + width : -1,
                                     column > 0 ? pixel - 1 : -1,
                                     column + 1 < width ? pixel + 1 : -1};
    for (const int q : next)
      if (q >= 0 && !reached[q] && inside (q) &&
          (organized[q].getVector3fMap() - organized[pixel].getVector3fMap()).norm() <
              max_step) {
        reached[q] = 1;
        queue.push_back (q);
      }
  }
  if (static_cast<int> (surface.size()) < kMinExtentPoints) {
    surface.clear();
    return false;
  }

  // The footprint on the plane, in a basis (e1, e2) of it.
  const Eigen::Vector3f normal = plane.head<3>();
  const Eigen::Vector3f e1 = normal.unitOrthogonal();
  const Eigen::Vector3f e2 = normal.cross (e1);
  std::vector<cv::Point2f> footprint;
  std::vector<float> heights;
  footprint.reserve (surface.size());
  heights.reserve (surface.size());
  for (const int pixel : surface) {
    const Eigen::Vector3f p = organized[pixel].getVector3fMap();
    footprint.emplace_back (e1.dot (p), e2.dot (p));
    heights.push_back (planeDistance (plane, p));
  }
  const cv::RotatedRect rectangle = cv::minAreaRect (footprint);
  const auto top =
      heights.begin() + static_cast<std::ptrdiff_t> (
                            kHeightQuantile * static_cast<float> (heights.size() - 1));
  std::nth_element (heights.begin(), top, heights.end());
  const float box_height = *top;

  const float angle = rectangle.angle * static_cast<float> (M_PI) / 180.0f;
  const Eigen::Vector3f along_width = std::cos (angle) * e1 + std::sin (angle) * e2;
  const Eigen::Vector3f along_height = normal.cross (along_width);
  const std::array<Eigen::Vector3f, 3> axes = {along_width, along_height, normal};
  const std::array<float, 3> edges = {
      rectangle.size.width, rectangle.size.height, box_height};
  std::array<int, 3> order = {0, 1, 2};
  std::sort (
      order.begin(), order.end(), [&] (int a, int b) { return edges[a] < edges[b]; });

  // The footprint's centre lies on the plane: -offset * normal is the plane's point nearest
  // the origin.
  const Eigen::Vector3f base =
      -plane[3] * normal + rectangle.center.x * e1 + rectangle.center.y * e2;
  Eigen::Matrix3f rotation;
  for (int i = 0; i < 3; ++i) {
    rotation.col (i) = axes[order[i]];
    extent.size[i] = edges[order[i]];
  }
  if (rotation.determinant() < 0.0f)
    rotation.col (2) = -rotation.col (2);
  extent.pose.topLeftCorner<3, 3>() = rotation;
  extent.pose.topRightCorner<3, 1>() = base + 0.5f * box_height * normal;
  return true;
}

} // namespace mid
