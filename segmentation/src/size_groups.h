#pragma once

#include "free_objects.h"

#include <mid/segmentation/model_size.h>
#include <mid/segmentation/surface_gap.h>

#include <cstddef>
#include <vector>

namespace mid {
namespace detail {

/** \brief Smallest share of two objects' colours that must overlap (colourOverlap()) for two
  * objects that no other agrees with to be copies when their sizes agree only loosely
  * (groupsOfOneSize()), or when one is partly hidden (SizeInstanceSearch's pairing of hidden
  * copies, completeHiddenCopy()): copies that show
  * different faces still share much of their print's colours. The three loose pairs of copies
  * on the benchmark overlap by 0.53, 0.92 and 0.94, a soy-milk and a juice carton by 0.16, a
  * black and a white mug of a real table by 0.21. The groups of one size overlap by 0.24 to 1
  * (0.71 in the median group, a tenth below 0.38): too little for a check of every group,
  * enough for the pairs the size alone does not make.
  */
constexpr float kMinLoosePairColourOverlap = 0.5f;

/** \brief The share of their pixels two objects' colours have in common: the intersection of
  * their histograms over 6 x 6 chromaticity bins and one of the pixels too dark to tell. 0
  * without chromaticities (`surface.chromaticity` null).
  */
float
colourOverlap (const KeypointSurface& surface,
               const FreeObject& a,
               const FreeObject& b);

/** \brief Group the `candidates` of `objects` by their size, the objects that may found a
  * model of copies (SizeInstanceSearch): the objects whose sizes agree with the first of the
  * group (most keypoints first); then two objects no other agrees with, whose sizes agree at
  * a looser tolerance (copies measured a little off) and whose colours overlap (copies share
  * their print's colours; needs `surface.chromaticity`), are a group; an object left is a
  * group of its own. Larger groups come first.
  * \return each group's indices into `objects`
  */
std::vector<std::vector<std::size_t>>
groupsOfOneSize (const FreeObjects& objects,
                 const std::vector<std::size_t>& candidates,
                 const SizeAgreement& agree,
                 const KeypointSurface& surface);

} // namespace detail
} // namespace mid
