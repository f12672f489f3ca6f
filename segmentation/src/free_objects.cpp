#include "free_objects.h"

#include "disjoint_sets.h"

#include <mid/segmentation/touching_surfaces.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace mid {
namespace detail {

namespace {

/** How far outside a found copy's box (its pose times its model's box) the points it claims
  * reach (metres): what its pose may be off by.
  */
constexpr float kClaimMargin = 0.002f;

/** The box an object occupies (fitInstanceBox()). */
OrientedBox
orientedBox (const InstanceExtent& extent)
{
  OrientedBox box;
  box.to_box = extent.pose.inverse();
  box.half = 0.5f * extent.size.array();
  return box;
}

/** Pairs of 4-neighbouring pixels along which the surfaces of two seeds must touch for the
  * seeds to be one object (touchingSurfaces()): a border, not a point where two objects meet.
  */
constexpr int kMinContactPixels = 3;

/** Join the seeds whose surfaces touch along a border (touchingSurfaces()). A seed whose
  * surface is empty (its pixel was another seed's, as SIFT puts keypoints of several
  * orientations on one pixel) joins the seed that holds its pixel.
  */
bool
joinTouchingSurfaces (const pcl::PointCloud<pcl::PointXYZ>& organized,
                      const std::vector<pcl::Indices>& seeds,
                      const std::vector<pcl::Indices>& surfaces,
                      float max_step,
                      detail::DisjointSets& sets)
{
  std::vector<std::pair<std::size_t, std::size_t>> touching;
  if (!touchingSurfaces (organized, surfaces, max_step, kMinContactPixels, touching))
    return false;
  for (const auto& [a, b] : touching)
    sets.unite (a, b);
  constexpr int kNone = -1;
  std::vector<int> holder (organized.size(), kNone);
  for (std::size_t s = 0; s < surfaces.size(); ++s)
    for (const auto pixel : surfaces[s])
      holder[static_cast<std::size_t> (pixel)] = static_cast<int> (s);
  for (std::size_t s = 0; s < seeds.size(); ++s)
    if (surfaces[s].empty())
      for (const auto pixel : seeds[s])
        if (const int h = holder[static_cast<std::size_t> (pixel)]; h != kNone)
          sets.unite (s, static_cast<std::size_t> (h));
  return true;
}

/** How far outside an object's box a point around it may lie and still be the object's own
  * (metres): the steep sides of a can, where its surface did not grow.
  */
constexpr float kOwnPointMargin = 0.003f;

} // namespace

int
upAxis (const InstanceExtent& extent, const Eigen::Vector4f& plane)
{
  const Eigen::Vector3f normal = plane.head<3>();
  int up = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs (extent.pose.col (i).head<3>().dot (normal)) >
        std::abs (extent.pose.col (up).head<3>().dot (normal)))
      up = i;
  return up;
}

OrientedBoxes
foundCopyBoxes (const ObjectModels& models, const ModelSizes& sizes)
{
  OrientedBoxes boxes;
  for (std::size_t m = 0; m < models.size(); ++m) {
    if (!sizes[m].valid)
      continue;
    for (const auto& instance : models[m].instances) {
      boxes.emplace_back();
      boxes.back().to_box = (instance.pose * sizes[m].box_in_model).inverse();
      boxes.back().half = 0.5f * sizes[m].size.array();
    }
  }
  return boxes;
}

pcl::PointCloud<pcl::PointXYZ>
withoutFoundCopies (const pcl::PointCloud<pcl::PointXYZ>& organized,
                    const OrientedBoxes& boxes)
{
  pcl::PointCloud<pcl::PointXYZ> unclaimed = organized;
  for (auto& point : unclaimed.points) {
    if (!std::isfinite (point.z))
      continue;
    for (const auto& box : boxes)
      if (box.holds (point.getVector3fMap(), kClaimMargin)) {
        point.x = point.y = point.z = std::numeric_limits<float>::quiet_NaN();
        break;
      }
  }
  return unclaimed;
}

bool
boxHoldsObserved (const InstanceExtent& box,
                  const KeypointCloud& keypoints,
                  const std::vector<bool>& observed,
                  float margin)
{
  const OrientedBox inner = orientedBox (box);
  for (std::size_t k = 0; k < keypoints.size(); ++k)
    if (observed[k] && inner.holds (keypoints[k].getVector3fMap(), -margin))
      return true;
  return false;
}

float
surroundedShare (const pcl::PointCloud<pcl::PointXYZ>& organized,
                 const Eigen::Vector4f& plane,
                 const InstanceExtent& object,
                 float tolerance)
{
  const pcl::Indices& pixels = object.surface;
  const OrientedBox own = orientedBox (object);
  const int width = static_cast<int> (organized.width);
  const int height = static_cast<int> (organized.height);
  std::vector<std::uint8_t> visited (organized.size(), 0);
  for (const auto p : pixels)
    visited[static_cast<std::size_t> (p)] = 1;
  std::size_t around = 0, occupied = 0;
  for (const auto p : pixels) {
    const int row = p / width, column = p % width;
    for (int r = std::max (0, row - kRingPixels);
         r <= std::min (height - 1, row + kRingPixels);
         ++r)
      for (int c = std::max (0, column - kRingPixels);
           c <= std::min (width - 1, column + kRingPixels);
           ++c) {
        const auto q = static_cast<std::size_t> (r) * static_cast<std::size_t> (width) +
                       static_cast<std::size_t> (c);
        if (visited[q] != 0)
          continue;
        visited[q] = 1;
        ++around;
        const auto& point = organized[q];
        if (std::isfinite (point.z) &&
            std::abs (planeDistance (plane, point.getVector3fMap())) > tolerance &&
            !own.holds (point.getVector3fMap(), kOwnPointMargin))
          ++occupied;
      }
  }
  return around == 0 ? 1.0f
                     : static_cast<float> (occupied) / static_cast<float> (around);
}

ObjectSeeds
objectSeeds (const ObjectModels& models, const pcl::Indices& keypoint_pixels)
{
  ObjectSeeds seeds;
  seeds.observed.assign (keypoint_pixels.size(), false);
  for (const auto& model : models)
    for (const auto& instance : model.instances)
      for (const auto k : instance.keypoints)
        seeds.observed[static_cast<std::size_t> (k)] = true;
  seeds.pixels = instanceSeedPixels (models, keypoint_pixels);
  seeds.instances = seeds.pixels.size();
  for (std::size_t k = 0; k < keypoint_pixels.size(); ++k)
    if (!seeds.observed[k]) {
      seeds.free.push_back (static_cast<pcl::index_t> (k));
      seeds.pixels.push_back ({keypoint_pixels[k]});
    }
  return seeds;
}

bool
freeObjects (const pcl::PointCloud<pcl::PointXYZ>& cloud,
             const pcl::PointCloud<pcl::PointXYZ>& organized,
             const Eigen::Vector4f& plane,
             const ObjectSeeds& seeds,
             const KeypointCloud& keypoints,
             const Growth& growth,
             int min_keypoints,
             FreeObjects& objects,
             FreeObjects* boxing_found)
{
  objects.clear();
  if (boxing_found != nullptr)
    boxing_found->clear();
  std::vector<pcl::Indices> surfaces;
  if (!growInstanceSurfaces (cloud,
                             plane,
                             seeds.pixels,
                             growth.max_step,
                             growth.max_radius,
                             growth.plane_tolerance,
                             surfaces))
    return false;
  detail::DisjointSets sets (seeds.pixels.size());
  if (!joinTouchingSurfaces (cloud, seeds.pixels, surfaces, growth.max_step, sets))
    return false;

  // An instance's seed is the smallest of its set.
  std::vector<std::vector<std::size_t>> members (seeds.pixels.size());
  for (std::size_t s = seeds.instances; s < seeds.pixels.size(); ++s)
    if (sets.find (s) >= seeds.instances)
      members[sets.find (s)].push_back (s);
  for (const auto& object : members) {
    if (object.size() < static_cast<std::size_t> (min_keypoints))
      continue;
    FreeObject free_object;
    for (const std::size_t s : object) {
      free_object.pixels.insert (
          free_object.pixels.end(), surfaces[s].begin(), surfaces[s].end());
      free_object.keypoints.push_back (seeds.free[s - seeds.instances]);
    }
    if (!fitInstanceBox (organized, plane, free_object.pixels, free_object.extent))
      continue;
    if (!boxHoldsObserved (free_object.extent, keypoints, seeds.observed, kBoxMargin))
      objects.push_back (free_object);
    else if (boxing_found != nullptr)
      boxing_found->push_back (free_object);
  }
  return true;
}

} // namespace detail
} // namespace mid
