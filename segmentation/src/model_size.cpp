#include <mid/segmentation/instance_extent.h>
#include <mid/segmentation/model_size.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace mid {

bool
SizeAgreement::edgesAgree (float x, float y) const
{
  return std::abs (x - y) <= std::max (absolute_, relative_ * std::max (x, y));
}

bool
SizeAgreement::operator() (const Eigen::Vector3f& a, const Eigen::Vector3f& b) const
{
  for (int i = 0; i < 3; ++i)
    if (!edgesAgree (a[i], b[i]))
      return false;
  return true;
}

bool
SizeAgreement::differOnEveryEdge (const Eigen::Vector3f& a,
                                  const Eigen::Vector3f& b) const
{
  for (int i = 0; i < 3; ++i)
    if (edgesAgree (a[i], b[i]))
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
measureInstanceBoxes (const pcl::PointCloud<pcl::PointXYZ>& organized,
                      const Eigen::Vector4f& plane,
                      const pcl::Indices& keypoint_pixels,
                      const ObjectModels& models,
                      float max_step,
                      float max_radius,
                      float plane_tolerance,
                      std::vector<InstanceExtents>& extents)
{
  extents.clear();
  const std::vector<pcl::Indices> seeds = instanceSeedPixels (models, keypoint_pixels);
  std::vector<pcl::Indices> surfaces;
  if (!growInstanceSurfaces (
          organized, plane, seeds, max_step, max_radius, plane_tolerance, surfaces))
    return false;
  extents.resize (models.size());
  for (std::size_t m = 0, id = 0; m < models.size(); ++m) {
    extents[m].resize (models[m].instances.size());
    for (auto& extent : extents[m])
      fitInstanceBox (organized, plane, surfaces[id++], extent);
  }
  return true;
}

std::vector<std::size_t>
measuredInstances (const InstanceExtents& extents)
{
  std::vector<std::size_t> measured;
  for (std::size_t i = 0; i < extents.size(); ++i)
    if (!extents[i].surface.empty())
      measured.push_back (i);
  return measured;
}

std::vector<std::size_t>
largestSizeGroup (const InstanceExtents& extents,
                  const std::vector<std::size_t>& candidates,
                  const SizeAgreement& agree,
                  std::size_t& representative)
{
  const SizeAgreement loosely = agree.scaled (2.0f);
  std::vector<std::size_t> best;
  std::size_t best_loose = 0;
  std::size_t best_surface = std::numeric_limits<std::size_t>::max();
  for (const std::size_t a : candidates) {
    std::vector<std::size_t> group;
    std::size_t loose = 0;
    for (const std::size_t b : candidates) {
      if (agree (extents[a].size, extents[b].size))
        group.push_back (b);
      if (loosely (extents[a].size, extents[b].size))
        ++loose;
    }
    const std::size_t surface = extents[a].surface.size();
    if (group.size() > best.size() ||
        (group.size() == best.size() &&
         (loose > best_loose || (loose == best_loose && surface < best_surface)))) {
      best = std::move (group);
      best_loose = loose;
      best_surface = surface;
      representative = a;
    }
  }
  return best;
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
  std::vector<InstanceExtents> extents;
  if (!measureInstanceBoxes (organized,
                             plane,
                             keypoint_pixels,
                             models,
                             max_step,
                             max_radius,
                             plane_tolerance,
                             extents))
    return false;
  modelSizesOfBoxes (models, extents, agree, min_agreeing, sizes);
  return true;
}

void
modelSizesOfBoxes (const ObjectModels& models,
                   const std::vector<InstanceExtents>& extents,
                   const SizeAgreement& agree,
                   int min_agreeing,
                   ModelSizes& sizes)
{
  sizes.assign (models.size(), ModelSize());
  for (std::size_t m = 0; m < models.size(); ++m) {
    std::size_t representative = 0;
    const std::vector<std::size_t> group = largestSizeGroup (
        extents[m], measuredInstances (extents[m]), agree, representative);
    if (group.empty())
      continue;
    sizes[m].size = extents[m][representative].size;
    sizes[m].box_in_model = models[m].instances[representative].pose.inverse() *
                            extents[m][representative].pose;
    sizes[m].agreeing = static_cast<int> (group.size());
    sizes[m].valid = sizes[m].agreeing >= min_agreeing;
  }
}

bool
boxOfSize (const Eigen::Vector3f& size,
           const ModelSize& own,
           const ObjectModel& model,
           const InstanceExtents& extents,
           const SizeAgreement& agree,
           Eigen::Matrix4f& box_in_model)
{
  if (own.valid && agree (size, own.size)) {
    box_in_model = own.box_in_model;
    return true;
  }
  for (const std::size_t i : measuredInstances (extents))
    if (agree (size, extents[i].size)) {
      box_in_model = model.instances[i].pose.inverse() * extents[i].pose;
      return true;
    }
  return false;
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
ModelSizeMeasurement::measure (const ObjectModels& models, ModelSizes& sizes) const
{
  sizes.clear();
  if (const std::string problem = measurementProblem (models); !problem.empty()) {
    PCL_ERROR ("[mid::ModelSizeMeasurement::measure] %s.\n", problem.c_str());
    return false;
  }
  Eigen::Vector4f plane;
  if (models.empty() || !fitPlane (plane)) {
    sizes.resize (models.size());
    return true;
  }
  return measureSizes (models, plane, sizes);
}

bool
ModelSizeMeasurement::measureBoxes (const ObjectModels& models,
                                    const Eigen::Vector4f& plane,
                                    std::vector<InstanceExtents>& extents) const
{
  return measureInstanceBoxes (*surface_.organized,
                               plane,
                               surface_.keypoint_pixels,
                               models,
                               max_step_,
                               max_radius_,
                               plane_tolerance_,
                               extents);
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
