#include <mid/segmentation/triplet_distance.h>

namespace mid {

namespace {

/** sum_i |T(x_i) - y_i| over the columns. */
float
transferError (const Eigen::Matrix3f& rotation,
               const Eigen::Vector3f& translation,
               const Eigen::Matrix3f& x,
               const Eigen::Matrix3f& y)
{
  return ((rotation * x).colwise() + translation - y).colwise().norm().sum();
}

} // namespace

TripletGeometry
makeTripletGeometry (const TripletMatch& triplet,
                     const KeypointCloud& source,
                     const KeypointCloud& target)
{
  TripletGeometry g;
  for (int k = 0; k < 3; ++k) {
    const auto& c = triplet.correspondences[static_cast<std::size_t> (k)];
    g.p.col (k) = source[static_cast<std::size_t> (c.index_query)].getVector3fMap();
    g.q.col (k) = target[static_cast<std::size_t> (c.index_match)].getVector3fMap();
  }
  g.rotation = triplet.transformation.topLeftCorner<3, 3>();
  g.translation = triplet.transformation.topRightCorner<3, 1>();
  g.p_centroid = g.p.rowwise().mean();
  g.q_centroid = g.q.rowwise().mean();
  return g;
}

TripletGeometry
invertTripletGeometry (const TripletGeometry& geometry)
{
  TripletGeometry inverse;
  inverse.p = geometry.q;
  inverse.q = geometry.p;
  inverse.rotation = geometry.rotation.transpose();
  inverse.translation = -(inverse.rotation * geometry.translation);
  inverse.p_centroid = geometry.q_centroid;
  inverse.q_centroid = geometry.p_centroid;
  return inverse;
}

float
tripletDistance (const TripletGeometry& pq, const TripletGeometry& ab)
{
  return transferError (pq.rotation, pq.translation, ab.p, ab.q) +
         transferError (ab.rotation, ab.translation, pq.p, pq.q);
}

float
tripletDistanceLowerBound (const TripletGeometry& pq, const TripletGeometry& ab)
{
  return 3.0f * ((pq.rotation * ab.p_centroid + pq.translation - ab.q_centroid).norm() +
                 (ab.rotation * pq.p_centroid + ab.translation - pq.q_centroid).norm());
}

} // namespace mid
