#include <mid/segmentation/photometric_verification.h>

#include <pcl/common/point_tests.h>
#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>

namespace mid {

namespace {

/** Running sums of grey-level pairs (a at a point's own pixel, b where it moved to). */
struct GreyPairs
{
  double n = 0.0, sa = 0.0, sb = 0.0, saa = 0.0, sbb = 0.0, sab = 0.0;

  void
  add (double a, double b)
  {
    n += 1.0;
    sa += a;
    sb += b;
    saa += a * a;
    sbb += b * b;
    sab += a * b;
  }

  /** Normalized cross-correlation; 0 when either side has no contrast. */
  double
  correlation () const
  {
    if (n < 2.0)
      return 0.0;
    const double va = saa - sa * sa / n, vb = sbb - sb * sb / n,
                 cab = sab - sa * sb / n;
    return va > 0.0 && vb > 0.0 ? cab / std::sqrt (va * vb) : 0.0;
  }
};

/** The grey-level pairs of the surface around `keypoints` moved by `motion` (see
  * PhotometricVerification).
  */
GreyPairs
movedSurfacePairs (const KeypointSurface& surface,
                   const FramePinhole& pinhole,
                   const pcl::Indices& keypoints,
                   const Eigen::Matrix4f& motion,
                   float radius,
                   float tolerance)
{
  const pcl::PointCloud<pcl::PointXYZ>& cloud = *surface.organized;
  const std::vector<float>& grey = *surface.intensity;
  const auto width = static_cast<int> (cloud.width),
             height = static_cast<int> (cloud.height);
  const Eigen::Affine3f move (motion);
  const double focal = std::max (std::abs (pinhole.fx), std::abs (pinhole.fy));
  GreyPairs pairs;
  for (const pcl::index_t k : keypoints) {
    const pcl::index_t pixel = surface.keypoint_pixels[static_cast<std::size_t> (k)];
    const Eigen::Vector3f centre =
        cloud[static_cast<std::size_t> (pixel)].getVector3fMap();
    if (!centre.allFinite() || !(std::abs (centre.z()) > 1e-6f))
      continue;
    // About 9 x 9 pixels of a grid over the radius, whatever the resolution.
    const int reach = static_cast<int> (
        std::min (std::ceil (focal * radius / std::abs (centre.z())), 1000.0));
    const int step = std::max (1, reach / 4);
    const int u0 = pixel % width, v0 = pixel / width;
    for (int v = std::max (0, v0 - reach); v <= std::min (height - 1, v0 + reach);
         v += step)
      for (int u = std::max (0, u0 - reach); u <= std::min (width - 1, u0 + reach);
           u += step) {
        const std::size_t own =
            static_cast<std::size_t> (v) * cloud.width + static_cast<std::size_t> (u);
        const Eigen::Vector3f point = cloud[own].getVector3fMap();
        if (!point.allFinite() || (point - centre).norm() > radius)
          continue;
        const Eigen::Vector3f moved = move * point;
        int mu = 0, mv = 0;
        if (!pinhole.project (moved, width, height, mu, mv))
          continue;
        const std::size_t there =
            static_cast<std::size_t> (mv) * cloud.width + static_cast<std::size_t> (mu);
        const pcl::PointXYZ& seen = cloud[there];
        // Depths along the view: the frame may look down -z (a half turn about x).
        if (pcl::isXYZFinite (seen) &&
            std::abs (std::abs (seen.z) - std::abs (moved.z())) <= tolerance)
          pairs.add (grey[own], grey[there]);
      }
  }
  return pairs;
}

/** True if every keypoint of the clusters' point sets is below `keypoints`. */
bool
keypointsHavePixels (const TripletClusters& clusters, std::size_t keypoints)
{
  const auto inside = [keypoints] (pcl::index_t k) {
    return k >= 0 && static_cast<std::size_t> (k) < keypoints;
  };
  return std::all_of (
      clusters.begin(), clusters.end(), [&inside] (const TripletCluster& c) {
        return std::all_of (c.source_indices.begin(), c.source_indices.end(), inside) &&
               std::all_of (c.target_indices.begin(), c.target_indices.end(), inside);
      });
}

} // namespace

std::vector<float>
greyLevels (const pcl::PointCloud<pcl::PointXYZRGB>& frame)
{
  std::vector<float> grey;
  grey.reserve (frame.size());
  for (const auto& p : frame)
    grey.push_back (0.299f * static_cast<float> (p.r) +
                    0.587f * static_cast<float> (p.g) +
                    0.114f * static_cast<float> (p.b));
  return grey;
}

void
PhotometricVerification::setKeypointSurface (const KeypointSurface& surface)
{
  surface_ = surface;
  has_pinhole_ = surface_.organized && fitFramePinhole (*surface_.organized, pinhole_);
}

double
PhotometricVerification::correlation (const TripletCluster& cluster, bool& tested) const
{
  tested = false;
  if (!has_pinhole_)
    return 0.0;
  const GreyPairs forward = movedSurfacePairs (surface_,
                                               pinhole_,
                                               cluster.source_indices,
                                               cluster.transformation,
                                               radius_,
                                               depth_tolerance_);
  const GreyPairs backward = movedSurfacePairs (surface_,
                                                pinhole_,
                                                cluster.target_indices,
                                                cluster.transformation.inverse(),
                                                radius_,
                                                depth_tolerance_);
  const auto enough = static_cast<double> (min_pairs_);
  tested = forward.n >= enough && backward.n >= enough;
  return std::min (forward.correlation(), backward.correlation());
}

bool
PhotometricVerification::filter (const TripletClusters& clusters,
                                 TripletClusters& verified) const
{
  verified.clear();
  if (!(radius_ > 0.0f) || !(depth_tolerance_ > 0.0f) || !(min_correlation_ >= -1.0f) ||
      !(min_correlation_ <= 1.0f)) {
    PCL_ERROR (
        "[mid::PhotometricVerification::filter] The radius (%g) and depth tolerance "
        "(%g) must be positive and the minimum correlation (%g) in [-1, 1].\n",
        static_cast<double> (radius_),
        static_cast<double> (depth_tolerance_),
        static_cast<double> (min_correlation_));
    return false;
  }
  if (!isValidKeypointSurface (surface_, surface_.keypoint_pixels.size()) ||
      !keypointsHavePixels (clusters, surface_.keypoint_pixels.size())) {
    PCL_ERROR (
        "[mid::PhotometricVerification::filter] The keypoint surface must be an "
        "organized frame with a pixel inside it for every keypoint of the clusters.\n");
    return false;
  }
  if (!surface_.intensity || surface_.intensity->size() != surface_.organized->size()) {
    PCL_ERROR (
        "[mid::PhotometricVerification::filter] The keypoint surface needs one grey "
        "level per pixel (%zu given for %zu pixels).\n",
        surface_.intensity ? surface_.intensity->size() : std::size_t{0},
        static_cast<std::size_t> (surface_.organized->size()));
    return false;
  }
  if (!has_pinhole_) {
    PCL_ERROR (
        "[mid::PhotometricVerification::filter] No pinhole camera fits the organized "
        "frame (its points do not project onto their pixels).\n");
    return false;
  }
  for (const auto& cluster : clusters) {
    bool tested = false;
    const double c = correlation (cluster, tested);
    if (!tested || c >= static_cast<double> (min_correlation_))
      verified.push_back (cluster);
  }
  return true;
}

} // namespace mid
