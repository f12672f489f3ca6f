#include "compatible_match_graph.h"

#include <mid/registration/correspondence_rejection_ppf_triplet.h>
#include <mid/registration/rigid_transform.h>
#include <mid/registration/triangle_criteria.h>

#include <pcl/common/io.h>
#include <pcl/console/print.h>
#include <pcl/conversions.h>

#include <algorithm>
#include <map>
#include <numeric>

namespace mid {

namespace {

using detail::UniqueMatch;

/** The input matches without duplicates (a->b and b->a are one match in one frame), ranked by
  * descriptor distance; unique_of[i] is the unique match of input correspondence i.
  */
std::vector<UniqueMatch>
rankUniqueMatches (const pcl::Correspondences& correspondences,
                   bool unordered,
                   std::vector<std::size_t>& unique_of)
{
  std::vector<std::size_t> order (correspondences.size());
  std::iota (order.begin(), order.end(), std::size_t{0});
  std::stable_sort (
      order.begin(), order.end(), [&correspondences] (std::size_t a, std::size_t b) {
        return correspondences[a].distance < correspondences[b].distance;
      });
  std::map<std::pair<pcl::index_t, pcl::index_t>, std::size_t> seen;
  std::vector<UniqueMatch> unique;
  unique_of.assign (correspondences.size(), 0);
  for (const std::size_t i : order) {
    const auto& c = correspondences[i];
    auto key = std::make_pair (c.index_query, c.index_match);
    if (unordered && key.first > key.second)
      std::swap (key.first, key.second);
    const auto inserted = seen.emplace (key, unique.size());
    if (inserted.second)
      unique.push_back ({c.index_query, c.index_match, c.distance});
    unique_of[i] = inserted.first->second;
  }
  return unique;
}

/** P side and Q side keypoint of match m used in direction r (1 = reversed). */
std::pair<pcl::index_t, pcl::index_t>
sides (const UniqueMatch& m, std::uint32_t r)
{
  return r == 0 ? std::make_pair (m.p, m.q) : std::make_pair (m.q, m.p);
}

bool
hasUnitNormal (const pcl::PointNormal& k)
{
  return k.getVector3fMap().allFinite() && k.getNormalVector3fMap().allFinite() &&
         std::abs (k.getNormalVector3fMap().norm() - 1.0f) < 0.1f;
}

/** Copy the fields of a PCLPointCloud2 into keypoints: positions, normals, or both. */
KeypointCloud::ConstPtr
fromBlob (const pcl::PCLPointCloud2& blob,
          const KeypointCloud::ConstPtr& previous,
          bool take_normals_only)
{
  auto converted = pcl::make_shared<KeypointCloud>();
  pcl::fromPCLPointCloud2 (blob, *converted);
  const bool has_normals = pcl::getFieldIndex (blob, "normal_x") >= 0;
  if (!take_normals_only) {
    if (!has_normals && previous && previous->size() == converted->size())
      for (std::size_t i = 0; i < converted->size(); ++i)
        (*converted)[i].getNormalVector3fMap() = (*previous)[i].getNormalVector3fMap();
    return converted;
  }
  if (!has_normals || !previous || previous->size() != converted->size())
    return previous;
  auto merged = pcl::make_shared<KeypointCloud> (*previous);
  for (std::size_t i = 0; i < merged->size(); ++i)
    (*merged)[i].getNormalVector3fMap() = (*converted)[i].getNormalVector3fMap();
  return merged;
}

} // namespace

void
CorrespondenceRejectorPPFTriplet::setSourcePoints (pcl::PCLPointCloud2::ConstPtr cloud2)
{
  source_ = fromBlob (*cloud2, source_, false);
}

void
CorrespondenceRejectorPPFTriplet::setSourceNormals (
    pcl::PCLPointCloud2::ConstPtr cloud2)
{
  source_ = fromBlob (*cloud2, source_, true);
}

void
CorrespondenceRejectorPPFTriplet::setTargetPoints (pcl::PCLPointCloud2::ConstPtr cloud2)
{
  target_ = fromBlob (*cloud2, target_, false);
}

void
CorrespondenceRejectorPPFTriplet::setTargetNormals (
    pcl::PCLPointCloud2::ConstPtr cloud2)
{
  target_ = fromBlob (*cloud2, target_, true);
}

bool
CorrespondenceRejectorPPFTriplet::checkInputs (
    const pcl::Correspondences& correspondences) const
{
  const char* name =
      "[mid::CorrespondenceRejectorPPFTriplet::getRemainingCorrespondences]";
  if (!source_ || source_->empty()) {
    PCL_ERROR ("%s No source keypoints given (or the cloud is empty).\n", name);
    return false;
  }
  const KeypointCloud& target = target_ ? *target_ : *source_;
  if (target.empty()) {
    PCL_ERROR ("%s The target keypoint cloud is empty.\n", name);
    return false;
  }
  for (const auto& c : correspondences) {
    if (c.index_query < 0 ||
        static_cast<std::size_t> (c.index_query) >= source_->size() ||
        c.index_match < 0 ||
        static_cast<std::size_t> (c.index_match) >= target.size()) {
      PCL_ERROR (
          "%s Correspondence %d -> %d indexes outside the keypoints (%zu source, %zu "
          "target).\n",
          name,
          c.index_query,
          c.index_match,
          source_->size(),
          target.size());
      return false;
    }
    if (!hasUnitNormal ((*source_)[static_cast<std::size_t> (c.index_query)]) ||
        !hasUnitNormal (target[static_cast<std::size_t> (c.index_match)])) {
      PCL_ERROR (
          "%s Keypoint %d or %d has no valid position and unit normal: normals are "
          "missing.\n",
          name,
          c.index_query,
          c.index_match);
      return false;
    }
  }
  const auto pi = static_cast<float> (M_PI);
  if (!(max_distance_difference_ >= 0.0f) || !(max_angle_difference_ >= 0.0f) ||
      !(max_angle_difference_ <= pi) || !(min_edge_length_ > 0.0f) ||
      !(max_edge_length_ >= min_edge_length_) || !(min_triangle_angle_ >= 0.0f) ||
      !(min_triangle_angle_ < pi / 3.0f) || std::isnan (overlap_distance_) ||
      max_triplets_per_keypoint_ < 1 || max_triplets_ < 1) {
    PCL_ERROR (
        "%s Invalid parameter: distance difference %g (>= 0), angle difference %g (in "
        "[0, pi]), edge lengths [%g, %g] (0 < min <= max), min angle %g (in [0, "
        "pi/3)), "
        "L %d (>= 1), max triplets %zu (>= 1).\n",
        name,
        static_cast<double> (max_distance_difference_),
        static_cast<double> (max_angle_difference_),
        static_cast<double> (min_edge_length_),
        static_cast<double> (max_edge_length_),
        static_cast<double> (min_triangle_angle_),
        max_triplets_per_keypoint_,
        max_triplets_);
    return false;
  }
  return true;
}

void
CorrespondenceRejectorPPFTriplet::getRemainingCorrespondences (
    const pcl::Correspondences& original_correspondences,
    pcl::Correspondences& remaining_correspondences)
{
  remaining_correspondences.clear();
  triplets_.clear();
  if (!checkInputs (original_correspondences))
    return;

  const KeypointCloud& source = *source_;
  const KeypointCloud& target = target_ ? *target_ : *source_;
  const bool one_frame = !target_ || target_ == source_;

  std::vector<std::size_t> unique_of;
  const std::vector<UniqueMatch> matches =
      rankUniqueMatches (original_correspondences, one_frame, unique_of);
  const detail::PairCriteria criteria{max_distance_difference_,
                                      max_angle_difference_,
                                      min_edge_length_,
                                      max_edge_length_};
  const detail::CompatibleMatchGraph graph (
      matches, source_, target, criteria, one_frame);

  // How many accepted triplets each keypoint is in; in one frame both sides share the counts.
  std::vector<int> source_uses (source.size(), 0);
  std::vector<int> target_uses_storage (one_frame ? 0 : target.size(), 0);
  std::vector<int>& target_uses = one_frame ? source_uses : target_uses_storage;
  const auto free = [&] (pcl::index_t p, pcl::index_t q) {
    return source_uses[static_cast<std::size_t> (p)] < max_triplets_per_keypoint_ &&
           target_uses[static_cast<std::size_t> (q)] < max_triplets_per_keypoint_;
  };
  const auto position = [] (const KeypointCloud& cloud, pcl::index_t i) {
    return cloud[static_cast<std::size_t> (i)].getVector3fMap();
  };
  const auto normal = [] (const KeypointCloud& cloud, pcl::index_t i) {
    return cloud[static_cast<std::size_t> (i)].getNormalVector3fMap();
  };

  std::vector<bool> used (matches.size(), false);
  bool capped = false;
  for (std::size_t a = 0; a < matches.size() && !capped; ++a) {
    const auto& list = graph.successors (a);
    for (std::size_t ib = 0; ib < list.size() && !capped; ++ib) {
      if (!free (matches[a].p, matches[a].q))
        break;
      const std::size_t b = list[ib] / 2;
      const std::uint32_t rb = list[ib] % 2;
      const auto side_b = sides (matches[b], rb);
      if (!free (side_b.first, side_b.second))
        continue;
      for (std::size_t ic = ib + 1; ic < list.size() && !capped; ++ic) {
        const std::size_t c = list[ic] / 2;
        const std::uint32_t rc = list[ic] % 2;
        if (c == b ||
            !graph.hasEdge (b, static_cast<std::uint32_t> (2 * c + (rb ^ rc))))
          continue;
        const auto side_c = sides (matches[c], rc);
        if (!free (side_c.first, side_c.second) || !free (matches[a].p, matches[a].q) ||
            !free (side_b.first, side_b.second))
          continue;
        const std::array<pcl::index_t, 3> p_index{
            matches[a].p, side_b.first, side_c.first};
        const std::array<pcl::index_t, 3> q_index{
            matches[a].q, side_b.second, side_c.second};
        Triangle p, q, np, nq;
        for (int k = 0; k < 3; ++k) {
          p[k] = position (source, p_index[k]);
          q[k] = position (target, q_index[k]);
          np[k] = normal (source, p_index[k]);
          nq[k] = normal (target, q_index[k]);
        }
        if (!hasAnglesAbove (p, min_triangle_angle_) ||
            !hasAnglesAbove (q, min_triangle_angle_))
          continue;
        if (triangleSidedness (p, np) * triangleSidedness (q, nq) < 0.0f)
          continue;
        if (one_frame && overlap_distance_ >= 0.0f &&
            triangleDistance (p, q) <= overlap_distance_)
          continue;

        TripletMatch triplet;
        Eigen::Matrix3Xf from (3, 3), to (3, 3);
        for (int k = 0; k < 3; ++k) {
          triplet.correspondences[k] =
              pcl::Correspondence (p_index[k],
                                   q_index[k],
                                   k == 0   ? matches[a].distance
                                   : k == 1 ? matches[b].distance
                                            : matches[c].distance);
          from.col (k) = p[k];
          to.col (k) = q[k];
          ++source_uses[static_cast<std::size_t> (p_index[k])];
          ++target_uses[static_cast<std::size_t> (q_index[k])];
        }
        triplet.transformation = estimateRigidTransform (from, to, &triplet.rms_error);
        triplets_.push_back (triplet);
        used[a] = used[b] = used[c] = true;
        if (triplets_.size() >= max_triplets_) {
          PCL_WARN (
              "[mid::CorrespondenceRejectorPPFTriplet::getRemainingCorrespondences] "
              "Reached the cap of %zu accepted triplets; the remaining candidates are "
              "not visited.\n",
              max_triplets_);
          capped = true;
        }
      }
    }
  }

  for (std::size_t i = 0; i < original_correspondences.size(); ++i)
    if (used[unique_of[i]])
      remaining_correspondences.push_back (original_correspondences[i]);
}

} // namespace mid
