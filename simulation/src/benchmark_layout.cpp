#include "benchmark_layout.h"

#include <algorithm>
#include <cmath>

namespace mid {
namespace simulation {

namespace {

constexpr double kPi = 3.14159265358979323846;

/** Distance between objects put in contact, and the smallest gap a contact spot must keep to
  * every object (metres): under the 1 mm a depth sensor resolves, yet no interpenetration.
  */
constexpr double kContactGap = 0.0005;
constexpr double kContactCheckGap = 0.0002;
/** Share of the reach along the shared side within which a contact spot slides. */
constexpr double kContactSlide = 0.8;
/** Largest turn away from the camera of an object with a front. */
constexpr double kFrontSpread = kPi / 6.0;
/** Smallest gap between two rows, metres. */
constexpr double kRowSeparation = 0.03;
constexpr int kMaxAttempts = 300;
constexpr int kMaxContactAttempts = 100;
constexpr int kMaxRestarts = 100;

/** Position of the camera in the table frame. */
Eigen::Vector2d
cameraOnTable (const PlacementView& view)
{
  return view.table_to_camera.inverse().translation().head<2>();
}

/** Heading of an item at a position: its front towards the camera, or any. */
double
drawYaw (const LayoutItem& item,
         const Eigen::Vector2d& center,
         const PlacementView& view,
         DeterministicRandom& random)
{
  if (!item.has_front)
    return random.uniform (0.0, 2.0 * kPi);
  const Eigen::Vector2d towards = cameraOnTable (view) - center;
  return std::atan2 (towards.y(), towards.x()) - item.front_angle +
         random.uniform (-kFrontSpread, kFrontSpread);
}

Eigen::Vector2d
rotate (double yaw, const Eigen::Vector2d& vector)
{
  return Eigen::Rotation2Dd (yaw) * vector;
}

/** A spot against a random placed object: turned by a multiple of 90 deg from it, beside one
  * of its sides, slid along that side.
  */
Footprint
drawContactSpot (const LayoutItem& item,
                 const std::vector<Footprint>& placed,
                 DeterministicRandom& random)
{
  const Footprint& anchor = placed[static_cast<std::size_t> (
      random.uniformInt (static_cast<int> (placed.size())))];
  const int turn = random.uniformInt (4);
  const int axis = random.uniformInt (2);
  const double sign = random.uniformInt (2) == 0 ? -1.0 : 1.0;
  const Eigen::Vector2d half =
      turn % 2 == 0 ? item.shape.half
                    : Eigen::Vector2d (item.shape.half.y(), item.shape.half.x());
  const int other = 1 - axis;
  Eigen::Vector2d offset;
  offset[axis] = sign * (anchor.half[axis] + half[axis] + kContactGap);
  offset[other] = random.uniform (-kContactSlide, kContactSlide) *
                  (anchor.half[other] + half[other]);
  Footprint spot = item.shape;
  spot.yaw = anchor.yaw + 0.5 * kPi * turn;
  spot.center = anchor.center + rotate (anchor.yaw, offset);
  return spot;
}

bool
placeScattered (const LayoutItem& item,
                const PlacementView& view,
                const ScatterStyle& style,
                DeterministicRandom& random,
                std::vector<Footprint>& placed)
{
  if (!placed.empty() && random.uniform() < style.touch_probability)
    for (int attempt = 0; attempt < kMaxContactAttempts; ++attempt) {
      const Footprint spot = drawContactSpot (item, placed, random);
      if (footprintFree (spot, view, placed, kContactCheckGap)) {
        placed.push_back (spot);
        return true;
      }
    }
  for (int attempt = 0; attempt < kMaxAttempts; ++attempt) {
    Footprint spot = item.shape;
    spot.center = Eigen::Vector2d (random.uniform (view.min_x, view.max_x),
                                   random.uniform (view.min_y, view.max_y));
    spot.yaw = drawYaw (item, spot.center, view, random);
    if (footprintFree (spot, view, placed, style.gap)) {
      placed.push_back (spot);
      return true;
    }
  }
  return false;
}

/** The footprints of a row centred at center, or false if one is not free. */
bool
placeRow (const RowSpec& row,
          int axis,
          const Eigen::Vector2d& center,
          double yaw,
          const PlacementView& view,
          const std::vector<Footprint>& placed,
          std::vector<Footprint>& footprints)
{
  footprints.clear();
  const double step = 2.0 * row.item.shape.half[axis] + row.gap;
  const Eigen::Vector2d direction = rotate (yaw, Eigen::Vector2d::Unit (axis));
  for (int i = 0; i < row.count; ++i) {
    Footprint footprint = row.item.shape;
    footprint.yaw = yaw;
    footprint.center = center + (i - 0.5 * (row.count - 1)) * step * direction;
    if (!footprintFree (footprint, view, placed, kRowSeparation))
      return false;
    footprints.push_back (footprint);
  }
  return true;
}

} // namespace

bool
layoutScattered (const std::vector<LayoutItem>& items,
                 const PlacementView& view,
                 const ScatterStyle& style,
                 DeterministicRandom& random,
                 std::vector<Footprint>& layout)
{
  std::vector<std::size_t> order (items.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  std::stable_sort (
      order.begin(), order.end(), [&items] (std::size_t a, std::size_t b) {
        return items[a].shape.half.prod() > items[b].shape.half.prod();
      });
  for (int restart = 0; restart < kMaxRestarts; ++restart) {
    std::vector<Footprint> placed;
    layout.assign (items.size(), Footprint());
    bool complete = true;
    for (const std::size_t index : order) {
      if (!placeScattered (items[index], view, style, random, placed)) {
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

bool
layoutRows (const std::vector<RowSpec>& rows,
            const PlacementView& view,
            DeterministicRandom& random,
            std::vector<Footprint>& layout)
{
  for (int restart = 0; restart < kMaxRestarts; ++restart) {
    layout.clear();
    bool complete = true;
    for (const RowSpec& row : rows) {
      // Side by side, not one behind the other: perpendicular to the front if there is one.
      const int axis = row.item.has_front
                           ? (std::abs (std::sin (row.item.front_angle)) < 0.5 ? 1 : 0)
                           : random.uniformInt (2);
      std::vector<Footprint> footprints;
      bool placed = false;
      for (int attempt = 0; attempt < kMaxAttempts && !placed; ++attempt) {
        const Eigen::Vector2d center (random.uniform (view.min_x, view.max_x),
                                      random.uniform (view.min_y, view.max_y));
        const double yaw = drawYaw (row.item, center, view, random);
        placed = placeRow (row, axis, center, yaw, view, layout, footprints);
      }
      if (!placed) {
        complete = false;
        break;
      }
      layout.insert (layout.end(), footprints.begin(), footprints.end());
    }
    if (complete)
      return true;
  }
  return false;
}

} // namespace simulation
} // namespace mid
