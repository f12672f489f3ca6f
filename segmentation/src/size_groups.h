#pragma once

#include "free_objects.h"

#include <mid/segmentation/model_size.h>
#include <mid/segmentation/surface_gap.h>

#include <cstddef>
#include <vector>

namespace mid {
namespace detail {

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
