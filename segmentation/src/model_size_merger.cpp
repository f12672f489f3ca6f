#include <mid/registration/model_merging.h>
#include <mid/segmentation/consensus_boxes.h>
#include <mid/segmentation/model_size.h>
#include <mid/segmentation/model_size_merger.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace mid {

namespace {

/** A model's boxes: one per instance, measured on its own surface, and one per instance
  * measured on what it shares with the model's other copies (consensusBoxes(); empty when
  * the merger uses none).
  */
struct ModelBoxes
{
  InstanceExtents measured;
  InstanceExtents consensus;
};

/** The boxes of one size in models a and b (box frame -> model frame) and that size: a's size
  * and a box of it in b, or else b's size and a box of it in a, or else, if `pair_agrees` (two
  * measured copies are enough for a size), the boxes of a copy of each that have one size (the
  * first of a's copies that has a size of b's copies), and that copy's size, or else a's size
  * and a consensus box of it in b, or b's size and one in a; false if none.
  */
bool
boxesOfOneSize (const ObjectModel& a,
                const ObjectModel& b,
                const ModelSize& size_a,
                const ModelSize& size_b,
                const ModelBoxes& boxes_a,
                const ModelBoxes& boxes_b,
                const SizeAgreement& agree,
                bool pair_agrees,
                Eigen::Matrix4f& box_in_a,
                Eigen::Matrix4f& box_in_b,
                Eigen::Vector3f& size)
{
  const InstanceExtents& extents_a = boxes_a.measured;
  const InstanceExtents& extents_b = boxes_b.measured;
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
  if (pair_agrees)
    for (const std::size_t i : measuredInstances (extents_a))
      if (boxOfSize (extents_a[i].size, ModelSize(), b, extents_b, agree, box_in_b)) {
        box_in_a = a.instances[i].pose.inverse() * extents_a[i].pose;
        size = extents_a[i].size;
        return true;
      }
  if (size_a.valid &&
      boxOfSize (size_a.size, ModelSize(), b, boxes_b.consensus, agree, box_in_b)) {
    box_in_a = size_a.box_in_model;
    size = size_a.size;
    return true;
  }
  if (size_b.valid &&
      boxOfSize (size_b.size, ModelSize(), a, boxes_a.consensus, agree, box_in_a)) {
    box_in_b = size_b.box_in_model;
    size = size_b.size;
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
  if (!(consensus_radius_ >= 0.0f) || !std::isfinite (consensus_radius_)) {
    PCL_ERROR ("[mid::ModelSizeMerger::merge] the consensus radius must be finite and "
               ">= 0.\n");
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
  std::vector<ModelBoxes> boxes (models.size());
  for (std::size_t m = 0; m < models.size(); ++m) {
    boxes[m].measured = std::move (extents[m]);
    if (consensus_radius_ > 0.0f && !consensusBoxes (*surface_.organized,
                                                     plane,
                                                     models[m],
                                                     boxes[m].measured,
                                                     consensus_radius_,
                                                     boxes[m].consensus))
      return false;
  }

  for (std::size_t a = 0; a < models.size(); ++a) {
    for (std::size_t b = a + 1; b < models.size();) {
      Eigen::Matrix4f box_in_a, box_in_b;
      Eigen::Vector3f size;
      if (!boxesOfOneSize (models[a],
                           models[b],
                           sizes[a],
                           sizes[b],
                           boxes[a],
                           boxes[b],
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
      // it merges on by its size alone. (So the boxes need no swap above.)
      boxes[a] = ModelBoxes();
      boxes.erase (boxes.begin() + static_cast<std::ptrdiff_t> (b));
    }
  }
  return true;
}

} // namespace mid
