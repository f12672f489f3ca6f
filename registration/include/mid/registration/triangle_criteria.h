#pragma once

#include <Eigen/Core>

#include <array>

namespace mid {

/** \brief Three 3D points (keypoint positions) or three normals. */
using Triangle = std::array<Eigen::Vector3f, 3>;

/** \brief True if every edge of the triangle is in [min_length, max_length] (metres).
  * The paper keeps triangles with edges between 10 mm and 125 mm.
  * \param[in] triangle three points (metres)
  * \param[in] min_length shortest allowed edge (metres)
  * \param[in] max_length longest allowed edge (metres)
  * \return false also if a coordinate is NaN
  */
bool
hasEdgeLengthsWithin (const Triangle& triangle, float min_length, float max_length);

/** \brief True if every interior angle of the triangle exceeds min_angle (radians): triangles
  * that are too acute give poorly conditioned poses. The paper uses 10 degrees.
  * \param[in] triangle three points (metres)
  * \param[in] min_angle smallest allowed interior angle (radians)
  * \return false also for a degenerate triangle (coinciding vertices)
  */
bool
hasAnglesAbove (const Triangle& triangle, float min_angle);

/** \brief On which side of the surface the triangle winds: the cosine between the triangle's
  * normal (p1 - p0) x (p2 - p0) and the mean surface normal at its vertices, in [-1, 1].
  *
  * A rigid motion keeps this value; a mirror reflection negates it. It is the 3D form of the
  * sidedness test of the paper (after Ferrari et al.): in 3D any triangle and its mirror image are
  * congruent by a rotation, so it is the surface normals that tell a reflection apart.
  * Returns 0 if the triangle is degenerate or the normals cancel.
  * \param[in] points the three vertices (metres)
  * \param[in] normals the surface normal at each vertex (any non-zero length)
  * \return the cosine, in [-1, 1]
  */
float
triangleSidedness (const Triangle& points, const Triangle& normals);

/** \brief The smallest 3D distance between two solid triangles, 0 if they touch or intersect.
  * \param[in] a first triangle (metres); a degenerate one is handled as its segment or point
  * \param[in] b second triangle (metres)
  * \return the distance (metres)
  */
float
triangleDistance (const Triangle& a, const Triangle& b);

} // namespace mid
