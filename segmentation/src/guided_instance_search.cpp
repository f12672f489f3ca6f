#include <mid/registration/landmark_box.h>
#include <mid/registration/rigid_transform.h>
#include <mid/registration/triplet_cluster.h>
#include <mid/segmentation/guided_instance_search.h>
#include <mid/segmentation/photometric_verification.h>

#include <Eigen/Geometry>
#include <pcl/common/point_tests.h>
#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <tuple>
#include <utility>
#include <vector>

namespace mid {

namespace {

/** Pixels along SIFT's orientation to the second point of a keypoint's local frame. */
constexpr double kOrientationStep = 4.0;

/** Cosine of the steepest view of a landmark's surface that still counts as facing the camera
  * (80 deg).
  */
constexpr float kMinFacing = 0.17f;

/** Width of a bin of the vote for the turn about the candidate's normal (10 deg). */
constexpr float kTurnBin = static_cast<float> (M_PI / 18.0);

/** At most one placed landmark in this many may float in front of the seen surface. */
constexpr std::size_t kInFrontShare = 5;

using Match = std::pair<std::size_t, std::size_t>; ///< (landmark, candidate index)

float
descriptorDistance (const SIFTDescriptor& a, const SIFTDescriptor& b)
{
  return (Eigen::Map<const Eigen::Matrix<float, 128, 1>> (a.histogram) -
          Eigen::Map<const Eigen::Matrix<float, 128, 1>> (b.histogram))
      .norm();
}

/** A keypoint's local frame (camera frame): z its normal, x SIFT's orientation carried from
  * the image onto the tangent plane through the projection; false where that direction is
  * undefined (no normal, the plane seen edge-on).
  */
bool
localFrame (const pcl::PointNormal& point,
            const ImageKeypoint& image,
            const FramePinhole& pinhole,
            Eigen::Matrix4f& frame)
{
  const Eigen::Vector3f p = point.getVector3fMap();
  Eigen::Vector3f n = point.getNormalVector3fMap();
  if (!p.allFinite() || !n.allFinite() || !(n.norm() > 0.5f) ||
      !(std::abs (p.z()) > 0.0f))
    return false;
  n.normalize();
  // OpenCV's angle: degrees; the image direction (cos, sin), with v pointing down.
  const double angle = static_cast<double> (image.angle) * M_PI / 180.0;
  const double u = pinhole.fx * p.x() / p.z() + pinhole.cx +
                   kOrientationStep * std::cos (angle),
               v = pinhole.fy * p.y() / p.z() + pinhole.cy +
                   kOrientationStep * std::sin (angle);
  const Eigen::Vector3f ray (static_cast<float> ((u - pinhole.cx) / pinhole.fx),
                             static_cast<float> ((v - pinhole.cy) / pinhole.fy),
                             1.0f);
  const float along = n.dot (ray);
  if (!(std::abs (along) > 1e-6f))
    return false;
  Eigen::Vector3f x = ray * (n.dot (p) / along) - p;
  x -= n * n.dot (x);
  if (!(x.norm() > 1e-9f))
    return false;
  x.normalize();
  frame.setIdentity();
  frame.block<3, 1> (0, 0) = x;
  frame.block<3, 1> (0, 1) = n.cross (x);
  frame.block<3, 1> (0, 2) = n;
  frame.block<3, 1> (0, 3) = p;
  return true;
}

/** One hypothesis: a keypoint of an instance, a candidate, their descriptor distance. */
struct Seed
{
  float distance;
  std::size_t instance;
  pcl::index_t source;
  std::size_t candidate; ///< index into the candidate list
};

/** What the steps of one search share: the model, the candidates and the frame. */
struct SearchFrame
{
  const ObjectModel& model;
  const pcl::PointCloud<pcl::PointXYZ>& cloud;
  const FramePinhole& pinhole;
  std::vector<Eigen::Vector3f> points; ///< per candidate
  std::vector<float> distance;         ///< landmark-major, landmarks x candidates
  std::vector<std::vector<std::size_t>>
      similar;            ///< per landmark: candidates within reach
  std::vector<bool> free; ///< per candidate

  float
  descriptorGap (std::size_t landmark, std::size_t candidate) const
  {
    return distance[landmark * points.size() + candidate];
  }

  /** The landmarks placed by `pose` that face the camera and lie on the seen surface (within
    * `tolerance` along the view); false if too many float in front of it.
    */
  bool
  placeOnSurface (const Eigen::Matrix4f& pose,
                  float tolerance,
                  std::vector<std::size_t>& on) const
  {
    on.clear();
    std::size_t in_front = 0;
    const Eigen::Affine3f move (pose);
    const auto width = static_cast<int> (cloud.width),
               height = static_cast<int> (cloud.height);
    for (std::size_t l = 0; l < model.landmarks.size(); ++l) {
      const Eigen::Vector3f q = move * model.landmarks[l].getVector3fMap();
      const Eigen::Vector3f n =
          move.linear() * model.landmarks[l].getNormalVector3fMap();
      int u = 0, v = 0;
      if (!(n.dot (-q.normalized()) > kMinFacing) ||
          !pinhole.project (q, width, height, u, v))
        continue;
      const pcl::PointXYZ& seen = cloud[static_cast<std::size_t> (v) * cloud.width +
                                        static_cast<std::size_t> (u)];
      if (!pcl::isXYZFinite (seen))
        continue;
      if (std::abs (seen.z - q.z()) <= tolerance)
        on.push_back (l);
      else if (std::abs (seen.z) > std::abs (q.z()) + tolerance)
        ++in_front;
    }
    return in_front * kInFrontShare <= on.size();
  }

  /** The turn about the seed's normal (the z axis of `seed_frame`) that brings the most
    * landmarks, placed by `pose`, onto free candidates with a similar descriptor at the same
    * distance from the seed: a one-dimensional Hough vote, as SIFT's orientation is the least
    * certain part of a pose from one match.
    */
  Eigen::Matrix4f
  voteTurn (const Eigen::Matrix4f& pose,
            const Eigen::Matrix4f& seed_frame,
            std::size_t seed,
            float max_offset,
            float max_height) const
  {
    const Eigen::Vector3f centre = seed_frame.block<3, 1> (0, 3);
    const Eigen::Matrix3f axes = seed_frame.block<3, 3> (0, 0);
    const auto bins = static_cast<int> (std::ceil (2.0 * M_PI / kTurnBin));
    std::vector<std::vector<std::size_t>> votes (static_cast<std::size_t> (bins));
    const Eigen::Affine3f move (pose);
    std::vector<float> reach (points.size());
    for (std::size_t c = 0; c < points.size(); ++c)
      reach[c] = (points[c] - centre).norm();
    for (std::size_t l = 0; l < model.landmarks.size(); ++l) {
      const Eigen::Vector3f q =
          axes.transpose() * (move * model.landmarks[l].getVector3fMap() - centre);
      if (std::hypot (q.x(), q.y()) < 2.0f * max_offset)
        continue; // too close to the axis to tell a turn
      const float from = std::atan2 (q.y(), q.x()), at = q.norm();
      for (const std::size_t c : similar[l]) {
        if (c == seed || !free[c] || std::abs (reach[c] - at) > max_offset)
          continue;
        const Eigen::Vector3f k = axes.transpose() * (points[c] - centre);
        if (std::abs (k.z() - q.z()) > max_height)
          continue;
        float turn = std::atan2 (k.y(), k.x()) - from;
        while (turn < 0.0f)
          turn += 2.0f * static_cast<float> (M_PI);
        votes[static_cast<std::size_t> (
                  std::min (bins - 1, static_cast<int> (turn / kTurnBin)))]
            .push_back (l);
      }
    }
    // The bin whose neighbourhood (itself and the two beside it) has the most landmarks.
    int best = 0;
    std::size_t best_count = 0;
    std::vector<std::size_t> seen;
    for (int b = 0; b < bins; ++b) {
      seen.clear();
      for (int d = -1; d <= 1; ++d) {
        const auto& v = votes[static_cast<std::size_t> ((b + d + bins) % bins)];
        seen.insert (seen.end(), v.begin(), v.end());
      }
      std::sort (seen.begin(), seen.end());
      const auto count = static_cast<std::size_t> (
          std::unique (seen.begin(), seen.end()) - seen.begin());
      if (count > best_count) {
        best_count = count;
        best = b;
      }
    }
    const float angle = (static_cast<float> (best) + 0.5f) * kTurnBin;
    const Eigen::Affine3f turn = Eigen::Translation3f (centre) *
                                 Eigen::AngleAxisf (angle, axes.col (2)) *
                                 Eigen::Translation3f (-centre);
    return turn.matrix() * pose;
  }

  /** Each landmark of `landmarks`, placed by `pose`, takes the free candidate within `radius`
    * with the most similar descriptor; a candidate taken twice goes to the closer descriptor.
    */
  void
  guidedMatches (const Eigen::Matrix4f& pose,
                 const std::vector<std::size_t>& landmarks,
                 float radius,
                 std::vector<Match>& matches) const
  {
    matches.clear();
    const Eigen::Affine3f move (pose);
    std::vector<float> best_of (points.size(), std::numeric_limits<float>::infinity());
    std::vector<Match> chosen;
    for (const auto l : landmarks) {
      const Eigen::Vector3f q = move * model.landmarks[l].getVector3fMap();
      std::size_t best = points.size();
      float best_gap = std::numeric_limits<float>::infinity();
      for (const std::size_t c : similar[l])
        if (free[c] && descriptorGap (l, c) < best_gap &&
            (points[c] - q).squaredNorm() <= radius * radius) {
          best = c;
          best_gap = descriptorGap (l, c);
        }
      if (best == points.size())
        continue;
      chosen.emplace_back (l, best);
      best_of[best] = std::min (best_of[best], best_gap);
    }
    for (const auto& m : chosen)
      if (descriptorGap (m.first, m.second) == best_of[m.second]) {
        matches.push_back (m);
        best_of[m.second] = -1.0f; // one landmark per candidate
      }
  }

  /** The pose that maps the matches' landmarks onto their candidates (least squares). */
  Eigen::Matrix4f
  fit (const std::vector<Match>& matches) const
  {
    Eigen::Matrix3Xf from (3, matches.size()), to (3, matches.size());
    for (std::size_t m = 0; m < matches.size(); ++m) {
      from.col (static_cast<Eigen::Index> (m)) =
          model.landmarks[matches[m].first].getVector3fMap();
      to.col (static_cast<Eigen::Index> (m)) = points[matches[m].second];
    }
    return estimateRigidTransform (from, to);
  }
};

} // namespace

void
GuidedInstanceSearch::setKeypointSurface (const KeypointSurface& surface)
{
  surface_ = surface;
  has_pinhole_ = surfacePinhole (surface_, pinhole_);
}

std::string
GuidedInstanceSearch::inputProblem (const ObjectModel& model) const
{
  if (!keypoints_ || !descriptors_)
    return "keypoints and descriptors must be set";
  const std::size_t n = keypoints_->size();
  if (descriptors_->size() != n || image_keypoints_.size() != n)
    return "the keypoints (" + std::to_string (n) + "), their descriptors (" +
           std::to_string (descriptors_->size()) + ") and image keypoints (" +
           std::to_string (image_keypoints_.size()) + ") must be as many";
  if (!isValidKeypointSurface (surface_, n) || !surface_.intensity ||
      surface_.intensity->size() != surface_.organized->size())
    return "the keypoint surface must hold an organized frame with every keypoint's "
           "pixel and one grey level per pixel";
  if (!has_pinhole_)
    return "the frame has no pinhole projection (none given, none fits)";
  if (!(seed_distance_ > 0.0f) || !(guided_distance_ > 0.0f) ||
      !(search_radius_ > 0.0f) || !(inlier_threshold_ > 0.0f) ||
      !(depth_tolerance_ > 0.0f) || !(correlation_radius_ > 0.0f) ||
      !(max_chromaticity_difference_ > 0.0f) ||
      !(max_vivid_chromaticity_difference_ > 0.0f) ||
      !(min_correlation_ >= -1.0f && min_correlation_ <= 1.0f) ||
      !(min_neighbourhood_correlation_ >= -1.0f &&
        min_neighbourhood_correlation_ <= 1.0f) ||
      !(max_disagreeing_share_ >= 0.0f && max_disagreeing_share_ <= 1.0f) ||
      min_inliers_ < 3)
    return "the distances, radii, tolerances and the chromaticity differences must be "
           "positive, the correlations in [-1, 1], the share of disagreeing "
           "neighbourhoods in [0, 1] and the minimum inliers at least 3";
  if (surface_.chromaticity &&
      surface_.chromaticity->size() != surface_.organized->size())
    return "the keypoint surface's chromaticity must be one per pixel";
  const auto isKeypoint = [n] (pcl::index_t k) {
    return k >= 0 && static_cast<std::size_t> (k) < n;
  };
  const auto isLandmark = [&model] (int l) {
    return l >= 0 && static_cast<std::size_t> (l) < model.landmarks.size();
  };
  if (!std::all_of (candidates_.begin(), candidates_.end(), isKeypoint))
    return "a candidate is not a keypoint";
  std::string descriptors = descriptorProblem (model);
  if (!descriptors.empty())
    return descriptors;
  const auto observes = [&] (const ModelInstance& instance) {
    return instance.keypoints.size() == instance.landmarks.size() &&
           std::all_of (
               instance.keypoints.begin(), instance.keypoints.end(), isKeypoint) &&
           std::all_of (
               instance.landmarks.begin(), instance.landmarks.end(), isLandmark);
  };
  if (!std::all_of (model.instances.begin(), model.instances.end(), observes) ||
      !std::all_of (
          found_instances_.begin(), found_instances_.end(), [&] (const auto& i) {
            return std::all_of (i.keypoints.begin(), i.keypoints.end(), isKeypoint);
          }))
    return "an instance observes a keypoint or landmark that does not exist";
  return {};
}

bool
GuidedInstanceSearch::search (const ObjectModel& model,
                              ModelInstances& found,
                              ModelInstances& unconfirmed) const
{
  found.clear();
  unconfirmed.clear();
  const std::string problem = inputProblem (model);
  if (!problem.empty()) {
    PCL_ERROR ("[mid::GuidedInstanceSearch::search] %s.\n", problem.c_str());
    return false;
  }
  const KeypointCloud& keypoints = *keypoints_;
  const SIFTDescriptorCloud& descriptors = *descriptors_;
  const std::size_t nc = candidates_.size(), nl = model.landmarks.size();
  if (nc < min_inliers_ || nl < min_inliers_ || model.instances.empty())
    return true;

  SearchFrame frame{model, *surface_.organized, pinhole_, {}, {}, {}, {}};
  for (const auto c : candidates_)
    frame.points.emplace_back (
        keypoints[static_cast<std::size_t> (c)].getVector3fMap());
  frame.free.assign (nc, true);
  frame.distance.assign (nl * nc, std::numeric_limits<float>::infinity());
  for (std::size_t d = 0; d < model.descriptors.size(); ++d) {
    const auto l = static_cast<std::size_t> (model.descriptor_landmarks[d]);
    for (std::size_t c = 0; c < nc; ++c) {
      float& gap = frame.distance[l * nc + c];
      gap = std::min (
          gap,
          descriptorDistance (model.descriptors[d],
                              descriptors[static_cast<std::size_t> (candidates_[c])]));
    }
  }
  frame.similar.resize (nl);
  for (std::size_t l = 0; l < nl; ++l)
    for (std::size_t c = 0; c < nc; ++c)
      if (frame.descriptorGap (l, c) <= guided_distance_)
        frame.similar[l].push_back (c);

  std::vector<Seed> seeds;
  for (std::size_t i = 0; i < model.instances.size(); ++i)
    for (const auto s : model.instances[i].keypoints)
      for (std::size_t c = 0; c < nc; ++c) {
        const float d =
            descriptorDistance (descriptors[static_cast<std::size_t> (s)],
                                descriptors[static_cast<std::size_t> (candidates_[c])]);
        if (d <= seed_distance_)
          seeds.push_back ({d, i, s, c});
      }
  std::sort (seeds.begin(), seeds.end(), [] (const Seed& a, const Seed& b) {
    return std::tie (a.distance, a.instance, a.source, a.candidate) <
           std::tie (b.distance, b.instance, b.source, b.candidate);
  });
  if (seeds.size() > max_hypotheses_)
    seeds.resize (max_hypotheses_);

  PhotometricVerification verification;
  KeypointSurface projected =
      surface_; // the projection resolved once, not fitted again
  projected.pinhole = std::make_shared<const FramePinhole> (pinhole_);
  verification.setKeypointSurface (projected);
  verification.setRadius (correlation_radius_);
  verification.setDepthTolerance (depth_tolerance_);
  verification.setMinCorrelation (min_correlation_);
  verification.setMaxChromaticityDifference (max_chromaticity_difference_);
  verification.setMaxVividChromaticityDifference (max_vivid_chromaticity_difference_);
  verification.setMinNeighbourhoodCorrelation (min_neighbourhood_correlation_);
  const LandmarkBox box = computeLandmarkBox (model);
  ModelInstances copies = found_instances_;
  std::vector<std::size_t> on;
  std::vector<Match> matches;
  for (const Seed& seed : seeds) {
    if (!frame.free[seed.candidate])
      continue;
    const ModelInstance& instance = model.instances[seed.instance];
    const auto s = static_cast<std::size_t> (seed.source),
               c = static_cast<std::size_t> (candidates_[seed.candidate]);
    Eigen::Matrix4f from, to;
    if (!localFrame (keypoints[s], image_keypoints_[s], pinhole_, from) ||
        !localFrame (keypoints[c], image_keypoints_[c], pinhole_, to))
      continue;
    // 1. The pose from the one match, its turn about the normal voted.
    Eigen::Matrix4f pose = frame.voteTurn (to * from.inverse() * instance.pose,
                                           to,
                                           seed.candidate,
                                           inlier_threshold_,
                                           search_radius_);
    // 2. On the surface; 3. guided matches, refitted at shrinking radii.
    if (!frame.placeOnSurface (pose, 2.0f * depth_tolerance_, on) ||
        on.size() < min_inliers_)
      continue;
    frame.guidedMatches (pose, on, search_radius_, matches);
    if (matches.size() < 3)
      continue;
    pose = frame.fit (matches);
    bool consistent = true;
    for (const float radius : {2.0f * inlier_threshold_, inlier_threshold_}) {
      consistent = frame.placeOnSurface (pose, depth_tolerance_, on);
      if (consistent)
        frame.guidedMatches (pose, on, radius, matches);
      consistent = consistent && matches.size() >= min_inliers_;
      if (!consistent)
        break;
      pose = frame.fit (matches);
    }
    if (!consistent)
      continue;
    ModelInstance candidate;
    candidate.pose = pose;
    const Eigen::Affine3f move (pose);
    double squared = 0.0;
    for (const auto& m : matches) {
      const float error =
          (move * model.landmarks[m.first].getVector3fMap() - frame.points[m.second])
              .norm();
      if (error > inlier_threshold_)
        continue;
      candidate.keypoints.push_back (candidates_[m.second]);
      candidate.landmarks.push_back (static_cast<int> (m.first));
      squared += static_cast<double> (error) * error;
    }
    if (candidate.keypoints.size() < min_inliers_)
      continue;
    candidate.rms_error = static_cast<float> (
        std::sqrt (squared / static_cast<double> (candidate.keypoints.size())));
    // Not on a copy found already, nor beside one as another face of it.
    if (std::any_of (copies.begin(), copies.end(), [&] (const ModelInstance& other) {
          return instancesOverlap (keypoints, candidate, other) ||
                 instancesAdjoin (keypoints, candidate, other);
        }))
      continue;
    // 4. The look of the instance's surface, moved onto the new copy, and back.
    TripletCluster link;
    link.source_indices = instance.keypoints;
    link.target_indices = candidate.keypoints;
    std::sort (link.source_indices.begin(), link.source_indices.end());
    std::sort (link.target_indices.begin(), link.target_indices.end());
    link.transformation = pose * instance.pose.inverse();
    const PhotometricVerification::Agreement agreement = verification.compare (link);
    if (!agreement.correlation_tested || verification.rejects (agreement))
      continue;
    const bool confirmed = !disagreesLocally (agreement, max_disagreeing_share_);
    // The copy's keypoints leave the candidates: those matched, and those inside the
    // model's box placed there.
    const Eigen::Affine3f to_model (pose.inverse());
    for (std::size_t k = 0; k < nc; ++k)
      if (box.valid && box.distanceTo (to_model * frame.points[k]) <= 0.0f)
        frame.free[k] = false;
    for (const auto& m : matches)
      frame.free[m.second] = false;
    copies.push_back (candidate);
    (confirmed ? found : unconfirmed).push_back (std::move (candidate));
  }
  return true;
}

bool
GuidedInstanceSearch::search (const ObjectModel& model, ModelInstances& found) const
{
  ModelInstances unconfirmed;
  return search (model, found, unconfirmed);
}

} // namespace mid
