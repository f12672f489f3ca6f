#include <mid/segmentation/instance_extent.h>
#include <mid/segmentation/model_size.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace mid {

bool
SizeAgreement::operator() (const Eigen::Vector3f& a, const Eigen::Vector3f& b) const
{
  for (int i = 0; i < 3; ++i)
    if (std::abs (a[i] - b[i]) >
        std::max (absolute_, relative_ * std::max (a[i], b[i])))
      return false;
  return true;
}

std::vector<pcl::Indices>
instanceSeedPixels (const ObjectModels& models, const pcl::Indices& keypoint_pixels)
{
  std::vector<pcl::Indices> seeds;
  for (const auto& model : models)
    for (const auto& instance : model.instances) {
      seeds.emplace_back();
      for (const auto k : instance.keypoints)
        seeds.back().push_back (keypoint_pixels[static_cast<std::size_t> (k)]);
    }
  return seeds;
}

bool
measureModelSizes (const pcl::PointCloud<pcl::PointXYZ>& organized,
                   const Eigen::Vector4f& plane,
                   const pcl::Indices& keypoint_pixels,
                   const ObjectModels& models,
                   float max_step,
                   float max_radius,
                   float plane_tolerance,
                   const SizeAgreement& agree,
                   int min_agreeing,
                   ModelSizes& sizes)
{
  sizes.clear();
  const std::vector<pcl::Indices> seeds = instanceSeedPixels (models, keypoint_pixels);
  std::vector<pcl::Indices> surfaces;
  if (!growInstanceSurfaces (
          organized, plane, seeds, max_step, max_radius, plane_tolerance, surfaces))
    return false;

  sizes.resize (models.size());
  for (std::size_t m = 0, id = 0; m < models.size(); ++m) {
    std::vector<InstanceExtent, Eigen::aligned_allocator<InstanceExtent>> extents;
    std::vector<std::size_t> measured;
    for (std::size_t i = 0; i < models[m].instances.size(); ++i, ++id) {
      InstanceExtent extent;
      if (fitInstanceBox (organized, plane, surfaces[id], extent)) {
        extents.push_back (extent);
        measured.push_back (i);
      }
    }
    int best_count = 0;
    std::size_t best_surface = std::numeric_limits<std::size_t>::max();
    for (std::size_t a = 0; a < extents.size(); ++a) {
      const auto count = static_cast<int> (
          std::count_if (extents.begin(), extents.end(), [&] (const InstanceExtent& b) {
            return agree (extents[a].size, b.size);
          }));
      if (count > best_count ||
          (count == best_count && extents[a].surface.size() < best_surface)) {
        best_count = count;
        best_surface = extents[a].surface.size();
        sizes[m].size = extents[a].size;
        sizes[m].box_in_model =
            models[m].instances[measured[a]].pose.inverse() * extents[a].pose;
      }
    }
    sizes[m].valid = best_count > 0 && best_count >= min_agreeing;
  }
  return true;
}

std::string
ModelSizeMeasurement::measurementProblem (const ObjectModels& models) const
{
  if (std::string problem = planeMeasurementProblem (models); !problem.empty())
    return problem;
  if (!(size_tolerance_ >= 0.0f) || !(relative_size_tolerance_ >= 0.0f))
    return "the size tolerances must be >= 0";
  if (min_agreeing_ < 1)
    return "at least one instance must agree on a size";
  return "";
}

bool
ModelSizeMeasurement::measureSizes (const ObjectModels& models,
                                    const Eigen::Vector4f& plane,
                                    ModelSizes& sizes) const
{
  return measureModelSizes (*surface_.organized,
                            plane,
                            surface_.keypoint_pixels,
                            models,
                            max_step_,
                            max_radius_,
                            plane_tolerance_,
                            agreement(),
                            min_agreeing_,
                            sizes);
}

} // namespace mid
