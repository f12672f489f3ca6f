#include <mid/features/point_pair_feature.h>

#include <Eigen/Geometry>

#include <cmath>

namespace mid {

float
angleBetween (const Eigen::Vector3f& a, const Eigen::Vector3f& b)
{
  return std::atan2 (a.cross (b).norm(), a.dot (b));
}

bool
computePointPairFeature (const Eigen::Vector3f& p1,
                         const Eigen::Vector3f& n1,
                         const Eigen::Vector3f& p2,
                         const Eigen::Vector3f& n2,
                         PointPairFeature& feature)
{
  if (!p1.allFinite() || !p2.allFinite() || !n1.allFinite() || !n2.allFinite())
    return false;
  const Eigen::Vector3f d = p2 - p1;
  const float distance = d.norm();
  if (distance <= 0.0f || n1.squaredNorm() <= 0.0f || n2.squaredNorm() <= 0.0f)
    return false;
  feature.distance = distance;
  feature.angle_n1_d = angleBetween (n1, d);
  feature.angle_n2_d = angleBetween (n2, d);
  feature.angle_n1_n2 = angleBetween (n1, n2);
  return true;
}

PointPairFeature
pointPairFeatureDifference (const PointPairFeature& a, const PointPairFeature& b)
{
  PointPairFeature difference;
  difference.distance = std::abs (a.distance - b.distance);
  difference.angle_n1_d = std::abs (a.angle_n1_d - b.angle_n1_d);
  difference.angle_n2_d = std::abs (a.angle_n2_d - b.angle_n2_d);
  difference.angle_n1_n2 = std::abs (a.angle_n1_n2 - b.angle_n1_n2);
  return difference;
}

bool
arePointPairFeaturesSimilar (const PointPairFeature& a,
                             const PointPairFeature& b,
                             float max_distance_difference,
                             float max_angle_difference)
{
  const PointPairFeature d = pointPairFeatureDifference (a, b);
  return d.distance <= max_distance_difference &&
         d.angle_n1_d <= max_angle_difference && d.angle_n2_d <= max_angle_difference &&
         d.angle_n1_n2 <= max_angle_difference;
}

} // namespace mid
