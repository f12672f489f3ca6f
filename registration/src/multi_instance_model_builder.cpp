#include "point_set_graph.h"

#include <mid/registration/model_refinement.h>
#include <mid/registration/multi_instance_model_builder.h>

#include <Eigen/Geometry>
#include <pcl/console/print.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <set>

namespace mid {

namespace {

/** Union-find over keypoint indices, joined by the clusters' correspondences: a class is one
  * physical point of the object seen on several instances (a landmark).
  */
class LandmarkClasses
{
public:
  LandmarkClasses (std::size_t keypoints, const TripletClusters& clusters)
  : parent_ (keypoints)
  {
    std::iota (parent_.begin(), parent_.end(), std::size_t{0});
    for (const auto& cluster : clusters)
      for (const auto& c : cluster.correspondences)
        unite (static_cast<std::size_t> (c.index_query),
               static_cast<std::size_t> (c.index_match));
  }

  std::size_t
  find (std::size_t i)
  {
    while (parent_[i] != i)
      i = parent_[i] = parent_[parent_[i]];
    return i;
  }

private:
  void
  unite (std::size_t a, std::size_t b)
  {
    a = find (a);
    b = find (b);
    if (a != b)
      parent_[std::max (a, b)] = std::min (a, b);
  }

  std::vector<std::size_t> parent_;
};

/** The keypoints of each group of a component: all the keypoints of its sets, except that a
  * contested keypoint (shared by the sets of a link the graph rejected) goes only to the group
  * whose sets hold it most often, on a tie to the group whose keypoints' centroid is nearest
  * (the set that holds it as a stray reaches over to another copy).
  */
std::vector<std::set<pcl::index_t>>
assignKeypointsToGroups (const detail::PointSetGraph& graph,
                         const KeypointCloud& keypoints,
                         const std::vector<std::size_t>& component,
                         const std::vector<int>& group,
                         std::size_t groups)
{
  std::map<pcl::index_t, std::vector<std::size_t>> holders_per_group;
  std::vector<Eigen::Vector3f, Eigen::aligned_allocator<Eigen::Vector3f>> centroids (
      groups, Eigen::Vector3f::Zero());
  std::vector<std::size_t> sizes (groups, 0);
  for (const std::size_t n : component) {
    const auto g = static_cast<std::size_t> (group[n]);
    for (const auto k : graph.points (n)) {
      auto& holders = holders_per_group[k];
      holders.resize (groups, 0);
      ++holders[g];
      centroids[g] += keypoints[static_cast<std::size_t> (k)].getVector3fMap();
      ++sizes[g];
    }
  }
  for (std::size_t g = 0; g < groups; ++g)
    centroids[g] /= static_cast<float> (std::max<std::size_t> (1, sizes[g]));
  std::vector<std::set<pcl::index_t>> points (groups);
  for (const auto& [k, holders] : holders_per_group) {
    if (graph.contestedKeypoints().count (k) == 0) {
      for (std::size_t g = 0; g < groups; ++g)
        if (holders[g] > 0)
          points[g].insert (k);
      continue;
    }
    const Eigen::Vector3f p = keypoints[static_cast<std::size_t> (k)].getVector3fMap();
    std::size_t best = 0;
    for (std::size_t g = 1; g < groups; ++g)
      if (holders[g] > holders[best] ||
          (holders[g] == holders[best] &&
           (p - centroids[g]).norm() < (p - centroids[best]).norm()))
        best = g;
    points[best].insert (k);
  }
  return points;
}

/** Landmark normals: the mean of the observed normals rotated into the model frame. */
void
estimateLandmarkNormals (ObjectModel& model, const KeypointCloud& keypoints)
{
  std::vector<Eigen::Vector3f, Eigen::aligned_allocator<Eigen::Vector3f>> sums (
      model.landmarks.size(), Eigen::Vector3f::Zero());
  for (const auto& instance : model.instances) {
    const Eigen::Matrix3f rotation = instance.pose.topLeftCorner<3, 3>();
    for (std::size_t o = 0; o < instance.keypoints.size(); ++o)
      sums[static_cast<std::size_t> (instance.landmarks[o])] +=
          rotation.transpose() *
          keypoints[static_cast<std::size_t> (instance.keypoints[o])]
              .getNormalVector3fMap();
  }
  for (std::size_t l = 0; l < model.landmarks.size(); ++l) {
    model.landmarks[l].getNormalVector3fMap() = sums[l].normalized();
    model.landmarks[l].curvature = 0.0f;
  }
}

} // namespace

bool
MultiInstanceModelBuilder::checkInputs() const
{
  const char* name = "[mid::MultiInstanceModelBuilder::compute]";
  if (!input_ || !descriptors_ || !clusters_) {
    PCL_ERROR ("%s Keypoints, descriptors and clusters must all be given.\n", name);
    return false;
  }
  if (input_->size() != descriptors_->size()) {
    PCL_ERROR ("%s %zu keypoints but %zu descriptors.\n",
               name,
               input_->size(),
               descriptors_->size());
    return false;
  }
  if (!(shared_point_weight_ >= 0.0) || refinement_iterations_ < 0 ||
      !(duplicate_angle_ >= 0.0f) || !(duplicate_distance_ >= 0.0f)) {
    PCL_ERROR ("%s Invalid parameter: shared point weight %g, refinement iterations "
               "%d, duplicate "
               "thresholds %g rad / %g m (all >= 0).\n",
               name,
               shared_point_weight_,
               refinement_iterations_,
               static_cast<double> (duplicate_angle_),
               static_cast<double> (duplicate_distance_));
    return false;
  }
  if (!(link_tolerance_ > 0.0f)) {
    PCL_ERROR ("%s Invalid link tolerance %g m (must be > 0).\n",
               name,
               static_cast<double> (link_tolerance_));
    return false;
  }
  for (const auto& cluster : *clusters_) {
    if (!cluster.transformation.allFinite()) {
      PCL_ERROR ("%s A cluster has a non-finite pose.\n", name);
      return false;
    }
    for (const auto& c : cluster.correspondences)
      if (c.index_query < 0 || c.index_match < 0 ||
          static_cast<std::size_t> (std::max (c.index_query, c.index_match)) >=
              input_->size()) {
        PCL_ERROR (
            "%s A cluster refers to keypoint %d -> %d, outside the %zu keypoints.\n",
            name,
            c.index_query,
            c.index_match,
            input_->size());
        return false;
      }
  }
  return true;
}

bool
MultiInstanceModelBuilder::compute (ObjectModels& models)
{
  models.clear();
  unused_keypoints_.clear();
  if (!checkInputs())
    return false;
  const KeypointCloud& keypoints = *input_;
  const TripletClusters& clusters = *clusters_;

  const detail::PointSetGraph graph (
      clusters, keypoints, shared_point_weight_, link_tolerance_);
  LandmarkClasses classes (keypoints.size(), clusters);
  std::vector<bool> used (keypoints.size(), false);

  for (const auto& component : graph.components()) {
    std::size_t reference = 0;
    detail::Transforms to_reference;
    std::vector<int> group;
    const std::size_t groups =
        graph.solveComponent (component, reference, to_reference, group);

    // One instance per group: the pose of its node nearest to the reference (model -> camera
    // is the inverse of camera -> reference frame); its keypoints are its nodes' points.
    detail::Transforms group_pose (groups, Eigen::Matrix4f::Zero());
    std::vector<bool> has_pose (groups, false);
    for (const std::size_t n : component) {
      const auto g = static_cast<std::size_t> (group[n]);
      if (!has_pose[g] || n == reference) {
        group_pose[g] = to_reference[n].inverse();
        has_pose[g] = true;
      }
    }
    const std::vector<std::set<pcl::index_t>> group_points =
        assignKeypointsToGroups (graph, keypoints, component, group, groups);
    // Merge groups whose poses coincide: one instance seen through sets that share no keypoint.
    Eigen::Vector3f center = Eigen::Vector3f::Zero();
    std::size_t count = 0;
    for (const std::size_t n : component)
      for (const auto k : graph.points (n)) {
        center += (to_reference[n].topLeftCorner<3, 3>() *
                   keypoints[static_cast<std::size_t> (k)].getVector3fMap()) +
                  to_reference[n].topRightCorner<3, 1>();
        ++count;
      }
    center /= static_cast<float> (std::max<std::size_t> (1, count));
    std::vector<std::size_t> instance_of_group (groups);
    std::vector<std::size_t> kept;
    for (std::size_t g = 0; g < groups; ++g) {
      instance_of_group[g] = kept.size();
      for (std::size_t i = 0; i < kept.size(); ++i)
        if (posesCoincide (group_pose[kept[i]],
                           group_pose[g],
                           center,
                           duplicate_angle_,
                           duplicate_distance_)) {
          instance_of_group[g] = i;
          break;
        }
      if (instance_of_group[g] == kept.size())
        kept.push_back (g);
    }

    ObjectModel model;
    model.instances.resize (kept.size());
    const std::size_t reference_instance =
        instance_of_group[static_cast<std::size_t> (group[reference])];
    std::vector<std::set<pcl::index_t>> instance_points (kept.size());
    for (std::size_t g = 0; g < groups; ++g)
      instance_points[instance_of_group[g]].insert (group_points[g].begin(),
                                                    group_points[g].end());
    std::map<std::size_t, int> landmark_of_class;
    std::vector<Eigen::Vector3f, Eigen::aligned_allocator<Eigen::Vector3f>> sums;
    std::vector<int> observations;
    for (std::size_t i = 0; i < kept.size(); ++i) {
      ModelInstance& instance = model.instances[i];
      instance.pose = group_pose[kept[i]];
      const Eigen::Matrix4f camera_to_model = instance.pose.inverse();
      for (const auto k : instance_points[i]) {
        const auto inserted =
            landmark_of_class.emplace (classes.find (static_cast<std::size_t> (k)),
                                       static_cast<int> (sums.size()));
        if (inserted.second) {
          sums.emplace_back (Eigen::Vector3f::Zero());
          observations.push_back (0);
        }
        const int l = inserted.first->second;
        sums[static_cast<std::size_t> (l)] +=
            camera_to_model.topLeftCorner<3, 3>() *
                keypoints[static_cast<std::size_t> (k)].getVector3fMap() +
            camera_to_model.topRightCorner<3, 1>();
        ++observations[static_cast<std::size_t> (l)];
        instance.keypoints.push_back (k);
        instance.landmarks.push_back (l);
        model.descriptors.push_back ((*descriptors_)[static_cast<std::size_t> (k)]);
        model.descriptor_landmarks.push_back (l);
        used[static_cast<std::size_t> (k)] = true;
      }
    }
    model.landmarks.resize (sums.size());
    for (std::size_t l = 0; l < sums.size(); ++l)
      model.landmarks[l].getVector3fMap() =
          sums[l] / static_cast<float> (observations[l]);

    if (refinement_iterations_ > 0)
      refineModel (model, keypoints, refinement_iterations_, reference_instance);
    estimateLandmarkNormals (model, keypoints);
    centerModelFrame (model);
    for (auto& instance : model.instances)
      updateInstanceError (model, keypoints, instance);
    updateModelDiameter (model);
    models.push_back (std::move (model));
  }

  std::stable_sort (
      models.begin(), models.end(), [] (const ObjectModel& a, const ObjectModel& b) {
        return a.descriptors.size() > b.descriptors.size();
      });
  for (std::size_t k = 0; k < keypoints.size(); ++k)
    if (!used[k])
      unused_keypoints_.push_back (static_cast<pcl::index_t> (k));
  return true;
}

} // namespace mid
