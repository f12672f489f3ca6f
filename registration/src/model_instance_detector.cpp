#include <mid/registration/model_instance_detector.h>
#include <mid/registration/rigid_transform.h>

#include <Eigen/Eigenvalues>
#include <opencv2/core.hpp>
#include <pcl/console/print.h>

#include <algorithm>
#include <random>

namespace mid {

namespace {

/** A landmark -> keypoint match. */
struct Match
{
  int landmark;
  pcl::index_t keypoint;
};

cv::Mat
toMatrix (const SIFTDescriptorCloud& descriptors, const pcl::Indices* subset = nullptr)
{
  const std::size_t rows = subset ? subset->size() : descriptors.size();
  cv::Mat matrix (static_cast<int> (rows), 128, CV_32F);
  for (std::size_t r = 0; r < rows; ++r) {
    const auto& d = descriptors[subset ? static_cast<std::size_t> ((*subset)[r]) : r];
    std::copy (
        d.histogram, d.histogram + 128, matrix.ptr<float> (static_cast<int> (r)));
  }
  return matrix;
}

/** Each candidate keypoint's nearest model descriptor, if close enough. */
std::vector<Match>
matchToModel (const ObjectModel& model,
              const SIFTDescriptorCloud& descriptors,
              const pcl::Indices& candidates,
              float max_distance)
{
  std::vector<Match> matches;
  if (candidates.empty() || model.descriptors.empty())
    return matches;
  cv::Mat distances;
  cv::batchDistance (toMatrix (descriptors, &candidates),
                     toMatrix (model.descriptors),
                     distances,
                     CV_32F,
                     cv::noArray(),
                     cv::NORM_L2);
  for (int r = 0; r < distances.rows; ++r) {
    cv::Point best;
    double best_distance = 0.0;
    cv::minMaxLoc (distances.row (r), &best_distance, nullptr, &best, nullptr);
    if (best_distance <= static_cast<double> (max_distance))
      matches.push_back ({model.descriptor_landmarks[static_cast<std::size_t> (best.x)],
                          candidates[static_cast<std::size_t> (r)]});
  }
  return matches;
}

/** The largest distance of a point from the line that fits the points best (through their
  * centroid along their main axis); 0 for fewer than three points.
  */
float
spreadOffLine (const Eigen::Matrix3Xf& points)
{
  if (points.cols() < 3)
    return 0.0f;
  const Eigen::Vector3f centroid = points.rowwise().mean();
  const Eigen::Matrix3Xf centred = points.colwise() - centroid;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3f> solver (centred *
                                                               centred.transpose());
  const Eigen::Vector3f axis = solver.eigenvectors().col (2);
  return (centred - axis * (axis.transpose() * centred)).colwise().norm().maxCoeff();
}

} // namespace

bool
ModelInstanceDetector::checkInputs() const
{
  const char* name = "[mid::ModelInstanceDetector::detect]";
  if (!model_ || !keypoints_ || !descriptors_) {
    PCL_ERROR ("%s Model, keypoints and descriptors must all be given.\n", name);
    return false;
  }
  if (keypoints_->size() != descriptors_->size() ||
      model_->descriptors.size() != model_->descriptor_landmarks.size()) {
    PCL_ERROR (
        "%s Keypoints and descriptors (or the model's descriptors and their landmarks) "
        "differ in number.\n",
        name);
    return false;
  }
  for (const int l : model_->descriptor_landmarks)
    if (l < 0 || static_cast<std::size_t> (l) >= model_->landmarks.size()) {
      PCL_ERROR ("%s The model refers to landmark %d of %zu.\n",
                 name,
                 l,
                 model_->landmarks.size());
      return false;
    }
  if (candidates_)
    for (const auto k : *candidates_)
      if (k < 0 || static_cast<std::size_t> (k) >= keypoints_->size()) {
        PCL_ERROR ("%s Candidate keypoint %d is outside the %zu keypoints.\n",
                   name,
                   k,
                   keypoints_->size());
        return false;
      }
  return hasValidParameters();
}

bool
ModelInstanceDetector::hasValidParameters() const
{
  if (!(max_descriptor_distance_ > 0.0f) || !(inlier_threshold_ > 0.0f) ||
      min_inliers_ < 3 || !(min_inlier_ratio_ >= 0.0f && min_inlier_ratio_ < 1.0f) ||
      !(min_inlier_spread_ >= 0.0f) || max_iterations_ < 1) {
    PCL_ERROR (
        "[mid::ModelInstanceDetector] Invalid parameter: descriptor distance %g, "
        "inlier "
        "threshold %g (> 0), min inliers %zu (>= 3), min inlier ratio %g (in [0, 1)), "
        "min inlier spread %g (>= 0), iterations %d (>= 1).\n",
        static_cast<double> (max_descriptor_distance_),
        static_cast<double> (inlier_threshold_),
        min_inliers_,
        static_cast<double> (min_inlier_ratio_),
        static_cast<double> (min_inlier_spread_),
        max_iterations_);
    return false;
  }
  return true;
}

bool
ModelInstanceDetector::detect (ModelInstances& instances) const
{
  instances.clear();
  if (!checkInputs())
    return false;
  const ObjectModel& model = *model_;
  const KeypointCloud& keypoints = *keypoints_;
  pcl::Indices candidates;
  if (candidates_)
    candidates = *candidates_;
  else
    for (std::size_t k = 0; k < keypoints.size(); ++k)
      candidates.push_back (static_cast<pcl::index_t> (k));
  std::vector<Match> matches =
      matchToModel (model, *descriptors_, candidates, max_descriptor_distance_);

  const auto landmark = [&model] (const Match& m) {
    return Eigen::Vector3f (
        model.landmarks[static_cast<std::size_t> (m.landmark)].getVector3fMap());
  };
  const auto point = [&keypoints] (const Match& m) {
    return Eigen::Vector3f (
        keypoints[static_cast<std::size_t> (m.keypoint)].getVector3fMap());
  };
  const auto fit = [&] (const std::vector<std::size_t>& chosen) {
    Eigen::Matrix3Xf from (3, static_cast<Eigen::Index> (chosen.size())),
        to (3, from.cols());
    for (std::size_t i = 0; i < chosen.size(); ++i) {
      from.col (static_cast<Eigen::Index> (i)) = landmark (matches[chosen[i]]);
      to.col (static_cast<Eigen::Index> (i)) = point (matches[chosen[i]]);
    }
    return estimateRigidTransform (from, to);
  };
  // The matches a pose brings within the inlier threshold.
  const auto inliersOf = [&] (const Eigen::Matrix4f& pose) {
    std::vector<std::size_t> inliers;
    for (std::size_t i = 0; i < matches.size(); ++i)
      if ((pose.topLeftCorner<3, 3>() * landmark (matches[i]) +
           pose.topRightCorner<3, 1>() - point (matches[i]))
              .norm() < inlier_threshold_)
        inliers.push_back (i);
    return inliers;
  };
  // Whether inliers fix a pose: their keypoints do not all lie along one line. Asked only of
  // a set that would become the best, as only the best set is ever kept.
  const auto spreads = [&] (const std::vector<std::size_t>& inliers) {
    if (!(min_inlier_spread_ > 0.0f))
      return true;
    Eigen::Matrix3Xf points (3, static_cast<Eigen::Index> (inliers.size()));
    for (std::size_t i = 0; i < inliers.size(); ++i)
      points.col (static_cast<Eigen::Index> (i)) = point (matches[inliers[i]]);
    return spreadOffLine (points) >= min_inlier_spread_;
  };

  std::mt19937 rng (seed_);
  const float reach = std::max (model.diameter, inlier_threshold_);
  while (matches.size() >= min_inliers_ &&
         (max_instances_ == 0 || instances.size() < max_instances_)) {
    std::vector<std::size_t> best;
    std::uniform_int_distribution<std::size_t> any (0, matches.size() - 1);
    for (int iteration = 0; iteration < max_iterations_; ++iteration) {
      const std::size_t first = any (rng);
      std::vector<std::size_t> near;
      for (std::size_t i = 0; i < matches.size(); ++i)
        if (i != first && matches[i].landmark != matches[first].landmark &&
            matches[i].keypoint != matches[first].keypoint &&
            (point (matches[i]) - point (matches[first])).norm() <= reach)
          near.push_back (i);
      if (near.size() < 2)
        continue;
      std::shuffle (near.begin(), near.end(), rng);
      const std::vector<std::size_t> sample{first, near[0], near[1]};
      const Eigen::Vector3f a = point (matches[first]), b = point (matches[near[0]]),
                            c = point (matches[near[1]]);
      if ((b - a).cross (c - a).norm() < 1e-6f ||
          matches[near[0]].landmark == matches[near[1]].landmark)
        continue;
      std::vector<std::size_t> inliers = inliersOf (fit (sample));
      if (inliers.size() > best.size() && spreads (inliers))
        best.swap (inliers);
    }
    if (best.size() < min_inliers_)
      break;
    Eigen::Matrix4f pose = fit (best);
    for (int refit = 0; refit < 2; ++refit) {
      std::vector<std::size_t> inliers = inliersOf (pose);
      if (inliers.size() < 3 || !spreads (inliers))
        break;
      best.swap (inliers);
      pose = fit (best);
    }
    // Inlier ratio over the matches within the model's reach of the hypothesis.
    const Eigen::Vector3f centre = pose.topRightCorner<3, 1>();
    std::size_t local = 0;
    for (const auto& m : matches)
      local += (point (m) - centre).norm() <= reach ? 1 : 0;
    const float ratio = static_cast<float> (best.size()) /
                        static_cast<float> (std::max<std::size_t> (1, local));
    if (best.size() < min_inliers_ || !(ratio > min_inlier_ratio_))
      break;

    ModelInstance instance;
    instance.pose = pose;
    std::vector<bool> taken (keypoints.size(), false);
    for (const std::size_t i : best) {
      if (taken[static_cast<std::size_t> (matches[i].keypoint)])
        continue;
      taken[static_cast<std::size_t> (matches[i].keypoint)] = true;
      instance.keypoints.push_back (matches[i].keypoint);
      instance.landmarks.push_back (matches[i].landmark);
    }
    updateInstanceError (model, keypoints, instance);
    instances.push_back (instance);
    matches.erase (
        std::remove_if (matches.begin(),
                        matches.end(),
                        [&taken] (const Match& m) {
                          return taken[static_cast<std::size_t> (m.keypoint)];
                        }),
        matches.end());
  }
  return true;
}

} // namespace mid
