#include "paired_sums.h"

#include <mid/segmentation/photometric_verification.h>

#include <Eigen/Geometry>
#include <pcl/common/point_tests.h>
#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace mid {

namespace {

/** Fewest pairs of one keypoint's neighbourhood that can tell on its own (of about 50 in
  * its disc).
  */
constexpr double kNeighbourhoodPairs = 20.0;

/** Least standard deviation (grey levels) of both sides of a neighbourhood that can tell
  * on its own: print, not the noise of a uniform ground.
  */
constexpr double kNeighbourhoodContrast = 5.0;

/** Fewest neighbourhoods, both ways together, whose share of disagreeing ones can reject. */
constexpr std::size_t kMinNeighbourhoods = 4;

/** How far a chromaticity (red and green shares) lies from grey: the sum of the three shares'
  * distances from a third (0 for grey, up to 4/3 for a pure primary).
  */
double
saturation (const Chromaticity& c)
{
  const double third = 1.0 / 3.0;
  return std::abs (c[0] - third) + std::abs (c[1] - third) +
         std::abs (1.0 - c[0] - c[1] - third);
}

/** Sums of the chromaticities of colour pairs: at the own pixels and where they moved to. */
struct ColourSums
{
  double pairs = 0.0;
  double own_red = 0.0, own_green = 0.0, moved_red = 0.0, moved_green = 0.0;

  void
  add (const Chromaticity& a, const Chromaticity& b)
  {
    pairs += 1.0;
    own_red += a[0];
    own_green += a[1];
    moved_red += b[0];
    moved_green += b[1];
  }
};

/** |dr| + |dg| between the mean colour of one side and the other's, over both directions
  * (forward: P moved onto Q; backward: Q moved onto P).
  */
double
meanColourDifference (const ColourSums& forward, const ColourSums& backward)
{
  const double n = forward.pairs + backward.pairs;
  return std::abs (forward.own_red + backward.moved_red - forward.moved_red -
                   backward.own_red) /
             n +
         std::abs (forward.own_green + backward.moved_green - forward.moved_green -
                   backward.own_green) /
             n;
}

/** Grey-level pairs: x at a point's own pixel, y where it moved to; and the chromaticities of
  * the pairs where both pixels have a colour, of all of them and of the vivid ones.
  */
struct GreyPairs : detail::PairedSums
{
  ColourSums colours, vivid;

  /** Add a colour pair; vivid if either pixel's saturation() reaches `vivid_saturation`. */
  void
  addColours (const Chromaticity& a, const Chromaticity& b, double vivid_saturation)
  {
    if (!std::isfinite (a[0]) || !std::isfinite (b[0]))
      return;
    colours.add (a, b);
    if (std::max (saturation (a), saturation (b)) >= vivid_saturation)
      vivid.add (a, b);
  }

  /** True if both sides vary by more than `grey_levels` (standard deviation; one by
    * default): below that, a uniform surface (or a frame without colour) cannot tell one pose
    * from another.
    */
  bool
  contrasted (double grey_levels = 1.0) const
  {
    const double least = n * grey_levels * grey_levels;
    return n >= 2.0 && sxx - sx * sx / n > least && syy - sy * sy / n > least;
  }

  /** Normalized cross-correlation; 0 without contrast. */
  double
  correlation () const
  {
    if (!contrasted())
      return 0.0;
    const double vx = sxx - sx * sx / n, vy = syy - sy * sy / n,
                 cxy = sxy - sx * sy / n;
    return cxy / std::sqrt (vx * vy);
  }
};

/** How the surface around keypoints is paired with where a motion takes it. */
struct PairSettings
{
  float radius;
  float tolerance;
  double vivid_saturation;
  double min_neighbourhood_correlation;
};

/** The grey-level pairs of the surface around `keypoints` moved by `motion`, and how many
  * keypoint neighbourhoods could tell on their own and disagree (see
  * PhotometricVerification).
  */
struct MovedSurface
{
  GreyPairs pairs;
  std::size_t neighbourhoods = 0;
  std::size_t disagreeing = 0;

  /** Count one keypoint's own pairs as a neighbourhood if they can tell. */
  void
  judge (const GreyPairs& own, double min_correlation)
  {
    if (own.n < kNeighbourhoodPairs || !own.contrasted (kNeighbourhoodContrast))
      return;
    ++neighbourhoods;
    if (own.correlation() < min_correlation)
      ++disagreeing;
  }
};

MovedSurface
movedSurfacePairs (const KeypointSurface& surface,
                   const FramePinhole& pinhole,
                   const pcl::Indices& keypoints,
                   const Eigen::Matrix4f& motion,
                   const PairSettings& settings)
{
  const float radius = settings.radius, tolerance = settings.tolerance;
  const pcl::PointCloud<pcl::PointXYZ>& cloud = *surface.organized;
  const std::vector<float>& grey = *surface.intensity;
  const auto width = static_cast<int> (cloud.width),
             height = static_cast<int> (cloud.height);
  const Eigen::Affine3f move (motion);
  const double focal = std::max (std::abs (pinhole.fx), std::abs (pinhole.fy));
  MovedSurface result;
  GreyPairs& pairs = result.pairs;
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
    GreyPairs own; // this keypoint's grey levels alone
    for (int dv = -reach; dv <= reach; dv += step)
      for (int du = -reach; du <= reach; du += step) {
        const int u = u0 + du, v = v0 + dv;
        if (u < 0 || v < 0 || u >= width || v >= height)
          continue;
        const std::size_t own_pixel =
            static_cast<std::size_t> (v) * cloud.width + static_cast<std::size_t> (u);
        const Eigen::Vector3f point = cloud[own_pixel].getVector3fMap();
        if (!point.allFinite() || (point - centre).norm() > radius)
          continue;
        const Eigen::Vector3f moved = move * point;
        int mu = 0, mv = 0;
        if (!pinhole.project (moved, width, height, mu, mv))
          continue;
        const std::size_t there =
            static_cast<std::size_t> (mv) * cloud.width + static_cast<std::size_t> (mu);
        const pcl::PointXYZ& seen = cloud[there];
        // The same z on the pixel's ray: the same side of the camera, also in a frame that
        // looks down -z.
        if (!pcl::isXYZFinite (seen) || std::abs (seen.z - moved.z()) > tolerance)
          continue;
        pairs.add (grey[own_pixel], grey[there]);
        own.add (grey[own_pixel], grey[there]);
        if (surface.chromaticity)
          pairs.addColours ((*surface.chromaticity)[own_pixel],
                            (*surface.chromaticity)[there],
                            settings.vivid_saturation);
      }
    result.judge (own, settings.min_neighbourhood_correlation);
  }
  return result;
}

/** True if every keypoint of the cluster's point sets is below `keypoints`. */
bool
keypointsHavePixels (const TripletCluster& cluster, std::size_t keypoints)
{
  const auto inside = [keypoints] (pcl::index_t k) {
    return k >= 0 && static_cast<std::size_t> (k) < keypoints;
  };
  return std::all_of (
             cluster.source_indices.begin(), cluster.source_indices.end(), inside) &&
         std::all_of (
             cluster.target_indices.begin(), cluster.target_indices.end(), inside);
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

std::vector<Chromaticity>
chromaticities (const pcl::PointCloud<pcl::PointXYZRGB>& frame, float min_brightness)
{
  std::vector<Chromaticity> shares;
  shares.reserve (frame.size());
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (const auto& p : frame) {
    const float r = p.r, g = p.g, sum = r + g + static_cast<float> (p.b);
    if (sum < min_brightness || !(sum > 0.0f))
      shares.push_back ({nan, nan});
    else
      shares.push_back ({r / sum, g / sum});
  }
  return shares;
}

void
PhotometricVerification::setKeypointSurface (const KeypointSurface& surface)
{
  surface_ = surface;
  has_pinhole_ = surfacePinhole (surface_, pinhole_);
}

std::string
PhotometricVerification::inputProblem() const
{
  if (!(radius_ > 0.0f) || !(depth_tolerance_ > 0.0f) ||
      !(max_chromaticity_difference_ > 0.0f) ||
      !(max_vivid_chromaticity_difference_ > 0.0f) || !(min_correlation_ >= -1.0f) ||
      !(min_correlation_ <= 1.0f))
    return "the radius (" + std::to_string (radius_) + "), depth tolerance (" +
           std::to_string (depth_tolerance_) +
           ") and largest chromaticity differences (" +
           std::to_string (max_chromaticity_difference_) + ", vivid " +
           std::to_string (max_vivid_chromaticity_difference_) +
           ") must be positive and the minimum correlation (" +
           std::to_string (min_correlation_) + ") in [-1, 1]";
  if (!(min_neighbourhood_correlation_ >= -1.0f) ||
      !(min_neighbourhood_correlation_ <= 1.0f) || !(max_disagreeing_share_ >= 0.0f) ||
      !(max_disagreeing_share_ <= 1.0f))
    return "the minimum correlation of a neighbourhood (" +
           std::to_string (min_neighbourhood_correlation_) +
           ") must be in [-1, 1] and the largest share of disagreeing neighbourhoods "
           "(" +
           std::to_string (max_disagreeing_share_) + ") in [0, 1]";
  if (!(vivid_saturation_ > 0.0f) || !(vivid_saturation_ <= 4.0f / 3.0f))
    return "the saturation of a vivid colour must be in (0, 4/3] (got " +
           std::to_string (vivid_saturation_) + ")";
  if (!isValidKeypointSurface (surface_, surface_.keypoint_pixels.size()))
    return "the keypoint surface must be an organized frame with every keypoint's "
           "pixel "
           "inside it";
  if (!surface_.intensity || surface_.intensity->size() != surface_.organized->size())
    return "the keypoint surface needs one grey level per pixel (" +
           std::to_string (surface_.intensity ? surface_.intensity->size() : 0) +
           " given for " + std::to_string (surface_.organized->size()) + " pixels)";
  if (surface_.chromaticity &&
      surface_.chromaticity->size() != surface_.organized->size())
    return "the keypoint surface's chromaticity must be one per pixel (" +
           std::to_string (surface_.chromaticity->size()) + " given for " +
           std::to_string (surface_.organized->size()) + " pixels)";
  if (!has_pinhole_)
    return surface_.pinhole
               ? "the keypoint surface's pinhole projection needs finite, "
                 "non-zero focal lengths and a finite principal point"
               : "no pinhole camera fits the organized frame (its points do not "
                 "project onto their pixels)";
  return {};
}

PhotometricVerification::Agreement
PhotometricVerification::compare (const TripletCluster& cluster) const
{
  Agreement agreement;
  if (!inputProblem().empty() ||
      !keypointsHavePixels (cluster, surface_.keypoint_pixels.size()))
    return agreement;
  const PairSettings settings{radius_,
                              depth_tolerance_,
                              static_cast<double> (vivid_saturation_),
                              static_cast<double> (min_neighbourhood_correlation_)};
  const MovedSurface moved_forward = movedSurfacePairs (
      surface_, pinhole_, cluster.source_indices, cluster.transformation, settings);
  const MovedSurface moved_backward =
      movedSurfacePairs (surface_,
                         pinhole_,
                         cluster.target_indices,
                         cluster.transformation.inverse(),
                         settings);
  const GreyPairs& forward = moved_forward.pairs;
  const GreyPairs& backward = moved_backward.pairs;
  agreement.neighbourhoods =
      moved_forward.neighbourhoods + moved_backward.neighbourhoods;
  agreement.disagreeing_neighbourhoods =
      moved_forward.disagreeing + moved_backward.disagreeing;
  // At least one pair, so that a tested mean is one.
  const auto enough = static_cast<double> (std::max<std::size_t> (min_pairs_, 1));
  agreement.correlation = std::min (forward.correlation(), backward.correlation());
  agreement.correlation_tested = forward.n >= enough && backward.n >= enough &&
                                 forward.contrasted() && backward.contrasted();
  // The mean colour of one side against the other's, over both directions: a pixel or two
  // of misregistration between colour and depth moves single pairs across print edges, not
  // the means.
  agreement.chromaticity_tested = surface_.chromaticity &&
                                  forward.colours.pairs >= enough &&
                                  backward.colours.pairs >= enough;
  if (agreement.chromaticity_tested)
    agreement.chromaticity_difference =
        meanColourDifference (forward.colours, backward.colours);
  agreement.vivid_tested = surface_.chromaticity && forward.vivid.pairs >= enough &&
                           backward.vivid.pairs >= enough;
  if (agreement.vivid_tested)
    agreement.vivid_difference = meanColourDifference (forward.vivid, backward.vivid);
  return agreement;
}

bool
PhotometricVerification::rejects (const Agreement& agreement) const
{
  return (agreement.correlation_tested &&
          agreement.correlation < static_cast<double> (min_correlation_)) ||
         (agreement.chromaticity_tested &&
          agreement.chromaticity_difference >
              static_cast<double> (max_chromaticity_difference_)) ||
         (agreement.vivid_tested &&
          agreement.vivid_difference >
              static_cast<double> (max_vivid_chromaticity_difference_)) ||
         (agreement.correlation_tested &&
          disagreesLocally (agreement, max_disagreeing_share_));
}

bool
disagreesLocally (const PhotometricVerification::Agreement& agreement, float max_share)
{
  return agreement.neighbourhoods >= kMinNeighbourhoods &&
         static_cast<double> (agreement.disagreeing_neighbourhoods) >
             static_cast<double> (max_share) *
                 static_cast<double> (agreement.neighbourhoods);
}

double
PhotometricVerification::correlation (const TripletCluster& cluster, bool& tested) const
{
  const Agreement agreement = compare (cluster);
  tested = agreement.correlation_tested;
  return agreement.correlation;
}

bool
PhotometricVerification::filter (const TripletClusters& clusters,
                                 TripletClusters& verified) const
{
  verified.clear();
  std::string problem = inputProblem();
  if (problem.empty() &&
      !std::all_of (clusters.begin(), clusters.end(), [this] (const TripletCluster& c) {
        return keypointsHavePixels (c, surface_.keypoint_pixels.size());
      }))
    problem = "a keypoint of the clusters has no pixel in the keypoint surface";
  if (!problem.empty()) {
    PCL_ERROR ("[mid::PhotometricVerification::filter] %s.\n", problem.c_str());
    return false;
  }
  for (const auto& cluster : clusters)
    if (!rejects (compare (cluster)))
      verified.push_back (cluster);
  return true;
}

} // namespace mid
