#pragma once

// The discovery pipeline's timed stages, in the order of DiscoveryResult::timing_ms and of the
// result JSON's timing_ms.
#include <string>
#include <vector>

namespace mid {
namespace test {

/** \brief The stages from "features" to "box_sizes", in order ("total" follows them). */
inline const std::vector<std::string>&
pipelineStages ()
{
  static const std::vector<std::string> stages = {
      "features",         "matching",          "triplets",        "clustering",
      "verification",     "modeling",          "detection",       "leftovers",
      "patches",          "box_search",        "surface",         "size_split",
      "size_merge",       "box_pruning",       "repeated_prints", "size_search",
      "interpenetration", "size_disagreement", "box_turns",       "support_prints",
      "observations",     "box_sizes"};
  return stages;
}

} // namespace test
} // namespace mid
