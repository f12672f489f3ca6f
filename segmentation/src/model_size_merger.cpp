#include <mid/registration/model_merging.h>
#include <mid/segmentation/instance_extent.h>
#include <mid/segmentation/model_size_merger.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace mid {

namespace {

/** Share of the frame's valid points that its support plane must hold. */
constexpr float kMinPlaneShare = 0.2f;

/** The size a model's instances agree on, and the box's frame in the model frame. */
struct ModelSize
{
  bool valid = false;
  Eigen::Vector3f size = Eigen::Vector3f::Zero();
  Eigen::Matrix4f box_in_model = Eigen::Matrix4f::Identity();

  EIGEN_MAKE_ALIGNED_OPERATOR_NEW
};

using ModelSizes = std::vector<ModelSize, Eigen::aligned_allocator<ModelSize>>;

class SizeAgreement
{
public:
  SizeAgreement (float absolute, float relative)
  : absolute_ (absolute), relative_ (relative)
  {}

  bool
  operator() (const Eigen::Vector3f& a, const Eigen::Vector3f& b) const
  {
    for (int i = 0; i < 3; ++i)
      if (std::abs (a[i] - b[i]) >
          std::max (absolute_, relative_ * std::max (a[i], b[i])))
        return false;
    return true;
  }

private:
  float absolute_, relative_;
};

} // namespace

std::string
ModelSizeMerger::inputProblem (const ObjectModels& models) const
{
  if (!keypoints_)
    return "no input keypoints";
  if (!isValidKeypointSurface (surface_, keypoints_->size()))
    return "the keypoint surface is not an organized frame holding every keypoint's "
           "pixel";
  if (!(max_step_ > 0.0f) || !(max_radius_ > 0.0f) || !(plane_tolerance_ > 0.0f))
    return "the step, radius and plane tolerance must be > 0";
  if (!(size_tolerance_ >= 0.0f) || !(relative_size_tolerance_ >= 0.0f))
    return "the size tolerances must be >= 0";
  if (min_agreeing_ < 1)
    return "at least one instance must agree on a size";
  for (const auto& model : models)
    for (const auto& instance : model.instances)
      for (const auto k : instance.keypoints)
        if (k < 0 || static_cast<std::size_t> (k) >= keypoints_->size())
          return "an instance observes a keypoint outside the input keypoints";
  return "";
}

bool
ModelSizeMerger::merge (ObjectModels& models) const
{
  const std::string problem = inputProblem (models);
  if (!problem.empty()) {
    PCL_ERROR ("[mid::ModelSizeMerger::merge] %s.\n", problem.c_str());
    return false;
  }
  if (models.size() < 2)
    return true;
  const auto& organized = *surface_.organized;
  Eigen::Vector4f plane;
  if (!fitSupportPlane (organized, plane_tolerance_, kMinPlaneShare, plane))
    return true;

  // Every instance's surface, grown from its keypoints' pixels, all at once.
  std::vector<pcl::Indices> seeds;
  for (const auto& model : models)
    for (const auto& instance : model.instances) {
      seeds.emplace_back();
      for (const auto k : instance.keypoints)
        seeds.back().push_back (surface_.keypoint_pixels[static_cast<std::size_t> (k)]);
    }
  std::vector<pcl::Indices> surfaces;
  if (!growInstanceSurfaces (
          organized, plane, seeds, max_step_, max_radius_, plane_tolerance_, surfaces))
    return false;

  const SizeAgreement agree (size_tolerance_, relative_size_tolerance_);
  ModelSizes sizes (models.size());
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
    sizes[m].valid = best_count >= min_agreeing_;
  }

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
