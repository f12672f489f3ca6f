#include <mid/registration/model_merging.h>
#include <mid/segmentation/model_size.h>
#include <mid/segmentation/model_size_merger.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace mid {

namespace {

/** The boxes of one size in models a and b (box frame -> model frame) and that size: a's size
  * and a box of it in b, or else b's size and a box of it in a, or else, if `pair_agrees` (two
  * measured copies are enough for a size), the boxes of a copy of each that have one size (the
  * first of a's copies that has a size of b's copies), and that copy's size; false if none.
  */
bool
boxesOfOneSize (const ObjectModel& a,
                const ObjectModel& b,
                const ModelSize& size_a,
                const ModelSize& size_b,
                const InstanceExtents& extents_a,
                const InstanceExtents& extents_b,
                const SizeAgreement& agree,
                bool pair_agrees,
                Eigen::Matrix4f& box_in_a,
                Eigen::Matrix4f& box_in_b,
                Eigen::Vector3f& size)
{
  if (size_a.valid && boxOfSize (size_a.size, size_b, b, extents_b, agree, box_in_b)) {
    box_in_a = size_a.box_in_model;
    size = size_a.size;
    return true;
  }
  if (size_b.valid && boxOfSize (size_b.size, size_a, a, extents_a, agree, box_in_a)) {
    box_in_b = size_b.box_in_model;
    size = size_b.size;
    return true;
  }
  if (!pair_agrees)
    return false;
  for (const std::size_t i : measuredInstances (extents_a))
    if (boxOfSize (extents_a[i].size, ModelSize(), b, extents_b, agree, box_in_b)) {
      box_in_a = a.instances[i].pose.inverse() * extents_a[i].pose;
      size = extents_a[i].size;
      return true;
    }
  return false;
}

} // namespace

bool
ModelSizeMerger::merge (ObjectModels& models) const
{
  const std::string problem = measurementProblem (models);
  if (!problem.empty()) {
    PCL_ERROR ("[mid::ModelSizeMerger::merge] %s.\n", problem.c_str());
    return false;
  }
  if (models.size() < 2)
    return true;
  Eigen::Vector4f plane;
  if (!fitPlane (plane))
    return true;
  const SizeAgreement agree = agreement();
  std::vector<InstanceExtents> extents;
  if (!measureBoxes (models, plane, extents))
    return false;
  ModelSizes sizes;
  modelSizesOfBoxes (models, extents, agree, min_agreeing_, sizes);

  for (std::size_t a = 0; a < models.size(); ++a) {
    for (std::size_t b = a + 1; b < models.size();) {
      Eigen::Matrix4f box_in_a, box_in_b;
      Eigen::Vector3f size;
      if (!boxesOfOneSize (models[a],
                           models[b],
                           sizes[a],
                           sizes[b],
                           extents[a],
                           extents[b],
                           agree,
                           min_agreeing_ <= 2,
                           box_in_a,
                           box_in_b,
                           size)) {
        ++b;
        continue;
      }
      if (models[b].instances.size() > models[a].instances.size()) {
        std::swap (models[a], models[b]);
        std::swap (sizes[a], sizes[b]);
        std::swap (box_in_a, box_in_b);
      }
      if (!sizes[a].valid) { // the size the two agree on, in a's frame
        sizes[a].valid = true;
        sizes[a].size = size;
        sizes[a].box_in_model = box_in_a;
      }
      // One box frame in both models: x_b = box_in_b * box_in_a^-1 * x_a.
      mergeModel (models[a],
                  models[b],
                  box_in_b * box_in_a.inverse(),
                  {},
                  duplicate_angle_,
                  duplicate_distance_);
      models.erase (models.begin() + static_cast<std::ptrdiff_t> (b));
      sizes.erase (sizes.begin() + static_cast<std::ptrdiff_t> (b));
      // The merged model's boxes are no longer its instances' (mergeModel() renumbers them):
      // it merges on by its size alone.
      extents[a].clear();
      extents.erase (extents.begin() + static_cast<std::ptrdiff_t> (b));
    }
  }
  return true;
}

} // namespace mid
