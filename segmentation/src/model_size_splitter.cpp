#include <mid/segmentation/model_size_splitter.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <iterator>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace mid {

namespace {

/** The two groups of instances of one model that split it, as indices into the model's
  * instances: `first` grew from the largest group of one size, `second` from the largest
  * among the rest (it has no more instances than `first`, whatever the sizes of the boxes).
  */
struct SizeGroups
{
  std::vector<std::size_t> first, second;
};

/** The number of the landmarks `instance` observes that some instance of `group` observes. */
std::size_t
sharedLandmarks (const ObjectModel& model,
                 const std::vector<std::size_t>& group,
                 const ModelInstance& instance)
{
  std::set<int> seen;
  for (const auto i : group)
    seen.insert (model.instances[i].landmarks.begin(),
                 model.instances[i].landmarks.end());
  return static_cast<std::size_t> (std::count_if (
      instance.landmarks.begin(), instance.landmarks.end(), [&seen] (int l) {
        return seen.count (l) > 0;
      }));
}

/** The two size groups that split `model` (SizeAgreement::differOnEveryEdge(), at least
  * `min_agreeing` measured instances each), every other instance given to the group that
  * shares more of its landmarks; false if the boxes do not split it.
  */
bool
findSizeGroups (const ObjectModel& model,
                const InstanceExtents& extents,
                const SizeAgreement& agree,
                std::size_t min_agreeing,
                SizeGroups& groups)
{
  std::vector<std::size_t> measured = measuredInstances (extents);
  std::size_t first = 0, second = 0;
  groups.first = largestSizeGroup (extents, measured, agree, first);
  if (groups.first.size() < min_agreeing)
    return false;
  measured.erase (std::remove_if (measured.begin(),
                                  measured.end(),
                                  [&] (std::size_t i) {
                                    return std::count (groups.first.begin(),
                                                       groups.first.end(),
                                                       i) > 0;
                                  }),
                  measured.end());
  groups.second = largestSizeGroup (extents, measured, agree, second);
  if (groups.second.size() < min_agreeing ||
      !agree.differOnEveryEdge (extents[first].size, extents[second].size))
    return false;

  std::vector<std::size_t> others;
  for (std::size_t i = 0; i < model.instances.size(); ++i)
    if (std::count (groups.first.begin(), groups.first.end(), i) == 0 &&
        std::count (groups.second.begin(), groups.second.end(), i) == 0)
      others.push_back (i);
  const SizeGroups measured_groups = groups;
  for (const auto i : others) {
    const auto& instance = model.instances[i];
    auto& group = sharedLandmarks (model, measured_groups.second, instance) >
                          sharedLandmarks (model, measured_groups.first, instance)
                      ? groups.second
                      : groups.first;
    group.push_back (i);
  }
  for (auto* group : {&groups.first, &groups.second})
    std::sort (group->begin(), group->end());
  return true;
}

} // namespace

bool
ModelSizeSplitter::split (ObjectModels& models, std::size_t& added) const
{
  added = 0;
  std::string problem = measurementProblem (models);
  if (problem.empty() && min_agreeing_ < 2)
    problem = "each size needs at least two instances that agree on it (min agreeing " +
              std::to_string (min_agreeing_) + ")";
  if (!problem.empty()) {
    PCL_ERROR ("[mid::ModelSizeSplitter::split] %s.\n", problem.c_str());
    return false;
  }
  const auto min_agreeing = static_cast<std::size_t> (min_agreeing_);
  if (std::none_of (models.begin(), models.end(), [&] (const ObjectModel& model) {
        return model.instances.size() >= 2 * min_agreeing;
      }))
    return true;
  Eigen::Vector4f plane;
  if (!fitPlane (plane))
    return true;
  std::vector<InstanceExtents> extents;
  if (!measureBoxes (models, plane, extents))
    return false;

  const SizeAgreement agree = agreement();
  ObjectModels kept, appended;
  for (std::size_t m = 0; m < models.size(); ++m) {
    // A stack of parts to look at, each with the boxes of its instances; the first group's
    // part is pushed last, so that it comes out first and takes the model's place.
    std::vector<std::pair<ObjectModel, InstanceExtents>> pending;
    pending.emplace_back (models[m], extents[m]);
    ObjectModels parts;
    while (!pending.empty()) {
      auto [model, boxes] = std::move (pending.back());
      pending.pop_back();
      SizeGroups groups;
      if (!findSizeGroups (model, boxes, agree, min_agreeing, groups)) {
        parts.push_back (std::move (model));
        continue;
      }
      for (const auto* group : {&groups.second, &groups.first}) {
        ObjectModel part;
        extractModelPart (model, *group, part);
        InstanceExtents part_boxes;
        for (const auto i : *group)
          part_boxes.push_back (boxes[i]);
        pending.emplace_back (std::move (part), std::move (part_boxes));
      }
    }
    added += parts.size() - 1;
    kept.push_back (std::move (parts.front()));
    std::move (parts.begin() + 1, parts.end(), std::back_inserter (appended));
  }
  std::move (appended.begin(), appended.end(), std::back_inserter (kept));
  models = std::move (kept);
  return true;
}

} // namespace mid
