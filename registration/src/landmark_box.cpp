#include <mid/registration/landmark_box.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace mid {

namespace {

/** The value at `share` of the sorted values (index floor (share (n - 1)); n > 0). */
float
percentile (const std::vector<float>& sorted, float share)
{
  const auto at = static_cast<std::size_t> (
      std::floor (share * static_cast<float> (sorted.size() - 1)));
  return sorted[at];
}

} // namespace

float
LandmarkBox::distanceTo (const Eigen::Vector3f& point) const
{
  if (!valid)
    return std::numeric_limits<float>::infinity();
  const Eigen::Vector3f local = axes.transpose() * (point - center);
  return (local.cwiseAbs() - half_extent).cwiseMax (0.0f).norm();
}

LandmarkBox
computeLandmarkBox (const ObjectModel& model, float trim)
{
  LandmarkBox box;
  std::vector<Eigen::Vector3f, Eigen::aligned_allocator<Eigen::Vector3f>> points;
  for (const auto& landmark : model.landmarks)
    if (landmark.getVector3fMap().allFinite())
      points.emplace_back (landmark.getVector3fMap());
  if (points.size() < 3 || !(trim >= 0.0f && trim < 0.5f))
    return box;
  Eigen::Vector3f mean = Eigen::Vector3f::Zero();
  for (const auto& p : points)
    mean += p;
  mean /= static_cast<float> (points.size());
  Eigen::Matrix3f covariance = Eigen::Matrix3f::Zero();
  for (const auto& p : points)
    covariance += (p - mean) * (p - mean).transpose();
  // The eigenvalues come in increasing order: the columns reversed put the largest first.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3f> solver (covariance);
  box.axes = solver.eigenvectors().rowwise().reverse();
  Eigen::Vector3f low, high;
  std::vector<float> coordinates (points.size());
  for (int axis = 0; axis < 3; ++axis) {
    std::transform (
        points.begin(),
        points.end(),
        coordinates.begin(),
        [&] (const Eigen::Vector3f& p) { return box.axes.col (axis).dot (p - mean); });
    std::sort (coordinates.begin(), coordinates.end());
    low[axis] = percentile (coordinates, trim);
    high[axis] = percentile (coordinates, 1.0f - trim);
  }
  box.center = mean + box.axes * (0.5f * (low + high));
  box.half_extent = 0.5f * (high - low);
  box.valid = true;
  return box;
}

} // namespace mid
