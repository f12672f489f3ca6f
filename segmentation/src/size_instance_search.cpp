#include "disjoint_sets.h"

#include <mid/segmentation/flat_top_parts.h>
#include <mid/segmentation/footprint_copy_sizes.h>
#include <mid/segmentation/footprint_split.h>
#include <mid/segmentation/instance_extent.h>
#include <mid/segmentation/model_size.h>
#include <mid/segmentation/occluded_outline.h>
#include <mid/segmentation/size_instance_search.h>
#include <mid/segmentation/touching_surfaces.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace mid {

namespace {

/** How far outside a found copy's box (its pose times its model's box) the points it claims
  * reach (metres): what its pose may be off by.
  */
constexpr float kClaimMargin = 0.002f;

/** A box in the camera frame (camera -> box frame, and half its edges), and the test of the
  * points inside it.
  */
struct OrientedBox
{
  Eigen::Matrix4f to_box = Eigen::Matrix4f::Identity();
  Eigen::Array3f half = Eigen::Array3f::Zero();

  bool
  holds (const Eigen::Vector3f& point, float margin) const
  {
    const Eigen::Vector3f local =
        to_box.topLeftCorner<3, 3>() * point + to_box.topRightCorner<3, 1>();
    return (local.array().abs() < half + margin).all();
  }

  EIGEN_MAKE_ALIGNED_OPERATOR_NEW
};

using OrientedBoxes = std::vector<OrientedBox, Eigen::aligned_allocator<OrientedBox>>;

/** The box an object occupies (fitInstanceBox()). */
OrientedBox
orientedBox (const InstanceExtent& extent)
{
  OrientedBox box;
  box.to_box = extent.pose.inverse();
  box.half = 0.5f * extent.size.array();
  return box;
}

/** The boxes of the found copies of the models with a size. */
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

/** `organized` without the points inside the found copies' boxes (NaN there): a copy
  * touching a found one, flush, then grows over its own surface alone instead of over the
  * found copy's too.
  */
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

/** True if one of `keypoints` marked in `observed` lies inside `box`, farther than `margin`
  * from its faces: an object whose box holds a found copy's keypoint is no other copy.
  */
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

/** The model of `size`, -1 if none: the closest (edge by edge) of the models whose size agrees
  * with it, else the first whose size rests on one measured copy alone and which has another
  * copy of `size` (boxOfSize()): with the object, two copies agree on it. `box_in_model` is
  * then the box of `size` in that model.
  */
int
modelOfSize (const Eigen::Vector3f& size,
             const ObjectModels& models,
             const ModelSizes& sizes,
             const std::vector<InstanceExtents>& extents,
             const SizeAgreement& agree,
             Eigen::Matrix4f& box_in_model)
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
      box_in_model = sizes[m].box_in_model;
    }
  }
  // No two of such a model's measured copies agree (its size is one copy's): ModelSize() has
  // no size of its own, so only its copies' boxes are looked at.
  for (std::size_t m = 0; best < 0 && m < sizes.size(); ++m)
    if (sizes[m].valid && sizes[m].agreeing < 2 &&
        boxOfSize (size, ModelSize(), models[m], extents[m], agree, box_in_model))
      best = static_cast<int> (m);
  return best;
}

/** How far inside an object's box a found copy's keypoint must lie to rule the object out
  * (metres): touching copies share a face, and their keypoints lie on it.
  */
constexpr float kBoxMargin = 0.005f;

/** Pixels around an object's surface (within this many of it) that tell what it stands on. */
constexpr int kRingPixels = 4;

/** How far outside an object's box a point around it may lie and still be the object's own
  * (metres): the steep sides of a can, where its surface did not grow.
  */
constexpr float kOwnPointMargin = 0.003f;

/** Share of the pixels around an object's surface (within kRingPixels of it, not on it) that
  * hold a point off the support plane (farther than `tolerance` from it) and outside the
  * object's box (grown by kOwnPointMargin): where the object leans on, lies under or stands
  * beside something else. Missing depth (the shadow beside an object) counts as free. 1 if
  * no pixel lies around.
  */
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

/** How much nearer the camera than an object's outline a point around it must lie to hide
  * part of the object (metres; occludedOutlineShare()).
  */
constexpr float kOccluderStep = 0.01f;

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

/** The seeds the objects grow from: every instance (its keypoints' pixels), then every
  * keypoint no instance observes.
  */
struct ObjectSeeds
{
  std::vector<pcl::Indices> pixels;
  std::size_t instances = 0;  ///< the first seeds, one per instance
  pcl::Indices free;          ///< the keypoint of each seed after them
  std::vector<bool> observed; ///< by keypoint: an instance observes it
};

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

/** How the surfaces grow (growInstanceSurfaces()). */
struct Growth
{
  float max_step, max_radius, plane_tolerance;
};

/** The objects of free keypoints alone (at least `min_keypoints`) whose surfaces, grown in
  * `cloud` (`organized` or a part of it), give a box that holds no instance's keypoint; those
  * whose box does hold one go to `boxing_found`, if given.
  */
bool
freeObjects (const pcl::PointCloud<pcl::PointXYZ>& cloud,
             const pcl::PointCloud<pcl::PointXYZ>& organized,
             const Eigen::Vector4f& plane,
             const ObjectSeeds& seeds,
             const KeypointCloud& keypoints,
             const Growth& growth,
             int min_keypoints,
             FreeObjects& objects,
             FreeObjects* boxing_found = nullptr)
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

/** Cells of the footprint raster when copies touching flush are cut apart (metres; a tenth of
  * the rectangle's shortest edge if that is less).
  */
constexpr float kFootprintCell = 0.004f;
/** Share of a copy's rectangle its cut of the footprint must cover. */
constexpr float kFootprintCoverage = 0.75f;

/** How far outside every copy's rectangle a point of a group of flush copies may lie and still
  * go to the nearest (metres): a copy's rectangle cuts the group only where another copy
  * lies beyond it; elsewhere the object's own outline ends the copy.
  */
constexpr float kFootprintReach = 0.05f;

/** The plane's 2D coordinates (along two axes orthogonal to its normal) of 3D points. */
class PlaneCoordinates
{
public:
  explicit PlaneCoordinates (const Eigen::Vector4f& plane)
  : e1_ (plane.head<3>().unitOrthogonal()), e2_ (plane.head<3>().cross (e1_))
  {}

  Eigen::Vector2f
  operator() (const Eigen::Vector3f& point) const
  {
    return {e1_.dot (point), e2_.dot (point)};
  }

private:
  Eigen::Vector3f e1_, e2_;
};

using Footprint =
    std::vector<Eigen::Vector2f, Eigen::aligned_allocator<Eigen::Vector2f>>;

/** The object's points projected onto the plane, in the order of its pixels. */
Footprint
footprintOf (const pcl::PointCloud<pcl::PointXYZ>& organized,
             const PlaneCoordinates& on_plane,
             const FreeObject& object)
{
  Footprint footprint;
  footprint.reserve (object.pixels.size());
  for (const auto pixel : object.pixels)
    footprint.push_back (on_plane (organized[pixel].getVector3fMap()));
  return footprint;
}

/** The axis of the box that stands up: the one closest to the plane's normal. */
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

/** The object's height above the plane: its box's edge along upAxis(). */
float
heightOf (const InstanceExtent& extent, const Eigen::Vector4f& plane)
{
  return extent.size[upAxis (extent, plane)];
}

/** The parts of `object` that copies of a box of `size` (a model's), touching each other
  * flush with their tops at one height, occupy (splitFootprint()): its pixels and keypoints
  * nearest each copy's rectangle on the plane (within kFootprintReach), with the box fitted to
  * them, so that a copy is measured on its own outline, not on the rectangle. None if the
  * object's height is none of the box's edges or its footprint is not such a group.
  */
FreeObjects
flushCopies (const pcl::PointCloud<pcl::PointXYZ>& organized,
             const Eigen::Vector4f& plane,
             const KeypointCloud& keypoints,
             const FreeObject& object,
             const Eigen::Vector3f& size,
             const SizeAgreement& agree)
{
  FreeObjects parts;
  // The box's edge closest to the object's height stands up.
  const float object_height = heightOf (object.extent, plane);
  int height = -1;
  for (int i = 0; i < 3; ++i)
    if (agree.edgesAgree (object_height, size[i]) &&
        (height < 0 ||
         std::abs (size[i] - object_height) < std::abs (size[height] - object_height)))
      height = i;
  if (height < 0)
    return parts;
  const Eigen::Vector2f rectangle (size[(height + 1) % 3], size[(height + 2) % 3]);

  const PlaneCoordinates on_plane (plane);
  const Footprint footprint = footprintOf (organized, on_plane, object);
  FootprintRectangles copies;
  const float cell = std::min (kFootprintCell, 0.1f * rectangle.minCoeff());
  if (!splitFootprint (footprint, rectangle, cell, kFootprintCoverage, copies))
    return parts;
  const auto nearest = [&copies] (const Eigen::Vector2f& point) {
    int best = -1;
    float best_distance = kFootprintReach;
    for (std::size_t c = 0; c < copies.size(); ++c)
      if (const float d = copies[c].distance (point); d <= best_distance) {
        best = static_cast<int> (c);
        best_distance = d;
      }
    return best;
  };
  FreeObjects cut (copies.size());
  for (std::size_t i = 0; i < footprint.size(); ++i)
    if (const int c = nearest (footprint[i]); c >= 0)
      cut[static_cast<std::size_t> (c)].pixels.push_back (object.pixels[i]);
  for (const auto k : object.keypoints)
    if (const int c = nearest (
            on_plane (keypoints[static_cast<std::size_t> (k)].getVector3fMap()));
        c >= 0)
      cut[static_cast<std::size_t> (c)].keypoints.push_back (k);
  for (auto& part : cut)
    if (fitInstanceBox (organized, plane, part.pixels, part.extent))
      parts.push_back (part);
  return parts;
}

/** The rectangles that the boxes of `objects` occupy on the plane (their edges other than
  * the height).
  */
FootprintRectangles
footprintRectangles (const FreeObjects& objects, const Eigen::Vector4f& plane)
{
  const PlaneCoordinates on_plane (plane);
  FootprintRectangles rectangles;
  for (const FreeObject& object : objects) {
    const InstanceExtent& box = object.extent;
    const int up = upAxis (box, plane);
    const int first = (up + 1) % 3, second = (up + 2) % 3;
    FootprintRectangle rectangle;
    rectangle.centre = on_plane (box.pose.topRightCorner<3, 1>());
    rectangle.direction = on_plane (box.pose.col (first).head<3>()).normalized();
    rectangle.size = Eigen::Vector2f (box.size[first], box.size[second]);
    rectangles.push_back (rectangle);
  }
  return rectangles;
}

/** Largest share of the smallest rectangle around an object's footprint that two or three
  * copies touching each other may fill (footprintCopySizes()): a footprint that fills more may
  * be one box of its size.
  */
constexpr float kMaxCopiesFill = 0.85f;

/** Largest share of an object's outline that something in front may hide for its outline to
  * tell its copies' edges (occludedOutlineShare()): copies hidden in part show edges that are
  * the occluder's. Two copies cut apart on the benchmark measure 0.01 to 0.09; an L that a box
  * in front left of two copies, 0.25.
  */
constexpr float kMaxOccludedShare = 0.15f;

/** Shortest edge of copies cut by their outline (metres), whatever the models' shortest edge:
  * the raster's cells (a tenth of the edge, 4 mm at most) measure 2 cm to a tenth.
  */
constexpr float kMinOutlineEdge = 0.02f;

/** The parts of `object`, of no model's size, that two or three copies of one box of unknown
  * size occupy, touching each other with their tops at one height, when its footprint is no
  * rectangle and something in front hides at most kMaxOccludedShare of its outline: cut by
  * each rectangle that the edges of its outline give (footprintCopySizes()), the object's
  * height the box's third edge (flushCopies()), the first cut into parts that each hold
  * `min_keypoints`, have no edge shorter than `min_edge` (kMinOutlineEdge at least), agree
  * in size with the first part and, at twice the tolerances (the outline's edges are a
  * raster's), with the box, and whose boxes fill at most kMaxCopiesFill of the rectangle
  * around them on the plane (rectanglesFill(): a long prism cut along its length fills it).
  * None if no cut does.
  */
FreeObjects
copiesOfItsOutline (const pcl::PointCloud<pcl::PointXYZ>& organized,
                    const Eigen::Vector4f& plane,
                    const KeypointCloud& keypoints,
                    const FreeObject& object,
                    const SizeAgreement& agree,
                    int min_keypoints,
                    float min_edge)
{
  const float edge = std::max (min_edge, kMinOutlineEdge);
  std::vector<Eigen::Vector2f, Eigen::aligned_allocator<Eigen::Vector2f>> rectangles;
  if (!footprintCopySizes (footprintOf (organized, PlaneCoordinates (plane), object),
                           std::min (kFootprintCell, 0.1f * edge),
                           edge,
                           kMaxCopiesFill,
                           rectangles))
    return {};
  float occluded = 0.0f;
  if (!occludedOutlineShare (
          organized, object.pixels, kRingPixels, kOccluderStep, occluded) ||
      occluded > kMaxOccludedShare)
    return {};
  const SizeAgreement loose = agree.scaled (2.0f);
  for (const auto& rectangle : rectangles) {
    Eigen::Vector3f box (heightOf (object.extent, plane), rectangle.x(), rectangle.y());
    std::sort (box.data(), box.data() + 3);
    FreeObjects parts = flushCopies (organized, plane, keypoints, object, box, agree);
    const bool copies =
        parts.size() >= 2 &&
        std::all_of (parts.begin(), parts.end(), [&] (const FreeObject& part) {
          return part.keypoints.size() >= static_cast<std::size_t> (min_keypoints) &&
                 part.extent.size.minCoeff() >= edge &&
                 agree (part.extent.size, parts.front().extent.size) &&
                 loose (part.extent.size, box);
        });
    if (copies && rectanglesFill (footprintRectangles (parts, plane)) <= kMaxCopiesFill)
      return parts;
  }
  return {};
}

/** The parts of `object` under the flat tops of a box of `size` (flatTopParts()), each with
  * the object's keypoints whose pixel it holds and measured on its own (fitInstanceBox()):
  * those with at least `min_keypoints` of them, not all.
  */
FreeObjects
flatTopCopies (const pcl::PointCloud<pcl::PointXYZ>& organized,
               const Eigen::Vector4f& plane,
               const pcl::Indices& keypoint_pixels,
               const FreeObject& object,
               const Eigen::Vector3f& size,
               int min_keypoints)
{
  std::vector<pcl::Indices> parts;
  if (!flatTopParts (organized, plane, object.pixels, size, parts))
    return {};
  FreeObjects copies;
  std::vector<std::uint8_t> in_part (organized.size(), 0);
  for (const pcl::Indices& pixels : parts) {
    FreeObject copy;
    copy.pixels = pixels;
    for (const auto p : pixels)
      in_part[static_cast<std::size_t> (p)] = 1;
    for (const auto k : object.keypoints)
      if (in_part[static_cast<std::size_t> (
              keypoint_pixels[static_cast<std::size_t> (k)])] != 0)
        copy.keypoints.push_back (k);
    for (const auto p : pixels)
      in_part[static_cast<std::size_t> (p)] = 0;
    if (copy.keypoints.size() >= static_cast<std::size_t> (min_keypoints) &&
        copy.keypoints.size() < object.keypoints.size() &&
        fitInstanceBox (organized, plane, copy.pixels, copy.extent))
      copies.push_back (copy);
  }
  return copies;
}

/** The copy of a box of `size` that `object` holds, joined with something else, found by its
  * flat top (flatTopCopies()): the first part whose box has that size. None otherwise.
  */
FreeObjects
copyByItsFlatTop (const pcl::PointCloud<pcl::PointXYZ>& organized,
                  const Eigen::Vector4f& plane,
                  const pcl::Indices& keypoint_pixels,
                  const FreeObject& object,
                  const Eigen::Vector3f& size,
                  const SizeAgreement& agree,
                  int min_keypoints)
{
  for (const FreeObject& copy :
       flatTopCopies (organized, plane, keypoint_pixels, object, size, min_keypoints))
    if (agree (copy.extent.size, size))
      return {copy};
  return {};
}

/** Two or more copies of one box of unknown size that `object`, of no model's size, holds,
  * joined with each other (one standing, one lying, or at right angles) and none seen alone:
  * for each box that a flat top of the object suggests (flatTopSizes()), no edge shorter
  * than `min_edge`, its parts (flatTopCopies(); a part holding no keypoint that an earlier one
  * does not is the same top again) with no edge shorter than `min_edge` that agree in size
  * with the first of them and, at twice the tolerances (a suggestion is a level patch's
  * rectangle, not a measured box), with the suggestion. A keypoint two parts hold (where the
  * copies touch) is neither's; the first suggestion that leaves two parts of `min_keypoints`
  * gives the copies. None otherwise.
  */
FreeObjects
copiesOfItsFlatTops (const pcl::PointCloud<pcl::PointXYZ>& organized,
                     const Eigen::Vector4f& plane,
                     const pcl::Indices& keypoint_pixels,
                     const FreeObject& object,
                     const SizeAgreement& agree,
                     int min_keypoints,
                     float min_edge)
{
  std::vector<Eigen::Vector3f> suggestions;
  if (!flatTopSizes (organized, plane, object.pixels, suggestions))
    return {};
  const SizeAgreement loose = agree.scaled (2.0f);
  std::vector<int> holders (keypoint_pixels.size(), 0);
  for (const Eigen::Vector3f& suggestion : suggestions) {
    if (suggestion.minCoeff() < min_edge)
      continue;
    FreeObjects copies;
    for (FreeObject& part : flatTopCopies (
             organized, plane, keypoint_pixels, object, suggestion, min_keypoints)) {
      if (part.extent.size.minCoeff() < min_edge ||
          !loose (part.extent.size, suggestion) ||
          (!copies.empty() && !agree (part.extent.size, copies.front().extent.size)) ||
          std::all_of (
              part.keypoints.begin(), part.keypoints.end(), [&] (pcl::index_t k) {
                return holders[static_cast<std::size_t> (k)] > 0;
              }))
        continue;
      for (const auto k : part.keypoints)
        ++holders[static_cast<std::size_t> (k)];
      copies.push_back (std::move (part));
    }
    std::vector<pcl::Indices> own (copies.size());
    for (std::size_t c = 0; c < copies.size(); ++c)
      for (const auto k : copies[c].keypoints)
        if (holders[static_cast<std::size_t> (k)] == 1)
          own[c].push_back (k);
    FreeObjects kept;
    for (std::size_t c = 0; c < copies.size(); ++c) {
      for (const auto k : copies[c].keypoints)
        holders[static_cast<std::size_t> (k)] = 0;
      copies[c].keypoints = own[c];
      if (own[c].size() >= static_cast<std::size_t> (min_keypoints))
        kept.push_back (std::move (copies[c]));
    }
    if (kept.size() >= 2)
      return kept;
  }
  return {};
}

/** How much looser than the size tolerance the sizes of two objects that no other agrees with
  * may agree for the two to be a group, when they look alike (colourOverlap()): copies
  * measured a little off (a length 5 mm short where a neighbour hides an end, 2 mm long where
  * its rim shows). On the benchmark's 440 development frames, 1.5 gave four such pairs, three
  * of copies and one of a soy-milk and a juice carton (11 mm apart on 200), which the colours
  * tell apart; 2 made false models that the colours let through (doc/benchmark.md, session
  * 38).
  */
constexpr float kLoosePairFactor = 1.5f;

/** Chromaticity bins along each of its two axes (colourOverlap()). */
constexpr int kColourBins = 6;

/** Smallest share of two objects' colours that must overlap (colourOverlap()) for their sizes
  * to agree at kLoosePairFactor: copies that show different faces still share much of their
  * print's colours. The three loose pairs of copies on the benchmark overlap by 0.53, 0.92
  * and 0.94, the soy-milk and juice cartons by 0.16, a black and a white mug of a real table by
  * 0.21. The groups of one size overlap by 0.24 to 1 (0.71 in the median group, a tenth below
  * 0.38): too little for a check of every group, enough for the pairs the size alone does not
  * make.
  */
constexpr float kMinLoosePairColourOverlap = 0.5f;

/** The share of their pixels two objects' colours have in common: the intersection of their
  * histograms over kColourBins x kColourBins chromaticity bins and one of the pixels too dark
  * to tell. 0 without chromaticities.
  */
float
colourOverlap (const KeypointSurface& surface, const FreeObject& a, const FreeObject& b)
{
  if (!surface.chromaticity || a.pixels.empty() || b.pixels.empty())
    return 0.0f;
  constexpr int kDark = kColourBins * kColourBins;
  const auto histogram = [&surface] (const pcl::Indices& pixels) {
    std::vector<float> shares (kDark + 1, 0.0f);
    for (const auto p : pixels) {
      const Chromaticity& c = (*surface.chromaticity)[static_cast<std::size_t> (p)];
      const auto bin = [] (float share) {
        return std::clamp (static_cast<int> (share * kColourBins), 0, kColourBins - 1);
      };
      const int cell = std::isfinite (c[0]) && std::isfinite (c[1])
                           ? bin (c[0]) * kColourBins + bin (c[1])
                           : kDark;
      shares[static_cast<std::size_t> (cell)] +=
          1.0f / static_cast<float> (pixels.size());
    }
    return shares;
  };
  const std::vector<float> first = histogram (a.pixels), second = histogram (b.pixels);
  float overlap = 0.0f;
  for (std::size_t i = 0; i < first.size(); ++i)
    overlap += std::min (first[i], second[i]);
  return overlap;
}

/** Group the objects whose sizes agree with the first of the group (most keypoints first);
  * then two objects no other agrees with whose sizes agree at kLoosePairFactor times the
  * tolerances and whose colours overlap by kMinLoosePairColourOverlap (the first such of
  * each, in that order) are a group; an object left is a group of its own.
  */
std::vector<std::vector<std::size_t>>
groupsOfOneSize (const FreeObjects& objects,
                 const std::vector<std::size_t>& candidates,
                 const SizeAgreement& agree,
                 const KeypointSurface& surface)
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
    for (const std::size_t g : group)
      grouped[g] = true;
    groups.push_back (group);
  }
  const SizeAgreement loose = agree.scaled (kLoosePairFactor);
  const auto sizeOf = [&objects] (const std::vector<std::size_t>& group) {
    return objects[group.front()].extent.size;
  };
  for (std::size_t a = 0; a < groups.size(); ++a) {
    if (groups[a].size() != 1)
      continue;
    const auto b = std::find_if (groups.begin() + static_cast<std::ptrdiff_t> (a + 1),
                                 groups.end(),
                                 [&] (const std::vector<std::size_t>& other) {
                                   return other.size() == 1 &&
                                          loose (sizeOf (groups[a]), sizeOf (other)) &&
                                          colourOverlap (surface,
                                                         objects[groups[a].front()],
                                                         objects[other.front()]) >=
                                              kMinLoosePairColourOverlap;
                                 });
    if (b != groups.end()) {
      groups[a].push_back (b->front());
      groups.erase (b);
    }
  }
  // Larger groups first: their size is the better evidence.
  std::stable_sort (
      groups.begin(),
      groups.end(),
      [] (const std::vector<std::size_t>& a, const std::vector<std::size_t>& b) {
        return a.size() > b.size();
      });
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
  std::vector<InstanceExtents> extents;
  if (!measureBoxes (models, plane, extents))
    return false;
  ModelSizes sizes;
  modelSizesOfBoxes (models, extents, agree, min_agreeing_, sizes);
  if (!discover_models_ &&
      std::none_of (sizes.begin(), sizes.end(), [] (const ModelSize& size) {
        return size.valid;
      }))
    return true;

  // The objects as they lie, and those beside the found copies of a measured model, grown
  // with the points inside those copies' boxes left out.
  const ObjectSeeds seeds = objectSeeds (models, surface_.keypoint_pixels);
  const Growth growth{max_step_, max_radius_, plane_tolerance_};
  FreeObjects free_objects, beside_found, boxing_found;
  const auto boxes = foundCopyBoxes (models, sizes);
  if (!freeObjects (organized,
                    organized,
                    plane,
                    seeds,
                    *keypoints_,
                    growth,
                    min_keypoints_,
                    free_objects,
                    &boxing_found) ||
      (!boxes.empty() && !freeObjects (withoutFoundCopies (organized, boxes),
                                       organized,
                                       plane,
                                       seeds,
                                       *keypoints_,
                                       growth,
                                       min_keypoints_,
                                       beside_found)))
    return false;

  // A copy of a model's size joins it (measured beside the found copies first), unless one of
  // its keypoints went to another copy already.
  std::vector<bool> taken (keypoints_->size(), false);
  const auto untaken = [&taken] (const FreeObject& object) {
    return std::none_of (
        object.keypoints.begin(), object.keypoints.end(), [&taken] (pcl::index_t k) {
          return taken[static_cast<std::size_t> (k)];
        });
  };
  // The model of the object's size, -1 if none; it joins that model unless one of its
  // keypoints went to another copy already.
  const auto joinModelOfItsSize = [&] (const FreeObject& object) {
    Eigen::Matrix4f box_in_model = Eigen::Matrix4f::Identity();
    const int m =
        modelOfSize (object.extent.size, models, sizes, extents, agree, box_in_model);
    if (m < 0 || !untaken (object))
      return m;
    addInstanceOfKeypoints (*keypoints_,
                            *descriptors_,
                            object.keypoints,
                            object.extent.pose * box_in_model.inverse(),
                            models[static_cast<std::size_t> (m)]);
    for (const auto k : object.keypoints)
      taken[static_cast<std::size_t> (k)] = true;
    ++found;
    return m;
  };
  const auto copyOfItsFlatTop = [&] (const FreeObject& object,
                                     const Eigen::Vector3f& size) {
    return copyByItsFlatTop (organized,
                             plane,
                             surface_.keypoint_pixels,
                             object,
                             size,
                             agree,
                             min_keypoints_);
  };
  // An object of no model's size may be copies of one touching each other flush, or hold one
  // joined with something else.
  const auto joinModelOrCutIntoCopies = [&] (const FreeObject& object) {
    int m = joinModelOfItsSize (object);
    for (std::size_t other = 0; m < 0 && other < sizes.size(); ++other) {
      if (!sizes[other].valid || !untaken (object))
        continue;
      for (const FreeObject& part : flushCopies (
               organized, plane, *keypoints_, object, sizes[other].size, agree))
        if (part.keypoints.size() >= static_cast<std::size_t> (min_keypoints_))
          m = std::max (m, joinModelOfItsSize (part));
      if (m < 0)
        for (const FreeObject& copy : copyOfItsFlatTop (object, sizes[other].size))
          m = joinModelOfItsSize (copy);
    }
    return m;
  };
  for (const FreeObject& object : beside_found)
    joinModelOrCutIntoCopies (object);
  // An object of no model's size, of the shortest edge asked for (and standing alone when
  // asked), may found a model with others of its size; the other objects of no model's size
  // may be copies of it touching each other flush.
  std::vector<std::size_t> founders, others;
  for (std::size_t o = 0; o < free_objects.size(); ++o) {
    const FreeObject& object = free_objects[o];
    if (joinModelOrCutIntoCopies (object) >= 0 || !discover_models_ ||
        !untaken (object))
      continue;
    if (object.extent.size.minCoeff() >= min_model_edge_ &&
        (max_surrounded_share_ >= 1.0f ||
         surroundedShare (organized, plane, object.extent, 2.0f * plane_tolerance_) <=
             max_surrounded_share_))
      founders.push_back (o);
    else
      others.push_back (o);
  }
  // The model frame is the first copy's box frame (centred on the landmarks after).
  const auto addModelOfCopies = [&] (const FreeObjects& copies) {
    ObjectModel model;
    for (const FreeObject& copy : copies) {
      addInstanceOfKeypoints (
          *keypoints_, *descriptors_, copy.keypoints, copy.extent.pose, model);
      for (const auto k : copy.keypoints)
        taken[static_cast<std::size_t> (k)] = true;
    }
    centerModelFrame (model);
    models.push_back (model);
    found += copies.size();
  };
  std::vector<std::size_t> candidates = founders;
  candidates.insert (candidates.end(), others.begin(), others.end());
  std::vector<bool> used (free_objects.size(), false);
  for (const auto& group : groupsOfOneSize (free_objects, founders, agree, surface_)) {
    FreeObjects copies;
    std::vector<std::size_t> sources;
    for (const std::size_t o : group)
      if (!used[o]) {
        copies.push_back (free_objects[o]);
        sources.push_back (o);
      }
    if (copies.empty())
      continue;
    // A size seen once cuts no group of copies (a box may be two of another), but it finds a
    // copy whose own top shows in a join with something else.
    const bool seen_once = copies.size() < 2;
    const Eigen::Vector3f size = copies.front().extent.size;
    for (const std::size_t o : candidates) {
      if (used[o] || std::find (group.begin(), group.end(), o) != group.end())
        continue;
      FreeObjects parts;
      if (!seen_once)
        for (const FreeObject& part :
             flushCopies (organized, plane, *keypoints_, free_objects[o], size, agree))
          if (part.keypoints.size() >= static_cast<std::size_t> (min_keypoints_) &&
              agree (part.extent.size, size))
            parts.push_back (part);
      if (parts.size() < 2)
        parts = copyOfItsFlatTop (free_objects[o], size);
      if (parts.empty())
        continue;
      sources.push_back (o);
      copies.insert (copies.end(), parts.begin(), parts.end());
    }
    if (copies.size() < 2)
      continue;
    for (const std::size_t o : sources)
      used[o] = true;
    addModelOfCopies (copies);
  }
  // Copies cut by their outline join the model of their size, as objects of it do, if they
  // all have one; else they make a model.
  const auto addCopies = [&] (const FreeObjects& copies) {
    Eigen::Matrix4f box_in_model;
    if (std::all_of (copies.begin(), copies.end(), [&] (const FreeObject& copy) {
          return modelOfSize (
                     copy.extent.size, models, sizes, extents, agree, box_in_model) >=
                 0;
        })) {
      for (const FreeObject& copy : copies)
        joinModelOfItsSize (copy);
      return;
    }
    addModelOfCopies (copies);
  };
  // What is left may be copies of one box touching each other, none measured alone, whose
  // footprint shows their edges.
  for (const std::size_t o : candidates) {
    if (used[o])
      continue;
    FreeObjects copies = copiesOfItsFlatTops (organized,
                                              plane,
                                              surface_.keypoint_pixels,
                                              free_objects[o],
                                              agree,
                                              min_keypoints_,
                                              min_model_edge_);
    if (copies.size() < 2)
      copies = copiesOfItsOutline (organized,
                                   plane,
                                   *keypoints_,
                                   free_objects[o],
                                   agree,
                                   min_keypoints_,
                                   min_model_edge_);
    if (copies.size() < 2)
      continue;
    used[o] = true;
    addCopies (copies);
  }
  // An object that is no rectangle has a box that may reach around a found copy: its parts'
  // boxes must not.
  for (const FreeObject& object : boxing_found) {
    if (!discover_models_ || !untaken (object))
      continue;
    const FreeObjects copies = copiesOfItsOutline (
        organized, plane, *keypoints_, object, agree, min_keypoints_, min_model_edge_);
    if (copies.size() < 2 ||
        std::any_of (copies.begin(), copies.end(), [&] (const FreeObject& copy) {
          return boxHoldsObserved (
              copy.extent, *keypoints_, seeds.observed, kBoxMargin);
        }))
      continue;
    addCopies (copies);
  }
  return true;
}

} // namespace mid
