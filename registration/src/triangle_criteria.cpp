#include <mid/features/point_pair_feature.h>
#include <mid/registration/triangle_criteria.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace mid {

namespace {

/** Closest point of triangle abc to p (Ericson, Real-Time Collision Detection, 5.1.5). */
Eigen::Vector3f
closestPointOnTriangle (const Eigen::Vector3f& p, const Triangle& t)
{
  const Eigen::Vector3f &a = t[0], &b = t[1], &c = t[2];
  const Eigen::Vector3f ab = b - a, ac = c - a, ap = p - a;
  const float d1 = ab.dot (ap), d2 = ac.dot (ap);
  if (d1 <= 0.0f && d2 <= 0.0f)
    return a;
  const Eigen::Vector3f bp = p - b;
  const float d3 = ab.dot (bp), d4 = ac.dot (bp);
  if (d3 >= 0.0f && d4 <= d3)
    return b;
  const float vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f)
    return a + (d1 / (d1 - d3)) * ab;
  const Eigen::Vector3f cp = p - c;
  const float d5 = ab.dot (cp), d6 = ac.dot (cp);
  if (d6 >= 0.0f && d5 <= d6)
    return c;
  const float vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f)
    return a + (d2 / (d2 - d6)) * ac;
  const float va = d3 * d6 - d5 * d4;
  if (va <= 0.0f && (d4 - d3) >= 0.0f && (d5 - d6) >= 0.0f)
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const float denominator = va + vb + vc;
  if (!(denominator > 0.0f)) // degenerate triangle: fall back to its vertices
    return (p - a).squaredNorm() < (p - b).squaredNorm() ? a : b;
  return a + ab * (vb / denominator) + ac * (vc / denominator);
}

/** Distance between segments p1q1 and p2q2 (Ericson, 5.1.9). */
float
segmentDistance (const Eigen::Vector3f& p1,
                 const Eigen::Vector3f& q1,
                 const Eigen::Vector3f& p2,
                 const Eigen::Vector3f& q2)
{
  constexpr float kEpsilon = 1e-12f;
  const Eigen::Vector3f d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const float a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot (r);
  float s = 0.0f, t = 0.0f;
  if (a <= kEpsilon && e <= kEpsilon)
    return r.norm();
  if (a <= kEpsilon)
    t = std::clamp (f / e, 0.0f, 1.0f);
  else {
    const float c = d1.dot (r);
    if (e <= kEpsilon)
      s = std::clamp (-c / a, 0.0f, 1.0f);
    else {
      const float b = d1.dot (d2), denominator = a * e - b * b;
      s = denominator > kEpsilon
              ? std::clamp ((b * f - c * e) / denominator, 0.0f, 1.0f)
              : 0.0f;
      t = (b * s + f) / e;
      if (t < 0.0f) {
        t = 0.0f;
        s = std::clamp (-c / a, 0.0f, 1.0f);
      }
      else if (t > 1.0f) {
        t = 1.0f;
        s = std::clamp ((b - c) / a, 0.0f, 1.0f);
      }
    }
  }
  return ((p1 + s * d1) - (p2 + t * d2)).norm();
}

/** True if segment pq pierces triangle t (Moeller-Trumbore restricted to the segment). */
bool
segmentIntersectsTriangle (const Eigen::Vector3f& p,
                           const Eigen::Vector3f& q,
                           const Triangle& t)
{
  const Eigen::Vector3f direction = q - p;
  const Eigen::Vector3f e1 = t[1] - t[0], e2 = t[2] - t[0];
  const Eigen::Vector3f h = direction.cross (e2);
  const float det = e1.dot (h);
  if (std::abs (det) < 1e-12f)
    return false; // parallel: the edge distances decide
  const float inverse = 1.0f / det;
  const Eigen::Vector3f s = p - t[0];
  const float u = inverse * s.dot (h);
  if (u < 0.0f || u > 1.0f)
    return false;
  const Eigen::Vector3f qv = s.cross (e1);
  const float v = inverse * direction.dot (qv);
  if (v < 0.0f || u + v > 1.0f)
    return false;
  const float along = inverse * e2.dot (qv);
  return along >= 0.0f && along <= 1.0f;
}

float
segmentTriangleDistance (const Eigen::Vector3f& p,
                         const Eigen::Vector3f& q,
                         const Triangle& t)
{
  if (segmentIntersectsTriangle (p, q, t))
    return 0.0f;
  float distance = std::min ((closestPointOnTriangle (p, t) - p).norm(),
                             (closestPointOnTriangle (q, t) - q).norm());
  for (int k = 0; k < 3; ++k)
    distance = std::min (distance, segmentDistance (p, q, t[k], t[(k + 1) % 3]));
  return distance;
}

} // namespace

bool
hasEdgeLengthsWithin (const Triangle& triangle, float min_length, float max_length)
{
  for (int k = 0; k < 3; ++k) {
    const float length = (triangle[(k + 1) % 3] - triangle[k]).norm();
    if (!(length >= min_length && length <= max_length))
      return false;
  }
  return true;
}

bool
hasAnglesAbove (const Triangle& triangle, float min_angle)
{
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3f& corner = triangle[k];
    const float angle =
        angleBetween (triangle[(k + 1) % 3] - corner, triangle[(k + 2) % 3] - corner);
    if (!(angle > min_angle))
      return false;
  }
  return true;
}

float
triangleSidedness (const Triangle& points, const Triangle& normals)
{
  const Eigen::Vector3f winding = (points[1] - points[0]).cross (points[2] - points[0]);
  const Eigen::Vector3f surface = normals[0] + normals[1] + normals[2];
  const float scale = winding.norm() * surface.norm();
  if (!(scale > 0.0f))
    return 0.0f;
  return winding.dot (surface) / scale;
}

float
triangleDistance (const Triangle& a, const Triangle& b)
{
  float distance = std::numeric_limits<float>::infinity();
  for (int k = 0; k < 3 && distance > 0.0f; ++k) {
    distance = std::min (distance, segmentTriangleDistance (a[k], a[(k + 1) % 3], b));
    distance = std::min (distance, segmentTriangleDistance (b[k], b[(k + 1) % 3], a));
  }
  return distance;
}

} // namespace mid
