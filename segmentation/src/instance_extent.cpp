#include <mid/segmentation/instance_extent.h>
#include <mid/segmentation/order_statistics.h>
#include <mid/segmentation/round_side.h>

#include <Eigen/Eigenvalues>
#include <opencv2/imgproc.hpp>
#include <pcl/console/print.h>

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

/** Share of the surface points allowed beyond each of the box's faces (noise, mixed depth at
  * the silhouette).
  */
constexpr float kEdgeQuantile = 0.995f;

bool
isFinite (const pcl::PointXYZ& p)
{
  return std::isfinite (p.x) && std::isfinite (p.y) && std::isfinite (p.z);
}

/** The least-squares plane through the points within tolerance of `plane`, twice: a plane
  * through three points is tilted by up to the tolerance, which the heights above it would
  * carry.
  */
void
refinePlane (const std::vector<Eigen::Vector3f,
                               Eigen::aligned_allocator<Eigen::Vector3f>>& points,
             float tolerance,
             Eigen::Vector4f& plane)
{
  for (int pass = 0; pass < 2; ++pass) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    Eigen::Matrix3d products = Eigen::Matrix3d::Zero();
    std::size_t count = 0;
    for (const auto& p : points)
      if (std::abs (planeDistance (plane, p)) < tolerance) {
        const Eigen::Vector3d q = p.cast<double>();
        sum += q;
        products += q * q.transpose();
        ++count;
      }
    if (count < 3)
      return;
    const Eigen::Vector3d mean = sum / static_cast<double> (count);
    const Eigen::Matrix3d covariance =
        products / static_cast<double> (count) - mean * mean.transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver (covariance);
    const Eigen::Vector3f normal = solver.eigenvectors().col (0).cast<float>();
    plane = Eigen::Vector4f (
        normal.x(), normal.y(), normal.z(), -normal.dot (mean.cast<float>()));
  }
}

/** Pixels on either side of a pixel that the crease test compares it with, and how far
  * (metres, along the viewing ray) it must lie behind them.
  */
constexpr int kCreasePixels = 6;
constexpr float kCreaseDepth = 0.006f;

/** True if the pixel lies in a crease: behind the chord between the points kCreasePixels away
  * on both sides, in one of four directions, by more than kCreaseDepth. The visible surface of
  * a convex object never does; where one object leans on or stands beside another, their
  * surfaces meet in one. The chord is taken in inverse depth, which is linear along a plane's
  * pixels.
  */
bool
inCrease (const pcl::PointCloud<pcl::PointXYZ>& organized, int pixel)
{
  const int width = static_cast<int> (organized.width);
  const int height = static_cast<int> (organized.height);
  const int row = pixel / width, column = pixel % width;
  const float z = organized[pixel].z;
  constexpr std::array<std::array<int, 2>, 4> kDirections = {
      {{0, 1}, {1, 0}, {1, 1}, {1, -1}}};
  return std::any_of (kDirections.begin(), kDirections.end(), [&] (const auto& d) {
    const int r0 = row - d[0] * kCreasePixels, c0 = column - d[1] * kCreasePixels;
    const int r1 = row + d[0] * kCreasePixels, c1 = column + d[1] * kCreasePixels;
    if (r0 < 0 || r1 >= height || std::min (c0, c1) < 0 || std::max (c0, c1) >= width)
      return false;
    const float z0 = organized[r0 * width + c0].z;
    const float z1 = organized[r1 * width + c1].z;
    return std::isfinite (z0) && std::isfinite (z1) &&
           z - 2.0f / (1.0f / z0 + 1.0f / z1) > kCreaseDepth;
  });
}

/** Share of an object's length at either end whose points are left out of its cross-section:
  * the flat ends of a can lying down are none of it.
  */
constexpr float kSectionEndShare = 0.1f;

/** widenToRoundSide() across the shorter of the footprint's two edges (extents [low, high]
  * along its two directions), on the points of the middle of the longer: `along` holds the
  * points' positions along both directions, `heights` their heights above the plane.
  */
void
widenShorterEdgeToRoundSide (const std::array<std::vector<float>, 2>& along,
                             const std::vector<float>& heights,
                             float height,
                             std::array<float, 2>& low,
                             std::array<float, 2>& high)
{
  const std::size_t across = high[0] - low[0] < high[1] - low[1] ? 0 : 1;
  const std::size_t length = 1 - across;
  const float end = kSectionEndShare * (high[length] - low[length]);
  std::vector<float> positions, section_heights;
  for (std::size_t i = 0; i < heights.size(); ++i)
    if (along[length][i] > low[length] + end && along[length][i] < high[length] - end) {
      positions.push_back (along[across][i]);
      section_heights.push_back (heights[i]);
    }
  widenToRoundSide (positions, section_heights, height, low[across], high[across]);
}

} // namespace

float
planeDistance (const Eigen::Vector4f& plane, const Eigen::Vector3f& p)
{
  return plane.head<3>().dot (p) + plane[3];
}

bool
fitSupportPlane (const pcl::PointCloud<pcl::PointXYZ>& organized,
                 float tolerance,
                 float min_share,
                 Eigen::Vector4f& plane)
{
  plane.setZero();
  if (organized.size() != static_cast<std::size_t> (organized.width) *
                              static_cast<std::size_t> (organized.height)) {
    PCL_ERROR ("[mid::fitSupportPlane] The cloud is not organized (width x height != "
               "size).\n");
    return false;
  }
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
  // std::mt19937's output is the same everywhere, unlike the standard distributions'.
  std::mt19937 random (0);
  const auto draw = [&] (std::mt19937& engine) {
    return static_cast<std::size_t> (engine()) % points.size();
  };
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
  refinePlane (points, tolerance, plane);
  // The camera (the origin) lies above the plane.
  if (plane[3] < 0.0f)
    plane = -plane;
  return true;
}

bool
growInstanceSurfaces (const pcl::PointCloud<pcl::PointXYZ>& organized,
                      const Eigen::Vector4f& plane,
                      const std::vector<pcl::Indices>& seeds,
                      float max_step,
                      float max_radius,
                      float plane_tolerance,
                      std::vector<pcl::Indices>& surfaces)
{
  surfaces.assign (seeds.size(), pcl::Indices());
  const int width = static_cast<int> (organized.width);
  const int height = static_cast<int> (organized.height);
  if (organized.size() !=
      static_cast<std::size_t> (width) * static_cast<std::size_t> (height)) {
    PCL_ERROR (
        "[mid::growInstanceSurfaces] The cloud is not organized (width x height != "
        "size).\n");
    return false;
  }
  const int pixels = width * height;
  std::vector<Eigen::Vector3f, Eigen::aligned_allocator<Eigen::Vector3f>> centroids (
      seeds.size(), Eigen::Vector3f::Zero());
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    int seeded = 0;
    for (const auto s : seeds[i]) {
      if (s < 0 || s >= pixels) {
        PCL_ERROR (
            "[mid::growInstanceSurfaces] Seed pixel %d is outside the %d x %d frame.\n",
            static_cast<int> (s),
            width,
            height);
        return false;
      }
      if (isFinite (organized[s])) {
        centroids[i] += organized[s].getVector3fMap();
        ++seeded;
      }
    }
    if (seeded > 0)
      centroids[i] /= static_cast<float> (seeded);
  }

  const auto inside = [&] (int pixel, std::size_t object) {
    const auto& p = organized[pixel];
    return isFinite (p) &&
           planeDistance (plane, p.getVector3fMap()) > plane_tolerance &&
           (p.getVector3fMap() - centroids[object]).norm() < max_radius &&
           !inCrease (organized, pixel);
  };
  // Breadth first from every object's seeds at once: a pixel belongs to the object that
  // reaches it first.
  constexpr int kUnreached = -1;
  std::vector<int> label (organized.size(), kUnreached);
  std::deque<int> queue;
  for (std::size_t i = 0; i < seeds.size(); ++i)
    for (const auto s : seeds[i]) {
      if (!inside (s, i))
        continue;
      if (label[static_cast<std::size_t> (s)] == kUnreached) {
        label[static_cast<std::size_t> (s)] = static_cast<int> (i);
        queue.push_back (s);
      }
    }
  while (!queue.empty()) {
    const int pixel = queue.front();
    queue.pop_front();
    const auto object =
        static_cast<std::size_t> (label[static_cast<std::size_t> (pixel)]);
    surfaces[object].push_back (pixel);
    const int row = pixel / width, column = pixel % width;
    const std::array<int, 4> next = {row > 0 ? pixel - width : -1,
                                     row + 1 < height ? pixel + width : -1,
                                     column > 0 ? pixel - 1 : -1,
                                     column + 1 < width ? pixel + 1 : -1};
    for (const int q : next)
      if (q >= 0 && label[static_cast<std::size_t> (q)] == kUnreached &&
          (organized[q].getVector3fMap() - organized[pixel].getVector3fMap()).norm() <
              max_step &&
          inside (q, object)) {
        label[static_cast<std::size_t> (q)] = static_cast<int> (object);
        queue.push_back (q);
      }
  }
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
  std::vector<pcl::Indices> surfaces;
  return growInstanceSurfaces (organized,
                               plane,
                               {seeds},
                               max_step,
                               max_radius,
                               plane_tolerance,
                               surfaces) &&
         fitInstanceBox (organized, plane, surfaces.front(), extent);
}

const char*
surfacePixelsProblem (const pcl::PointCloud<pcl::PointXYZ>& organized,
                      const pcl::Indices& surface)
{
  if (!organized.isOrganized() || organized.empty())
    return "The cloud is not organized";
  const auto count = static_cast<pcl::index_t> (organized.size());
  if (std::any_of (surface.begin(), surface.end(), [&] (pcl::index_t p) {
        return p < 0 || p >= count ||
               !organized[static_cast<std::size_t> (p)].getVector3fMap().allFinite();
      }))
    return "A surface pixel lies outside the cloud or has no point";
  return nullptr;
}

bool
fitInstanceBox (const pcl::PointCloud<pcl::PointXYZ>& organized,
                const Eigen::Vector4f& plane,
                const pcl::Indices& surface,
                InstanceExtent& extent)
{
  extent = InstanceExtent();
  if (static_cast<int> (surface.size()) < kMinExtentPoints)
    return false;
  for (const auto pixel : surface)
    if (pixel < 0 || static_cast<std::size_t> (pixel) >= organized.size() ||
        !isFinite (organized[pixel])) {
      PCL_ERROR ("[mid::fitInstanceBox] Surface pixel %d has no point.\n",
                 static_cast<int> (pixel));
      return false;
    }
  extent.surface = surface;

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
  const std::vector<float> point_heights = heights;
  const float box_height = quantile (heights, kEdgeQuantile);

  // The rectangle gives the footprint's directions; its extents along them are quantiles,
  // so that a few stray points (mixed depth at the silhouette) do not widen it.
  const float angle = rectangle.angle * static_cast<float> (M_PI) / 180.0f;
  const Eigen::Vector2f u (std::cos (angle), std::sin (angle));
  const Eigen::Vector2f v (-u.y(), u.x());
  std::vector<float> along_u, along_v;
  along_u.reserve (footprint.size());
  along_v.reserve (footprint.size());
  for (const auto& f : footprint) {
    along_u.push_back (u.x() * f.x + u.y() * f.y);
    along_v.push_back (v.x() * f.x + v.y() * f.y);
  }
  const std::array<std::vector<float>, 2> along = {along_u, along_v};
  std::array<float, 2> low = {quantile (along_u, 1.0f - kEdgeQuantile),
                              quantile (along_v, 1.0f - kEdgeQuantile)};
  std::array<float, 2> high = {quantile (along_u, kEdgeQuantile),
                               quantile (along_v, kEdgeQuantile)};
  // A can lying down shows the camera half its round side.
  widenShorterEdgeToRoundSide (along, point_heights, box_height, low, high);
  const Eigen::Vector2f centre =
      0.5f * (low[0] + high[0]) * u + 0.5f * (low[1] + high[1]) * v;

  const Eigen::Vector3f along_width = u.x() * e1 + u.y() * e2;
  const Eigen::Vector3f along_height = normal.cross (along_width);
  const std::array<Eigen::Vector3f, 3> axes = {along_width, along_height, normal};
  const std::array<float, 3> edges = {high[0] - low[0], high[1] - low[1], box_height};
  std::array<int, 3> order = {0, 1, 2};
  std::sort (
      order.begin(), order.end(), [&] (int a, int b) { return edges[a] < edges[b]; });

  // The footprint's centre lies on the plane: -offset * normal is the plane's point nearest
  // the origin.
  const Eigen::Vector3f base = -plane[3] * normal + centre.x() * e1 + centre.y() * e2;
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
