#pragma once

#include <mid/features/keypoint_types.h>
#include <mid/registration/model_instance_detector.h>
#include <mid/registration/object_model.h>
#include <mid/registration/triplet_cluster.h>

#include <cmath>
#include <cstddef>
#include <functional>
#include <memory>
#include <vector>

namespace mid {

/** \brief Merges models of one object whose instances show a common surface in the keypoints
  * around them, beyond the landmarks (not in Abbeloos et al.).
  *
  * A model holds only the keypoints that self-matching paired between its copies, so two
  * models of one product built on different faces (one pair of copies showing the front,
  * another the side) share no landmark, and the paper's model-against-model search finds
  * nothing. Yet a copy of one model often shows, next to its landmarks, some of the surface a
  * copy of the other model shows: the rest of a label around a can, a face seen at a slant. This
  * class searches for it, in one pass over the pairs of models in their order: for each pair
  * and each instance a of the first and b of the second, a's region (computeInstanceRegions():
  * what a observes, and the free keypoints within the region margin of its model's landmark box
  * and nearest to it), expressed in the first model's frame, is searched for in b's region by
  * descriptor matching and 3-point RANSAC (ModelInstanceDetector, with the RANSAC settings of
  * the detector given). The first pair of instances that succeeds gives where b's copy sits in
  * the first model's frame; the second model is merged into the first (mergeModel(); its
  * instances whose poses coincide with the first's join them), the merged model refined
  * (refineModel()), and the regions computed again. A pair of models compared before a merge
  * is not compared again.
  *
  * A merge condition, when set, is asked about each pair of copies the search pairs up, before
  * they merge: a pair it refuses does not merge the models, and the search goes on with the
  * next pair. The pipeline uses it to compare the look of the two copies' common surface
  * (PhotometricVerification, in the segmentation module): on the benchmark's development
  * frames, regions of different products whose prints share the same kind of small text
  * matched on 6 keypoints and more.
  *
  * Random draws are the detector's: the same input and seed give the same merges.
  */
class RegionModelMerger
{
public:
  /** \brief A test of one pair of copies the search paired up: `link` holds, as a cluster
    * would, the frame's keypoints of the first model's copy that the search matched (source,
    * sorted), the keypoints they matched on the second model's copy (target, sorted), the pairs
    * themselves (correspondences: index_query on the first copy, index_match on the second)
    * and the rigid transform mapping the first copy onto the second in the frame. Returns
    * true if the two may merge.
    */
  using MergeCondition = std::function<bool (const TripletCluster& link)>;

  /** \brief Shared pointer to a merger. */
  using Ptr = std::shared_ptr<RegionModelMerger>;
  /** \brief Shared pointer to a const merger. */
  using ConstPtr = std::shared_ptr<const RegionModelMerger>;

  /** \brief The frame's keypoints, which the models' instances index. Required. */
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

  /** \brief One descriptor per keypoint, in the keypoints' order. Required. */
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

  /** \brief The search between two regions: its descriptor distance, inlier threshold, minimum
    * inliers and inlier ratio, iterations and seed are used; its model, keypoints, descriptors,
    * candidates and instance count are set for each pair. Default: a default
    * ModelInstanceDetector with 6 minimum inliers (with the detection's 5, models of different
    * products whose prints share the same kind of text merged on the benchmark's development
    * frames).
    */
  ///@{
  void
  setDetector (const ModelInstanceDetector& detector)
  {
    detector_ = detector;
  }
  const ModelInstanceDetector&
  getDetector () const
  {
    return detector_;
  }
  ///@}

  /** \brief How far a region reaches beyond the landmarks' box, on every side (metres, >= 0;
    * default 20 mm).
    */
  ///@{
  void
  setRegionMargin (float margin)
  {
    margin_ = margin;
  }
  float
  getRegionMargin () const
  {
    return margin_;
  }
  ///@}

  /** \brief Instances of the two models whose poses coincide within this rotation (radians)
    * and distance (metres) once merged are one instance (defaults: 10 deg, 10 mm, as
    * DiscoveryParameters::duplicate_angle and duplicate_distance).
    */
  ///@{
  void
  setDuplicateThresholds (float max_angle, float max_distance)
  {
    max_angle_ = max_angle;
    max_distance_ = max_distance;
  }
  float
  getDuplicateAngle () const
  {
    return max_angle_;
  }
  float
  getDuplicateDistance () const
  {
    return max_distance_;
  }
  ///@}

  /** \brief Alternations of the joint refinement after each merge (>= 0; default 20). */
  ///@{
  void
  setRefinementIterations (int iterations)
  {
    refinement_iterations_ = iterations;
  }
  int
  getRefinementIterations () const
  {
    return refinement_iterations_;
  }
  ///@}

  /** \brief The test each pair of copies must pass before it merges two models (see the
    * class); empty (the default): every pair the search finds merges.
    */
  ///@{
  void
  setMergeCondition (const MergeCondition& condition)
  {
    condition_ = condition;
  }
  const MergeCondition&
  getMergeCondition () const
  {
    return condition_;
  }
  ///@}

  /** \brief How many pairs of copies the merge condition refused in the last merge(). */
  std::size_t
  getRefusedCount () const
  {
    return refused_;
  }

  /** \brief Merge the models that show a common surface around their instances.
    * \param[in,out] models the models; merged ones are removed, the others keep their order
    * \return false (with a PCL_ERROR; models unchanged) if keypoints or descriptors are
    * missing or differ in number, a parameter (of this class or of the detector) is out of its
    * range, or an instance refers to a keypoint the frame does not have
    */
  bool
  merge (ObjectModels& models);

  /** \brief How many models the last merge() merged into others (0 after a failure). */
  std::size_t
  getMergedCount () const
  {
    return merged_;
  }

private:
  /** \brief What became of a pair of models. */
  enum class PairOutcome {
    merged,
    apart,
    failed ///< the detector refused its input (its PCL_ERROR says why)
  };

  /** \brief merge() after its checks, on a copy of the models, counting the merges and the
    * pairs of copies the condition refused; false if a search failed.
    */
  bool
  mergeChecked (ObjectModels& models, std::size_t& merged, std::size_t& refused) const;

  /** \brief Try to merge models[j] into models[i], given the instances' regions; counts the
    * pairs of copies the condition refused.
    */
  PairOutcome
  mergePair (ObjectModels& models,
             const std::vector<std::vector<pcl::Indices>>& regions,
             std::size_t i,
             std::size_t j,
             std::size_t& refused) const;

  KeypointCloud::ConstPtr keypoints_;
  SIFTDescriptorCloud::ConstPtr descriptors_;
  ModelInstanceDetector detector_ = defaultDetector();
  float margin_ = 0.02f;
  float max_angle_ = static_cast<float> (10.0 * M_PI / 180.0);
  float max_distance_ = 0.01f;
  int refinement_iterations_ = 20;
  MergeCondition condition_;
  std::size_t merged_ = 0;
  std::size_t refused_ = 0;

  /** \brief A default detector with 6 minimum inliers. */
  static ModelInstanceDetector
  defaultDetector ()
  {
    ModelInstanceDetector detector;
    detector.setMinInliers (6);
    return detector;
  }
};

} // namespace mid
