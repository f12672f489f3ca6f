#include "copy_cutter.h"

#include "hidden_copy.h"

#include <mid/segmentation/flat_top_parts.h>
#include <mid/segmentation/footprint_copy_sizes.h>
#include <mid/segmentation/footprint_split.h>
#include <mid/segmentation/instance_extent.h>
#include <mid/segmentation/occluded_outline.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace mid {
namespace detail {

namespace {

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

/** The object's height above the plane: its box's edge along upAxis(). */
float
heightOf (const InstanceExtent& extent, const Eigen::Vector4f& plane)
{
  return extent.size[upAxis (extent, plane)];
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

} // namespace

FreeObjects
CopyCutter::flushCopies (const FreeObject& object, const Eigen::Vector3f& size) const
{
  FreeObjects parts;
  // The box's edge closest to the object's height stands up.
  const float object_height = heightOf (object.extent, plane_);
  int height = -1;
  for (int i = 0; i < 3; ++i)
    if (agree_.edgesAgree (object_height, size[i]) &&
        (height < 0 ||
         std::abs (size[i] - object_height) < std::abs (size[height] - object_height)))
      height = i;
  if (height < 0)
    return parts;
  const Eigen::Vector2f rectangle (size[(height + 1) % 3], size[(height + 2) % 3]);

  const PlaneCoordinates on_plane (plane_);
  const Footprint footprint = footprintOf (organized_, on_plane, object);
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
            on_plane (keypoints_[static_cast<std::size_t> (k)].getVector3fMap()));
        c >= 0)
      cut[static_cast<std::size_t> (c)].keypoints.push_back (k);
  for (auto& part : cut)
    if (fitInstanceBox (organized_, plane_, part.pixels, part.extent))
      parts.push_back (part);
  return parts;
}

FreeObjects
CopyCutter::copiesOfItsOutline (const FreeObject& object) const
{
  const float edge = std::max (min_edge_, kMinOutlineEdge);
  std::vector<Eigen::Vector2f, Eigen::aligned_allocator<Eigen::Vector2f>> rectangles;
  if (!footprintCopySizes (footprintOf (organized_, PlaneCoordinates (plane_), object),
                           std::min (kFootprintCell, 0.1f * edge),
                           edge,
                           kMaxCopiesFill,
                           rectangles))
    return {};
  float occluded = 0.0f;
  if (!occludedOutlineShare (
          organized_, object.pixels, kRingPixels, kOccluderStep, occluded) ||
      occluded > kMaxOccludedShare)
    return {};
  const SizeAgreement loose = agree_.scaled (2.0f);
  for (const auto& rectangle : rectangles) {
    Eigen::Vector3f box (
        heightOf (object.extent, plane_), rectangle.x(), rectangle.y());
    std::sort (box.data(), box.data() + 3);
    FreeObjects parts = flushCopies (object, box);
    const bool copies =
        parts.size() >= 2 &&
        std::all_of (parts.begin(), parts.end(), [&] (const FreeObject& part) {
          return part.keypoints.size() >= static_cast<std::size_t> (min_keypoints_) &&
                 part.extent.size.minCoeff() >= edge &&
                 agree_ (part.extent.size, parts.front().extent.size) &&
                 loose (part.extent.size, box);
        });
    if (copies &&
        rectanglesFill (footprintRectangles (parts, plane_)) <= kMaxCopiesFill)
      return parts;
  }
  return {};
}

FreeObjects
CopyCutter::flatTopCopies (const FreeObject& object, const Eigen::Vector3f& size) const
{
  std::vector<pcl::Indices> parts;
  if (!flatTopParts (organized_, plane_, object.pixels, size, parts))
    return {};
  FreeObjects copies;
  std::vector<std::uint8_t> in_part (organized_.size(), 0);
  for (const pcl::Indices& pixels : parts) {
    FreeObject copy;
    copy.pixels = pixels;
    for (const auto p : pixels)
      in_part[static_cast<std::size_t> (p)] = 1;
    for (const auto k : object.keypoints)
      if (in_part[static_cast<std::size_t> (
              keypoint_pixels_[static_cast<std::size_t> (k)])] != 0)
        copy.keypoints.push_back (k);
    for (const auto p : pixels)
      in_part[static_cast<std::size_t> (p)] = 0;
    if (copy.keypoints.size() >= static_cast<std::size_t> (min_keypoints_) &&
        copy.keypoints.size() < object.keypoints.size() &&
        fitInstanceBox (organized_, plane_, copy.pixels, copy.extent))
      copies.push_back (copy);
  }
  return copies;
}

FreeObjects
CopyCutter::copyByItsFlatTop (const FreeObject& object,
                              const Eigen::Vector3f& size) const
{
  for (const FreeObject& copy : flatTopCopies (object, size))
    if (agree_ (copy.extent.size, size))
      return {copy};
  return {};
}

FreeObjects
CopyCutter::copiesOfItsFlatTops (const FreeObject& object) const
{
  std::vector<Eigen::Vector3f> suggestions;
  if (!flatTopSizes (organized_, plane_, object.pixels, suggestions))
    return {};
  const SizeAgreement loose = agree_.scaled (2.0f);
  std::vector<int> holders (keypoint_pixels_.size(), 0);
  for (const Eigen::Vector3f& suggestion : suggestions) {
    if (suggestion.minCoeff() < min_edge_)
      continue;
    FreeObjects copies;
    for (FreeObject& part : flatTopCopies (object, suggestion)) {
      if (part.extent.size.minCoeff() < min_edge_ ||
          !loose (part.extent.size, suggestion) ||
          (!copies.empty() && !agree_ (part.extent.size, copies.front().extent.size)) ||
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
      if (own[c].size() >= static_cast<std::size_t> (min_keypoints_))
        kept.push_back (std::move (copies[c]));
    }
    if (kept.size() >= 2)
      return kept;
  }
  return {};
}

FreeObjects
CopyCutter::hiddenCopy (const FreeObject& object, const Eigen::Vector3f& size) const
{
  InstanceExtent completed;
  if (!completeHiddenCopy (organized_, plane_, size, object, agree_, completed))
    return {};
  FreeObject copy = object;
  copy.extent = completed;
  return {copy};
}

bool
CopyCutter::endsOfOneBox (const FreeObject& a, const FreeObject& b) const
{
  return endsOfOneHiddenBox (organized_, plane_, a, b, agree_);
}

} // namespace detail
} // namespace mid
