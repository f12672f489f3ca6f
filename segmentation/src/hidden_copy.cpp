#include "hidden_copy.h"

#include "image_line.h"

#include <mid/segmentation/occluded_outline.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

namespace mid {
namespace detail {

namespace {

/** Smallest share of the whole copy's edge that the hidden one must show. */
constexpr float kMinVisibleShare = 0.6f;
/** How far from the end face of a box its outline pixels lie that tell whether the end is
  * hidden (metres).
  */
constexpr float kEndBand = 0.01f;
/** Smallest share of an end's outline pixels that something in front must hide. */
constexpr float kMinHiddenEnd = 0.5f;
/** How far from an outline pixel a point in front must lie to hide it (pixels): a surface
  * grown beside a nearer occluder stops up to 6 pixels short of it, where its pixels lie
  * behind the chord between their neighbours 6 pixels away (growInstanceSurfaces()).
  */
constexpr int kOccluderRing = 8;
/** Fewest outline pixels at an end for its share to count. */
constexpr std::size_t kMinEndPixels = 5;
/** Cosine of the largest angle between the axes of two ends of one box (10 deg). */
const float kMinAxisCosine = std::cos (static_cast<float> (10.0 * M_PI / 180.0));
/** Largest distance of one end's centre from the other's axis, as a share of the shorter of
  * their cross-section edges.
  */
constexpr float kMaxAxisOffset = 0.25f;
/** Shortest gap between two ends of one box that something in front hides in the middle
  * (metres): room for what hides it. Copies touching in a row have none.
  */
constexpr float kMinMiddleGap = 0.02f;
/** Smallest share of the image line between two ends of one box whose points lie in front of
  * the box: what hides its middle. The surface of each end stops a few pixels short of the
  * occluder (see kOccluderRing), and those pixels are the box's own.
  */
constexpr float kMinHiddenMiddle = 0.5f;

/** The edge of `whole` of which `hidden`'s edge `i` shows a part: their other two edges agree
  * (either way round), and edge i is shorter beyond the tolerance but kMinVisibleShare of it
  * at least. -1 if none.
  */
int
shortenedEdge (const Eigen::Vector3f& whole,
               const Eigen::Vector3f& hidden,
               int i,
               const SizeAgreement& agree)
{
  const auto othersAgree = [&] (int j) {
    const float a0 = whole[(j + 1) % 3], a1 = whole[(j + 2) % 3];
    const float b0 = hidden[(i + 1) % 3], b1 = hidden[(i + 2) % 3];
    return (agree.edgesAgree (a0, b0) && agree.edgesAgree (a1, b1)) ||
           (agree.edgesAgree (a0, b1) && agree.edgesAgree (a1, b0));
  };
  for (int j = 0; j < 3; ++j)
    if (hidden[i] < whole[j] && !agree.edgesAgree (hidden[i], whole[j]) &&
        hidden[i] >= kMinVisibleShare * whole[j] && othersAgree (j))
      return j;
  return -1;
}

/** The end of `box` along its axis `i` (+1 or -1) where something in front hides kMinHiddenEnd
  * of the outline's pixels at least (the larger share if both), 0 if neither. `hidden` is
  * sorted (occludedOutline() lists in the frame's order).
  */
int
hiddenEnd (const pcl::PointCloud<pcl::PointXYZ>& organized,
           const InstanceExtent& box,
           int i,
           const pcl::Indices& outline,
           const pcl::Indices& hidden)
{
  const Eigen::Vector3f axis = box.pose.col (i).head<3>();
  const Eigen::Vector3f centre = box.pose.col (3).head<3>();
  const float reach = 0.5f * box.size[i] - kEndBand;
  std::array<std::size_t, 2> at_end = {0, 0}, hidden_at_end = {0, 0};
  for (const auto p : outline) {
    const float along =
        axis.dot (organized[static_cast<std::size_t> (p)].getVector3fMap() - centre);
    if (std::abs (along) < reach)
      continue;
    const std::size_t end = along > 0.0f ? 1 : 0;
    ++at_end[end];
    if (std::binary_search (hidden.begin(), hidden.end(), p))
      ++hidden_at_end[end];
  }
  std::array<float, 2> share = {0.0f, 0.0f};
  for (std::size_t end = 0; end < 2; ++end)
    if (at_end[end] >= kMinEndPixels)
      share[end] =
          static_cast<float> (hidden_at_end[end]) / static_cast<float> (at_end[end]);
  if (std::max (share[0], share[1]) < kMinHiddenEnd)
    return 0;
  return share[1] >= share[0] ? 1 : -1;
}

/** The pixel of `pixels` whose point lies farthest along `direction` (camera frame): the tip
  * of the end that faces that way; -1 if none has a point.
  */
pcl::index_t
tipPixel (const pcl::PointCloud<pcl::PointXYZ>& organized,
          const pcl::Indices& pixels,
          const Eigen::Vector3f& direction)
{
  pcl::index_t tip = -1;
  float farthest = -std::numeric_limits<float>::infinity();
  for (const auto p : pixels) {
    const Eigen::Vector3f point =
        organized[static_cast<std::size_t> (p)].getVector3fMap();
    if (point.allFinite() && direction.dot (point) > farthest) {
      farthest = direction.dot (point);
      tip = p;
    }
  }
  return tip;
}

/** The share of the pixels on the image line between pixels p and q (both left out), of those
  * with a point, whose point lies nearer the camera by kOccluderStep at least than the straight
  * segment between p's and q's points (along its viewing ray, walkImageLine()) and outside
  * `box` grown by kOccluderStep (the box the two ends would make whole: a copy lying between
  * them in line is on it, not in front of it); 0 if none has a point.
  */
float
hiddenShareBetween (const pcl::PointCloud<pcl::PointXYZ>& organized,
                    pcl::index_t p,
                    pcl::index_t q,
                    const OrientedBox& box)
{
  std::size_t seen = 0, hidden = 0;
  walkImageLine (organized, p, q, [&] (pcl::index_t pixel, double behind) {
    ++seen;
    if (behind < -static_cast<double> (kOccluderStep) &&
        !box.holds (organized[static_cast<std::size_t> (pixel)].getVector3fMap(),
                    kOccluderStep))
      ++hidden;
    return true;
  });
  return seen == 0 ? 0.0f : static_cast<float> (hidden) / static_cast<float> (seen);
}

/** `box` with its edge `i` lengthened to `length` beyond its end `end` (+1 or -1), its edges
  * sorted ascending again with its frame's axes (kept right-handed).
  */
InstanceExtent
lengthened (const InstanceExtent& box, int i, float length, int end)
{
  InstanceExtent longer = box;
  longer.pose.col (3).head<3>() += 0.5f * (length - box.size[i]) *
                                   static_cast<float> (end) *
                                   box.pose.col (i).head<3>();
  Eigen::Vector3f size = box.size;
  size[i] = length;
  std::array<int, 3> order = {0, 1, 2};
  std::stable_sort (
      order.begin(), order.end(), [&size] (int a, int b) { return size[a] < size[b]; });
  for (int k = 0; k < 3; ++k) {
    longer.size[k] = size[order[static_cast<std::size_t> (k)]];
    longer.pose.col (k).head<3>() =
        box.pose.col (order[static_cast<std::size_t> (k)]).head<3>();
  }
  if (longer.pose.topLeftCorner<3, 3>().determinant() < 0.0f)
    longer.pose.col (2).head<3>() *= -1.0f;
  return longer;
}

} // namespace

bool
completeHiddenCopy (const pcl::PointCloud<pcl::PointXYZ>& organized,
                    const Eigen::Vector4f& plane,
                    const Eigen::Vector3f& whole,
                    const FreeObject& hidden,
                    const SizeAgreement& agree,
                    InstanceExtent& completed)
{
  const InstanceExtent& box = hidden.extent;
  if (!(whole.array() > 0.0f).all() || !(box.size.array() > 0.0f).all())
    return false;
  const int up = upAxis (box, plane);
  pcl::Indices outline, hidden_outline;
  bool outlined = false;
  for (int i = 0; i < 3; ++i) {
    const int j = i == up ? -1 : shortenedEdge (whole, box.size, i, agree);
    if (j < 0)
      continue;
    if (!outlined) {
      if (!occludedOutline (organized,
                            hidden.pixels,
                            kOccluderRing,
                            kOccluderStep,
                            outline,
                            hidden_outline))
        return false;
      outlined = true;
    }
    if (const int end = hiddenEnd (organized, box, i, outline, hidden_outline);
        end != 0) {
      completed = lengthened (box, i, whole[j], end);
      return true;
    }
  }
  return false;
}

bool
endsOfOneHiddenBox (const pcl::PointCloud<pcl::PointXYZ>& organized,
                    const Eigen::Vector4f& plane,
                    const FreeObject& a,
                    const FreeObject& b,
                    const SizeAgreement& agree)
{
  const InstanceExtent &box_a = a.extent, &box_b = b.extent;
  if (!(box_a.size.array() > 0.0f).all() || !(box_b.size.array() > 0.0f).all())
    return false;
  const int up_a = upAxis (box_a, plane), up_b = upAxis (box_b, plane);
  if (!agree.edgesAgree (box_a.size[up_a], box_b.size[up_b]))
    return false;
  const Eigen::Vector3f normal = plane.head<3>().normalized();
  Eigen::Vector3f between = box_b.pose.col (3).head<3>() - box_a.pose.col (3).head<3>();
  between -= normal.dot (between) * normal;
  const auto axis = [] (const InstanceExtent& box, int i) {
    return Eigen::Vector3f (box.pose.col (i).head<3>());
  };
  // Each box's footprint axis that points most at the other.
  const auto along = [&] (const InstanceExtent& box, int up) {
    int best = -1;
    for (int i = 0; i < 3; ++i)
      if (i != up && (best < 0 || std::abs (axis (box, i).dot (between)) >
                                      std::abs (axis (box, best).dot (between))))
        best = i;
    return best;
  };
  const int i = along (box_a, up_a), j = along (box_b, up_b);
  const int across_a = 3 - i - up_a, across_b = 3 - j - up_b;
  const float distance = axis (box_a, i).dot (between);
  const float gap = std::abs (distance) - 0.5f * (box_a.size[i] + box_b.size[j]);
  if (std::abs (axis (box_a, i).dot (axis (box_b, j))) < kMinAxisCosine ||
      !agree.edgesAgree (box_a.size[across_a], box_b.size[across_b]) ||
      (between - distance * axis (box_a, i)).norm() >
          kMaxAxisOffset * std::min (box_a.size[across_a], box_b.size[across_b]) ||
      gap < kMinMiddleGap)
    return false;
  // Something in front of the box they would make whole hides the middle: the image line
  // between the tips of the two ends.
  const float side = distance > 0.0f ? 1.0f : -1.0f;
  const float from = -0.5f * side * box_a.size[i];
  const float to = distance + 0.5f * side * box_b.size[j];
  Eigen::Vector3f half;
  half[i] = 0.5f * std::abs (to - from);
  half[across_a] = 0.5f * std::max (box_a.size[across_a], box_b.size[across_b]);
  half[up_a] = 0.5f * std::max (box_a.size[up_a], box_b.size[up_b]);
  Eigen::Matrix4f whole = box_a.pose;
  whole.col (3).head<3>() += 0.5f * (from + to) * axis (box_a, i);
  OrientedBox hull;
  hull.to_box = whole.inverse();
  hull.half = half.array();
  const pcl::index_t tip_a = tipPixel (organized, a.pixels, side * axis (box_a, i));
  const pcl::index_t tip_b = tipPixel (organized, b.pixels, -side * axis (box_a, i));
  return tip_a >= 0 && tip_b >= 0 &&
         hiddenShareBetween (organized, tip_a, tip_b, hull) >= kMinHiddenMiddle;
}

} // namespace detail
} // namespace mid
