#pragma once

#include <mid/features/keypoint_types.h>

#include <pcl/correspondence.h>

#include <memory>

namespace mid {

/** \brief Matches the keypoints of ONE frame against each other: for every keypoint, its most
  * similar OTHER keypoint by Euclidean descriptor distance (Abbeloos et al., 3DV 2017, Sec. 3.1).
  *
  * The search is exact (brute force over all pairs, in blocks of rows so memory stays bounded)
  * and deterministic. A candidate is skipped if it lies closer than the minimum 3D distance to
  * the query keypoint: SIFT often reports one location at several orientations, and such a
  * keypoint would otherwise match itself. A match is kept if its descriptor distance is at most
  * the maximum descriptor distance, and, when enabled, if it passes the ratio test and the mutual
  * check.
  *
  * The output holds one correspondence per matched keypoint i: index_query = i,
  * index_match = j, distance = the L2 descriptor distance, sorted by index_query. Both i->j and
  * j->i appear when each is the other's best match.
  *
  * The ratio test (best / second best distance) is off by default: with three or more copies of
  * an object, the second-best match of a keypoint is often another correct one.
  */
class SelfMatcher
{
public:
  /** \brief Shared pointer to a matcher. */
  using Ptr = std::shared_ptr<SelfMatcher>;
  /** \brief Shared pointer to a const matcher. */
  using ConstPtr = std::shared_ptr<const SelfMatcher>;

  /** \brief The keypoints (their positions are used for the minimum 3D distance); match()
    * fails while they are not set.
    */
  ///@{
  void
  setInputKeypoints (const KeypointCloud::ConstPtr& keypoints)
  {
    keypoints_ = keypoints;
  }
  const KeypointCloud::ConstPtr&
  getInputKeypoints () const
  {
    return keypoints_;
  }
  ///@}

  /** \brief One descriptor per keypoint, in the keypoints' order (match() fails if the counts
    * differ).
    */
  ///@{
  void
  setInputDescriptors (const SIFTDescriptorCloud::ConstPtr& descriptors)
  {
    descriptors_ = descriptors;
  }
  const SIFTDescriptorCloud::ConstPtr&
  getInputDescriptors () const
  {
    return descriptors_;
  }
  ///@}

  /** \brief Largest L2 descriptor distance of a kept match (the paper's threshold that turns N
    * keypoints into M <= N matches). OpenCV's SIFT descriptors have an L2 norm of about 512.
    * Default 350; must be > 0 (match() fails otherwise).
    */
  ///@{
  void
  setMaxDescriptorDistance (float distance)
  {
    max_descriptor_distance_ = distance;
  }
  float
  getMaxDescriptorDistance () const
  {
    return max_descriptor_distance_;
  }
  ///@}

  /** \brief Candidates closer than this to the query keypoint in 3D are skipped (metres).
    * Default 0.01, the paper's minimum triangle edge; must be >= 0 (match() fails otherwise).
    */
  ///@{
  void
  setMinKeypointDistance (float distance)
  {
    min_keypoint_distance_ = distance;
  }
  float
  getMinKeypointDistance () const
  {
    return min_keypoint_distance_;
  }
  ///@}

  /** \brief Lowe's ratio test: keep a match only if best < ratio * second best. A ratio of 1
    * disables the test. Default 1; must be in (0, 1] (match() fails otherwise).
    */
  ///@{
  void
  setMaxDistanceRatio (float ratio)
  {
    max_distance_ratio_ = ratio;
  }
  float
  getMaxDistanceRatio () const
  {
    return max_distance_ratio_;
  }
  ///@}

  /** \brief Keep i->j only if j's best match is i. Default false. */
  ///@{
  void
  setMutualCheck (bool mutual_check)
  {
    mutual_check_ = mutual_check;
  }
  bool
  getMutualCheck () const
  {
    return mutual_check_;
  }
  ///@}

  /** \brief Matches kept per keypoint: its k most similar other keypoints (each within the
    * descriptor distance; the ratio test and the mutual check apply to the most similar one,
    * which decides whether the keypoint is matched at all). The most similar ones come
    * first, as with k = 1; then the further ones whose pair is not matched yet, each pair once.
    * Default 1, the paper's "most similar keypoint"; with n copies in view, a
    * keypoint has n - 1 true partners, and k > 1 gives each pair of copies more matches (not
    * in the paper). Must be >= 1 (match() fails otherwise).
    */
  ///@{
  void
  setMaxMatchesPerKeypoint (int k)
  {
    max_matches_per_keypoint_ = k;
  }
  int
  getMaxMatchesPerKeypoint () const
  {
    return max_matches_per_keypoint_;
  }
  ///@}

  /** \brief Match every keypoint to its most similar other keypoint(s).
    * \param[out] matches the kept matches (see the class description)
    * \return false (matches cleared, PCL_ERROR printed) if an input is missing, the two inputs
    * differ in size, or a parameter is out of range; true otherwise
    */
  bool
  match (pcl::Correspondences& matches) const;

private:
  KeypointCloud::ConstPtr keypoints_;
  SIFTDescriptorCloud::ConstPtr descriptors_;
  float max_descriptor_distance_ = 350.0f;
  float min_keypoint_distance_ = 0.01f;
  float max_distance_ratio_ = 1.0f;
  bool mutual_check_ = false;
  int max_matches_per_keypoint_ = 1;
};

} // namespace mid
