#include <mid/registration/model_merging.h>
#include <mid/registration/object_model.h>
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

/** Fewest pairs of copies that one relative pose of two models must make coincide before it
  * replaces the transform of their boxes: one pair's own pose always makes that pair coincide.
  */
constexpr std::size_t kMinCoincidingPairs = 2;

/** How many of a's instances coincide with an instance of b (each of b's at most once) when b's
  * frame sits at `a_to_b` (x_b = a_to_b * x_a) in a's: within `max_angle` and `max_distance`
  * at a's landmark centroid `center_a`, among the pairs `nearby` flags (nearby[i][j]: a's
  * instance i and b's instance j lie close enough to be one copy).
  */
std::size_t
coincidingPairs (const ObjectModel& a,
                 const ObjectModel& b,
                 const Eigen::Matrix4f& a_to_b,
                 const Eigen::Vector3f& center_a,
                 const std::vector<std::vector<bool>>& nearby,
                 float max_angle,
                 float max_distance)
{
  std::vector<bool> taken (b.instances.size(), false);
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < a.instances.size(); ++i)
    for (std::size_t j = 0; j < b.instances.size(); ++j)
      if (nearby[i][j] && !taken[j] &&
          posesCoincide (a.instances[i].pose,
                         b.instances[j].pose * a_to_b,
                         center_a,
                         max_angle,
                         max_distance)) {
        taken[j] = true;
        ++pairs;
        break;
      }
  return pairs;
}

/** Where b's frame sits in a's (x_b = result * x_a) when both models see the same copies:
  * the boxes' transform `boxes_a_to_b` is right only up to a symmetry of the box, and two
  * models of different parts of one product (the two ends of a carton, say) whose instances
  * lie on the same copies are placed right by those copies' poses instead. The relative pose
  * of one pair of instances replaces the boxes' transform when it makes at least
  * kMinCoincidingPairs pairs of nearby instances (their landmark centroids less than `reach`
  * apart) coincide (coincidingPairs()) and more than the boxes' transform does.
  */
Eigen::Matrix4f
transformOfSharedCopies (const ObjectModel& a,
                         const ObjectModel& b,
                         const Eigen::Matrix4f& boxes_a_to_b,
                         float reach,
                         float max_angle,
                         float max_distance)
{
  const Eigen::Vector3f center_a = landmarkCentroid (a);
  const Eigen::Vector3f center_b = landmarkCentroid (b);
  const auto placed = [] (const Eigen::Matrix4f& pose, const Eigen::Vector3f& point) {
    return Eigen::Vector3f (pose.topLeftCorner<3, 3>() * point +
                            pose.topRightCorner<3, 1>());
  };
  std::vector<std::vector<bool>> nearby (a.instances.size(),
                                         std::vector<bool> (b.instances.size()));
  for (std::size_t i = 0; i < a.instances.size(); ++i)
    for (std::size_t j = 0; j < b.instances.size(); ++j)
      nearby[i][j] = (placed (a.instances[i].pose, center_a) -
                      placed (b.instances[j].pose, center_b))
                         .norm() < reach;
  const auto pairs = [&] (const Eigen::Matrix4f& a_to_b) {
    return coincidingPairs (a, b, a_to_b, center_a, nearby, max_angle, max_distance);
  };
  Eigen::Matrix4f best = boxes_a_to_b;
  std::size_t most = std::max (pairs (boxes_a_to_b), kMinCoincidingPairs - 1);
  for (const auto& first : a.instances)
    for (const auto& second : b.instances) {
      // second.pose * a_to_b = first.pose puts the pair at one pose.
      const Eigen::Matrix4f a_to_b = second.pose.inverse() * first.pose;
      if (!a_to_b.allFinite())
        continue;
      const std::size_t count = pairs (a_to_b);
      if (count > most) {
        most = count;
        best = a_to_b;
      }
    }
  return best;
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
      // One box frame in both models: x_b = box_in_b * box_in_a^-1 * x_a, unless the two
      // see the same copies.
      mergeModel (models[a],
                  models[b],
                  transformOfSharedCopies (models[a],
                                           models[b],
                                           box_in_b * box_in_a.inverse(),
                                           size.maxCoeff(),
                                           duplicate_angle_,
                                           duplicate_distance_),
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
