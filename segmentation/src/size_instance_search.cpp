#include "disjoint_sets.h"

#include <mid/segmentation/instance_extent.h>
#include <mid/segmentation/model_size.h>
#include <mid/segmentation/size_instance_search.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace mid {

namespace {

/** Join the seeds whose surfaces touch: two 4-neighbouring pixels of two surfaces whose points
  * are closer than max_step. A seed whose surface is empty (its pixel was another seed's, as
  * SIFT puts keypoints of several orientations on one pixel) joins the seed that holds its
  * pixel.
  */
void
joinTouchingSurfaces (const pcl::PointCloud<pcl::PointXYZ>& organized,
                      const std::vector<pcl::Indices>& seeds,
                      const std::vector<pcl::Indices>& surfaces,
                      float max_step,
                      detail::DisjointSets& sets)
{
  constexpr int kNone = -1;
  std::vector<int> label (organized.size(), kNone);
  for (std::size_t s = 0; s < surfaces.size(); ++s)
    for (const auto pixel : surfaces[s])
      label[static_cast<std::size_t> (pixel)] = static_cast<int> (s);
  const auto width = static_cast<std::size_t> (organized.width);
  for (std::size_t pixel = 0; pixel < label.size(); ++pixel) {
    if (label[pixel] == kNone)
      continue;
    const bool has_right = (pixel + 1) % width != 0;
    for (const std::size_t next : {has_right ? pixel + 1 : pixel, pixel + width}) {
      if (next == pixel || next >= label.size() || label[next] == kNone ||
          label[next] == label[pixel])
        continue;
      if ((organized[next].getVector3fMap() - organized[pixel].getVector3fMap())
              .norm() < max_step)
        sets.unite (static_cast<std::size_t> (label[pixel]),
                    static_cast<std::size_t> (label[next]));
    }
  }
  for (std::size_t s = 0; s < seeds.size(); ++s)
    if (surfaces[s].empty())
      for (const auto pixel : seeds[s])
        if (label[static_cast<std::size_t> (pixel)] != kNone)
          sets.unite (
              s, static_cast<std::size_t> (label[static_cast<std::size_t> (pixel)]));
}

/** True if one of `keypoints` marked in `observed` lies inside `box`, farther than `margin`
  * from its faces: an object whose box holds a found copy's keypoint is no other copy.
  */
bool
boxHoldsObserved (const InstanceExtent& box,
                  const KeypointCloud& keypoints,
                  const std::vector<bool>& observed,
                  float margin)
{
  const Eigen::Matrix4f to_box = box.pose.inverse();
  const Eigen::Array3f inner = 0.5f * box.size.array() - margin;
  for (std::size_t k = 0; k < keypoints.size(); ++k) {
    if (!observed[k])
      continue;
    const Eigen::Vector3f local =
        to_box.topLeftCorner<3, 3>() * keypoints[k].getVector3fMap() +
        to_box.topRightCorner<3, 1>();
    if ((local.array().abs() < inner).all())
      return true;
  }
  return false;
}

/** The model whose size `size` agrees with, the closest edge by edge if several do; -1 if
  * none.
  */
int
modelOfSize (const Eigen::Vector3f& size,
             const ModelSizes& sizes,
             const SizeAgreement& agree)
{
  int best = -1;
  float best_difference = std::numeric_limits<float>::infinity();
  for (std::size_t m = 0; m < sizes.size(); ++m) {
    if (!sizes[m].valid || !agree (sizes[m].size, size))
      continue;
    const float difference = (sizes[m].size - size).cwiseAbs().maxCoeff();
    if (difference < best_difference) {
      best = static_cast<int> (m);
      best_difference = difference;
    }
  }
  return best;
}

/** How far inside an object's box a found copy's keypoint must lie to rule the object out
  * (metres): touching copies share a face, and their keypoints lie on it.
  */
constexpr float kBoxMargin = 0.005f;

/** Pixels around an object's surface (within this many of it) that tell what it stands on. */
constexpr int kRingPixels = 4;

/** Share of the pixels around `pixels` (within kRingPixels of them, not among them) that hold
  * a point off the support plane (farther than `tolerance` from it): where the object leans on,
  * lies under or stands beside something else. Missing depth (the shadow beside an object)
  * counts as free. 1 if no pixel lies around.
  */
float
surroundedShare (const pcl::PointCloud<pcl::PointXYZ>& organized,
                 const Eigen::Vector4f& plane,
                 const pcl::Indices& pixels,
                 float tolerance)
{
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
            std::abs (planeDistance (plane, point.getVector3fMap())) > tolerance)
          ++occupied;
      }
  }
  return around == 0 ? 1.0f
                     : static_cast<float> (occupied) / static_cast<float> (around);
}

/** An object on the table that no instance observes: its surface, its keypoints and its
  * box.
  */
struct FreeObject
{
  pcl::Indices pixels;
  pcl::Indices keypoints;
  InstanceExtent extent;

  EIGEN_MAKE_ALIGNED_OPERATOR_NEW
};

using FreeObjects = std::vector<FreeObject, Eigen::aligned_allocator<FreeObject>>;

/** Group the objects whose sizes agree with the first of the group (most keypoints first);
  * groups of one are dropped.
  */
std::vector<std::vector<std::size_t>>
groupsOfOneSize (const FreeObjects& objects,
                 const std::vector<std::size_t>& candidates,
                 const SizeAgreement& agree)
{
  std::vector<std::size_t> order = candidates;
  std::stable_sort (
      order.begin(), order.end(), [&objects] (std::size_t a, std::size_t b) {
        return objects[a].keypoints.size() > objects[b].keypoints.size();
      });
  std::vector<bool> grouped (objects.size(), false);
  std::vector<std::vector<std::size_t>> groups;
  for (std::size_t i = 0; i < order.size(); ++i) {
    if (grouped[order[i]])
      continue;
    std::vector<std::size_t> group = {order[i]};
    for (std::size_t j = i + 1; j < order.size(); ++j)
      if (!grouped[order[j]] &&
          agree (objects[order[i]].extent.size, objects[order[j]].extent.size))
        group.push_back (order[j]);
    if (group.size() < 2)
      continue;
    for (const std::size_t g : group)
      grouped[g] = true;
    groups.push_back (group);
  }
  return groups;
}

} // namespace

std::string
SizeInstanceSearch::inputProblem (const ObjectModels& models) const
{
  if (std::string problem = measurementProblem (models); !problem.empty())
    return problem;
  if (!descriptors_ || descriptors_->size() != keypoints_->size())
    return "the descriptors are not one per keypoint";
  if (min_keypoints_ < 1)
    return "one keypoint at least must make an instance";
  if (!(max_surrounded_share_ >= 0.0f && max_surrounded_share_ <= 1.0f) ||
      !(min_model_edge_ >= 0.0f) || !std::isfinite (min_model_edge_))
    return "the surrounded share must be in [0, 1] and the shortest edge finite and >= "
           "0";
  return "";
}

bool
SizeInstanceSearch::search (ObjectModels& models, std::size_t& found) const
{
  found = 0;
  const std::string problem = inputProblem (models);
  if (!problem.empty()) {
    PCL_ERROR ("[mid::SizeInstanceSearch::search] %s.\n", problem.c_str());
    return false;
  }
  if (models.empty() && !discover_models_)
    return true;
  const auto& organized = *surface_.organized;
  Eigen::Vector4f plane;
  if (!fitPlane (plane))
    return true;
  const SizeAgreement agree = agreement();
  ModelSizes sizes;
  if (!measureSizes (models, plane, sizes))
    return false;
  if (!discover_models_ &&
      std::none_of (sizes.begin(), sizes.end(), [] (const ModelSize& size) {
        return size.valid;
      }))
    return true;

  // Seeds: every instance (its keypoints' pixels), then every keypoint no instance observes.
  std::vector<bool> observed (keypoints_->size(), false);
  for (const auto& model : models)
    for (const auto& instance : model.instances)
      for (const auto k : instance.keypoints)
        observed[static_cast<std::size_t> (k)] = true;
  std::vector<pcl::Indices> seeds =
      instanceSeedPixels (models, surface_.keypoint_pixels);
  const std::size_t instance_seeds = seeds.size();
  pcl::Indices free;
  for (std::size_t k = 0; k < observed.size(); ++k)
    if (!observed[k]) {
      free.push_back (static_cast<pcl::index_t> (k));
      seeds.push_back ({surface_.keypoint_pixels[k]});
    }
  std::vector<pcl::Indices> surfaces;
  if (!growInstanceSurfaces (
          organized, plane, seeds, max_step_, max_radius_, plane_tolerance_, surfaces))
    return false;
  detail::DisjointSets sets (seeds.size());
  joinTouchingSurfaces (organized, seeds, surfaces, max_step_, sets);

  // Objects of free keypoints alone: an instance's seed is the smallest of its set.
  std::vector<std::vector<std::size_t>> objects (seeds.size());
  for (std::size_t s = instance_seeds; s < seeds.size(); ++s)
    if (sets.find (s) >= instance_seeds)
      objects[sets.find (s)].push_back (s);
  FreeObjects free_objects;
  for (const auto& object : objects) {
    if (object.size() < static_cast<std::size_t> (min_keypoints_))
      continue;
    FreeObject free_object;
    for (const std::size_t s : object) {
      free_object.pixels.insert (
          free_object.pixels.end(), surfaces[s].begin(), surfaces[s].end());
      free_object.keypoints.push_back (free[s - instance_seeds]);
    }
    if (fitInstanceBox (organized, plane, free_object.pixels, free_object.extent) &&
        !boxHoldsObserved (free_object.extent, *keypoints_, observed, kBoxMargin))
      free_objects.push_back (free_object);
  }

  // A copy of a model's size joins it; an object standing alone, of no model's size, may
  // found a model with others of its size.
  std::vector<std::size_t> alone;
  for (std::size_t o = 0; o < free_objects.size(); ++o) {
    const FreeObject& object = free_objects[o];
    const int m = modelOfSize (object.extent.size, sizes, agree);
    if (m >= 0) {
      addInstanceOfKeypoints (
          *keypoints_,
          *descriptors_,
          object.keypoints,
          object.extent.pose *
              sizes[static_cast<std::size_t> (m)].box_in_model.inverse(),
          models[static_cast<std::size_t> (m)]);
      ++found;
    }
    else if (discover_models_ && object.extent.size.minCoeff() >= min_model_edge_ &&
             surroundedShare (
                 organized, plane, object.pixels, 2.0f * plane_tolerance_) <=
                 max_surrounded_share_)
      alone.push_back (o);
  }
  // The model frame is the first copy's box frame (centred on the landmarks after).
  for (const auto& group : groupsOfOneSize (free_objects, alone, agree)) {
    ObjectModel model;
    for (const std::size_t o : group)
      addInstanceOfKeypoints (*keypoints_,
                              *descriptors_,
                              free_objects[o].keypoints,
                              free_objects[o].extent.pose,
                              model);
    centerModelFrame (model);
    models.push_back (model);
    found += group.size();
  }
  return true;
}

} // namespace mid
