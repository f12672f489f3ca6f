#include "size_groups.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace mid {
namespace detail {

namespace {

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

} // namespace

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

} // namespace detail
} // namespace mid
