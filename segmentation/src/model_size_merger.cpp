#include <mid/registration/model_merging.h>
#include <mid/segmentation/model_size.h>
#include <mid/segmentation/model_size_merger.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace mid {

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
  ModelSizes sizes;
  if (!measureSizes (models, plane, sizes))
    return false;

  for (std::size_t a = 0; a < models.size(); ++a) {
    for (std::size_t b = a + 1; b < models.size() && sizes[a].valid;) {
      if (!sizes[b].valid || !agree (sizes[a].size, sizes[b].size)) {
        ++b;
        continue;
      }
      if (models[b].instances.size() > models[a].instances.size()) {
        std::swap (models[a], models[b]);
        std::swap (sizes[a], sizes[b]);
      }
      // One box frame in both models: x_b = box_in_b * box_in_a^-1 * x_a.
      const Eigen::Matrix4f into_to_from =
          sizes[b].box_in_model * sizes[a].box_in_model.inverse();
      mergeModel (models[a],
                  models[b],
                  into_to_from,
                  {},
                  duplicate_angle_,
                  duplicate_distance_);
      models.erase (models.begin() + static_cast<std::ptrdiff_t> (b));
      sizes.erase (sizes.begin() + static_cast<std::ptrdiff_t> (b));
    }
  }
  return true;
}

} // namespace mid
