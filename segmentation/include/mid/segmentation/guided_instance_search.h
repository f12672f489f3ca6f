#pragma once

#include <mid/features/keypoint_types.h>
#include <mid/registration/instance_overlap.h>
#include <mid/registration/object_model.h>
#include <mid/segmentation/surface_gap.h>

#include <pcl/types.h>

#include <cstddef>
#include <string>

namespace mid {

/** \brief Finds more instances of a model from a single keypoint match each, checked by the
  * depth and the grey levels of the frame (not in the paper).
  *
  * The paper's additional instance detection (ModelInstanceDetector) needs three keypoints of
  * a new copy whose most similar model descriptor lies at the right model point. On printed
  * faces seen at another angle, SIFT often ranks the right model point behind others or
  * farther than the matching threshold, while the keypoint itself is found again at the same
  * object point. This search asks for one right match only:
  *
  * 1. **A pose from one match.** A keypoint of an instance and a candidate keypoint with a
  *    similar descriptor each give a local frame: the surface normal, and SIFT's orientation
  *    carried from the image onto the tangent plane. The two frames give the rigid motion from
  *    the instance to the candidate's copy, and so the model's pose there. SIFT's orientation
  *    is off by 10 to 35 deg between two views of one point, so the turn about the normal is
  *    then voted over the whole circle (10 deg bins): each landmark votes for the turns that
  *    put it on a candidate with a similar descriptor at its distance from the seed.
  * 2. **Depth.** The model's landmarks placed by that pose must lie on the frame's surface
  *    (within the depth tolerance) where they face the camera and are seen, and none may float
  *    in front of it (free space).
  * 3. **Guided matching.** Each landmark placed on the surface takes the candidate keypoint
  *    nearest to it (within the search radius) whose descriptor is within the guided distance
  *    of one of the landmark's descriptors; the pose is refitted on those matches, and those
  *    within the inlier threshold must number at least the minimum.
  * 4. **Grey levels.** The surface around the instance's keypoints, moved by the refitted
  *    motion, must correlate with the frame there, and back, have its colours where the
  *    keypoint surface holds them (PhotometricVerification). A copy of which too many keypoint
  *    neighbourhoods disagree on their own is unconfirmed: returned apart by search() with
  *    three outputs, dropped by the other.
  *
  * Hypotheses are tried from the most similar pair of descriptors on; an accepted instance's
  * keypoints, and the candidates inside the model's box placed there, leave the candidates. A
  * new instance that overlaps or adjoins an instance found already is refused (the same
  * copy again, or another object). Deterministic: no random draws.
  */
class GuidedInstanceSearch
{
public:
  /** \brief The frame's keypoints (camera frame, metres, with normals towards the camera).
    * Required.
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

  /** \brief One descriptor per keypoint. Required. */
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

  /** \brief Where each keypoint was found in the image, for its SIFT orientation. Required,
    * one per keypoint.
    */
  ///@{
  void
  setImageKeypoints (const ImageKeypoints& image_keypoints)
  {
    image_keypoints_ = image_keypoints;
  }
  const ImageKeypoints&
  getImageKeypoints () const
  {
    return image_keypoints_;
  }
  ///@}

  /** \brief The organized frame, its grey levels and projection, and each keypoint's pixel.
    * Required: every keypoint's pixel, grey levels, and a projection (given or fitted).
    */
  void
  setKeypointSurface (const KeypointSurface& surface);

  /** \brief Only these keypoints may form new instances (those no instance uses yet).
    * Required.
    */
  ///@{
  void
  setCandidates (const pcl::Indices& candidates)
  {
    candidates_ = candidates;
  }
  const pcl::Indices&
  getCandidates () const
  {
    return candidates_;
  }
  ///@}

  /** \brief The instances found already, of every model (only their keypoints are read): a
    * new instance that overlaps one (instancesOverlap()) or adjoins one as another face of its
    * copy (instancesAdjoin()) is that copy again, or a copy of another object, and is
    * refused. Optional.
    */
  ///@{
  void
  setFoundInstances (const ModelInstances& instances)
  {
    found_instances_ = instances;
  }
  const ModelInstances&
  getFoundInstances () const
  {
    return found_instances_;
  }
  ///@}

  /** \brief Largest descriptor distance of the one match a pose comes from (default 450). */
  ///@{
  void
  setSeedDescriptorDistance (float distance)
  {
    seed_distance_ = distance;
  }
  float
  getSeedDescriptorDistance () const
  {
    return seed_distance_;
  }
  ///@}

  /** \brief Largest descriptor distance of a guided match (default 500). */
  ///@{
  void
  setGuidedDescriptorDistance (float distance)
  {
    guided_distance_ = distance;
  }
  float
  getGuidedDescriptorDistance () const
  {
    return guided_distance_;
  }
  ///@}

  /** \brief Radius around a placed landmark in which a guided match is looked for, before the
    * refit (metres, default 0.015).
    */
  ///@{
  void
  setSearchRadius (float radius)
  {
    search_radius_ = radius;
  }
  float
  getSearchRadius () const
  {
    return search_radius_;
  }
  ///@}

  /** \brief Inlier threshold of the refitted pose (metres, default 0.005). */
  ///@{
  void
  setInlierThreshold (float threshold)
  {
    inlier_threshold_ = threshold;
  }
  float
  getInlierThreshold () const
  {
    return inlier_threshold_;
  }
  ///@}

  /** \brief Fewest inliers of an instance (default 6, >= 3). */
  ///@{
  void
  setMinInliers (std::size_t count)
  {
    min_inliers_ = count;
  }
  std::size_t
  getMinInliers () const
  {
    return min_inliers_;
  }
  ///@}

  /** \brief Depth tolerance of a placed landmark and of the grey-level pairs (metres, default
    * 0.01).
    */
  ///@{
  void
  setDepthTolerance (float tolerance)
  {
    depth_tolerance_ = tolerance;
  }
  float
  getDepthTolerance () const
  {
    return depth_tolerance_;
  }
  ///@}

  /** \brief Smallest grey-level correlation, each way (default 0.6). */
  ///@{
  void
  setMinCorrelation (float correlation)
  {
    min_correlation_ = correlation;
  }
  float
  getMinCorrelation () const
  {
    return min_correlation_;
  }
  ///@}

  /** \brief Largest difference of the mean chromaticities of the compared surfaces, where
    * the keypoint surface holds the chromaticity
    * (PhotometricVerification::setMaxChromaticityDifference(); default 0.1).
    */
  ///@{
  void
  setMaxChromaticityDifference (float difference)
  {
    max_chromaticity_difference_ = difference;
  }
  float
  getMaxChromaticityDifference () const
  {
    return max_chromaticity_difference_;
  }
  ///@}

  /** \brief The same over the vivid colours alone
    * (PhotometricVerification::setMaxVividChromaticityDifference(); default 0.15; the vivid
    * saturation is the verification's default, 0.1).
    */
  ///@{
  void
  setMaxVividChromaticityDifference (float difference)
  {
    max_vivid_chromaticity_difference_ = difference;
  }
  float
  getMaxVividChromaticityDifference () const
  {
    return max_vivid_chromaticity_difference_;
  }
  ///@}

  /** \brief Smallest grey-level correlation of one keypoint's own neighbourhood that agrees
    * (in [-1, 1], default 0.3; PhotometricVerification::setMinNeighbourhoodCorrelation()).
    */
  ///@{
  void
  setMinNeighbourhoodCorrelation (float correlation)
  {
    min_neighbourhood_correlation_ = correlation;
  }
  float
  getMinNeighbourhoodCorrelation () const
  {
    return min_neighbourhood_correlation_;
  }
  ///@}

  /** \brief Largest share of the keypoint neighbourhoods that disagree (in [0, 1], default 1:
    * never rejects; PhotometricVerification::setMaxDisagreeingShare()): two printed sides of
    * one layout, told apart by their words.
    */
  ///@{
  void
  setMaxDisagreeingShare (float share)
  {
    max_disagreeing_share_ = share;
  }
  float
  getMaxDisagreeingShare () const
  {
    return max_disagreeing_share_;
  }
  ///@}

  /** \brief Radius of the grey-level comparison around each keypoint (metres, default
    * 0.015).
    */
  ///@{
  void
  setCorrelationRadius (float radius)
  {
    correlation_radius_ = radius;
  }
  float
  getCorrelationRadius () const
  {
    return correlation_radius_;
  }
  ///@}

  /** \brief Most hypotheses (seed matches, most similar first) tried per search (default
    * 500).
    */
  ///@{
  void
  setMaxHypotheses (std::size_t count)
  {
    max_hypotheses_ = count;
  }
  std::size_t
  getMaxHypotheses () const
  {
    return max_hypotheses_;
  }
  ///@}

  /** \brief Find new instances of `model` among the candidates.
    * \param[in] model the model with at least one instance on the frame's keypoints
    * \param[out] found the new instances (pose model -> camera, keypoints and the landmarks
    * they observe), cleared on failure
    * \param[out] unconfirmed the copies that pass every check but the share of disagreeing
    * neighbourhoods (setMaxDisagreeingShare()), cleared on failure: the layout of the model's
    * print with other words, another printed side of the object, so their pose rests on the
    * layout alone, right at best up to a turn of the box. Their landmarks are those their
    * keypoints matched, not what they show: a caller that keeps them gives their keypoints
    * landmarks of their own (addInstanceOfKeypoints()). Their keypoints leave the candidates
    * like those of the found instances.
    * \return false (with a PCL_ERROR) on missing or inconsistent input or a parameter out of
    * range
    */
  bool
  search (const ObjectModel& model,
          ModelInstances& found,
          ModelInstances& unconfirmed) const;

  /** \brief The same without the unconfirmed copies: those are dropped (their keypoints still
    * leave the candidates, as they are copies of something).
    */
  bool
  search (const ObjectModel& model, ModelInstances& found) const;

private:
  /** \brief What is wrong with the input or parameters for `model`; empty if nothing. */
  std::string
  inputProblem (const ObjectModel& model) const;

  KeypointCloud::ConstPtr keypoints_;
  SIFTDescriptorCloud::ConstPtr descriptors_;
  ImageKeypoints image_keypoints_;
  KeypointSurface surface_;
  FramePinhole pinhole_;
  bool has_pinhole_ = false;
  pcl::Indices candidates_;
  ModelInstances found_instances_;
  float seed_distance_ = 450.0f;
  float guided_distance_ = 500.0f;
  float search_radius_ = 0.015f;
  float inlier_threshold_ = 0.005f;
  std::size_t min_inliers_ = 6;
  float depth_tolerance_ = 0.01f;
  float min_correlation_ = 0.6f;
  float max_chromaticity_difference_ = 0.1f;
  float max_vivid_chromaticity_difference_ = 0.15f;
  float min_neighbourhood_correlation_ = 0.3f;
  float max_disagreeing_share_ = 1.0f;
  float correlation_radius_ = 0.015f;
  std::size_t max_hypotheses_ = 500;
};

} // namespace mid
