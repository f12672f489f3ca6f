#include <mid/segmentation/order_statistics.h>
#include <mid/segmentation/round_side.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace mid {

namespace {

/** How much narrower than its height (metres) the extent must be to be looked at. */
constexpr float kNarrowerBy = 0.005f;
/** Points within this much (metres) of the top make the ridge. */
constexpr float kRidgeBand = 0.002f;
/** Largest median distance (metres) of the points from the circle. */
constexpr float kCircleTolerance = 0.0025f;
/** Radii tried: from this share of half the height up to half of it. */
constexpr float kSmallestRadius = 0.8f;
/** Centres tried: up to this far (metres) from the middle of the ridge. */
constexpr float kCentreRange = 0.008f;
/** Step (metres) between the centres and radii tried. */
constexpr float kStep = 0.0005f;
/** Most points the circles are scored on (every how many is taken to stay under it). */
constexpr std::size_t kMaxSectionPoints = 400;
/** Share of the radius the points must reach on one side of the ridge. */
constexpr float kMinReach = 0.8f;
/** How far beyond the radius (metres) the points may reach on either side. */
constexpr float kMaxOverreach = 2.0f * kCircleTolerance;

} // namespace

bool
widenToRoundSide (const std::vector<float>& across,
                  const std::vector<float>& heights,
                  float height,
                  float& low,
                  float& high)
{
  const auto finite = [] (float value) { return std::isfinite (value); };
  if (across.size() != heights.size() ||
      !std::all_of (across.begin(), across.end(), finite) ||
      !std::all_of (heights.begin(), heights.end(), finite) ||
      !std::isfinite (height) || !std::isfinite (low) || !std::isfinite (high) ||
      low > high) {
    PCL_ERROR (
        "[mid::widenToRoundSide] The positions and heights must be finite and as many, "
        "and the extent [low, high] finite and ordered.\n");
    return false;
  }
  const float half_height = 0.5f * height;
  if (across.empty() || high - low >= height - kNarrowerBy || half_height <= 0.0f)
    return false;
  std::vector<float> ridge;
  for (std::size_t i = 0; i < across.size(); ++i)
    if (heights[i] >= height - kRidgeBand)
      ridge.push_back (across[i]);
  if (ridge.empty())
    return false;
  const float ridge_middle = median (ridge);
  const float reach_of_ridge = std::max (ridge_middle - low, high - ridge_middle);
  if (reach_of_ridge + kCentreRange < kMinReach * kSmallestRadius * half_height)
    return false;

  // The circle (centre near the ridge's middle, radius below half the height) that the points
  // lie on most closely, on at most kMaxSectionPoints of them.
  const std::size_t stride =
      (across.size() + kMaxSectionPoints - 1) / kMaxSectionPoints;
  std::vector<float> distances;
  distances.reserve (across.size() / stride + 1);
  float centre = ridge_middle, radius = half_height;
  float residual = std::numeric_limits<float>::infinity();
  for (float c = ridge_middle - kCentreRange;
       c <= ridge_middle + kCentreRange + 0.5f * kStep;
       c += kStep)
    for (float r = kSmallestRadius * half_height; r <= half_height + 0.5f * kStep;
         r += kStep) {
      distances.clear();
      for (std::size_t i = 0; i < across.size(); i += stride)
        distances.push_back (std::abs (std::hypot (across[i] - c, heights[i] - r) - r));
      if (const float distance = median (distances); distance < residual) {
        residual = distance;
        centre = c;
        radius = r;
      }
    }
  const float reach = std::max (centre - low, high - centre);
  if (residual > kCircleTolerance || reach < kMinReach * radius ||
      reach > radius + kMaxOverreach)
    return false;
  low = centre - radius;
  high = centre + radius;
  return true;
}

} // namespace mid
