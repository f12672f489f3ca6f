#include "free_objects.h"

#include <mid/segmentation/size_disagreement_filter.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace mid {

namespace {

/** True if `boxes` (one per instance) agree on no size, and two of them
  * differ on every edge.
  */
bool
agreeOnNoSize (const InstanceExtents& boxes, const SizeAgreement& agree)
{
  bool apart = false;
  for (std::size_t a = 0; a < boxes.size(); ++a)
    for (std::size_t b = a + 1; b < boxes.size(); ++b) {
      if (agree (boxes[a].size, boxes[b].size))
        return false;
      apart = apart || agree.differOnEveryEdge (boxes[a].size, boxes[b].size);
    }
  return apart;
}

} // namespace

std::string
SizeDisagreementFilter::inputProblem (const ObjectModels& models) const
{
  std::string problem = measurementProblem (models);
  if (problem.empty() &&
      !(max_surrounded_share_ >= 0.0f && max_surrounded_share_ <= 1.0f))
    problem = "the largest surrounded share must be in [0, 1] (got " +
              std::to_string (max_surrounded_share_) + ")";
  if (problem.empty() && min_copies_ < 2)
    problem = "a model needs two copies at least to be judged (got " +
              std::to_string (min_copies_) + ")";
  return problem;
}

bool
SizeDisagreementFilter::filter (ObjectModels& models, std::size_t& removed) const
{
  removed = 0;
  if (const std::string why = inputProblem (models); !why.empty()) {
    PCL_ERROR ("[mid::SizeDisagreementFilter::filter] %s.\n", why.c_str());
    return false;
  }
  const bool any_judged =
      std::any_of (models.begin(), models.end(), [this] (const ObjectModel& model) {
        return static_cast<int> (model.instances.size()) >= min_copies_;
      });
  Eigen::Vector4f plane;
  if (!any_judged || !fitPlane (plane))
    return true;
  std::vector<InstanceExtents> extents;
  if (!measureBoxes (models, plane, extents))
    return false;
  const SizeAgreement agree = agreement();
  // A box fitted to no surface (an instance without observations) stands nowhere.
  const auto standsAlone = [&] (const InstanceExtent& box) {
    return !box.surface.empty() &&
           detail::surroundedShare (
               *surface_.organized, plane, box, 2.0f * plane_tolerance_) <=
               max_surrounded_share_;
  };
  ObjectModels kept;
  for (std::size_t m = 0; m < models.size(); ++m) {
    const InstanceExtents& boxes = extents[m];
    const bool judged = static_cast<int> (models[m].instances.size()) >= min_copies_ &&
                        std::all_of (boxes.begin(), boxes.end(), standsAlone);
    if (judged && agreeOnNoSize (boxes, agree))
      ++removed;
    else
      kept.push_back (std::move (models[m]));
  }
  models.swap (kept);
  return true;
}

} // namespace mid
