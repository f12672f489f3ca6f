#pragma once

#include <mid/features/keypoint_types.h>
#include <mid/registration/object_model.h>

#include <pcl/pcl_base.h>

#include <cstdint>
#include <memory>

namespace mid {

/** \brief Finds instances of a known object model among keypoints: descriptor matching, then
  * 3-point RANSAC (Abbeloos et al., 3DV 2017, "Additional Instance Detection").
  *
  * Every candidate keypoint is matched to the model descriptor nearest to its own (within the
  * maximum descriptor distance), giving landmark -> keypoint matches. RANSAC draws one match and
  * two more whose keypoints lie within the model's diameter of the first, fits the rigid pose of
  * the three landmarks onto the three keypoints, and counts inliers: matches whose landmark lands
  * within the inlier threshold of its keypoint; a hypothesis whose inliers' keypoints lie along
  * one line (within the minimum inlier spread) does not count. The best hypothesis succeeds if
  * it has at least the minimum number of inliers and its inlier ratio exceeds the minimum, where
  * the ratio is taken over the matches whose keypoints lie within the model's reach of the
  * hypothesis (the model's diameter around its centre), so that it measures how well the model
  * explains that region of the frame rather than how many other instances the frame holds. The
  * pose is then re-estimated on the inliers (twice, recounting), the instance is recorded, its
  * keypoints are removed, and the search repeats until a hypothesis fails.
  *
  * Random draws come from std::mt19937 seeded with the seed parameter: the same input and seed
  * give the same instances.
  *
  * Please cite: W. Abbeloos, E. Ataer-Cansizoglu, S. Caccamo, Y. Taguchi, Y. Domae, "3D Object
  * Discovery and Modeling Using Single RGB-D Images Containing Multiple Object Instances",
  * 3DV 2017.
  */
class ModelInstanceDetector
{
public:
  /** \brief Shared pointer to a detector. */
  using Ptr = std::shared_ptr<ModelInstanceDetector>;
  /** \brief Shared pointer to a const detector. */
  using ConstPtr = std::shared_ptr<const ModelInstanceDetector>;

  /** \brief The model to find (landmarks, descriptors, diameter). Required; detect() fails if
    * a descriptor refers to a landmark the model does not have.
    */
  ///@{
  void
  setModel (const std::shared_ptr<const ObjectModel>& model)
  {
    model_ = model;
  }
  const std::shared_ptr<const ObjectModel>&
  getModel () const
  {
    return model_;
  }
  ///@}

  /** \brief The frame's keypoints (positions in metres, camera frame). Required. */
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
  /** \brief One descriptor per keypoint, in the keypoints' order. Required; detect() fails if
    * the counts differ.
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

  /** \brief Only these keypoints may form instances (e.g. those no model uses yet); unset means
    * all. detect() fails if an index lies outside the keypoints.
    */
  ///@{
  void
  setCandidates (const pcl::IndicesConstPtr& candidates)
  {
    candidates_ = candidates;
  }
  const pcl::IndicesConstPtr&
  getCandidates () const
  {
    return candidates_;
  }
  ///@}

  /** \brief Largest L2 descriptor distance of a landmark -> keypoint match. Default 350; must be
    * > 0.
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

  /** \brief RANSAC inlier threshold (metres). Default 0.005 (the paper); must be > 0. */
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

  /** \brief Fewest inliers of a detection. Default 5 (the paper); must be >= 3. */
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

  /** \brief The inlier ratio must exceed this. Default 0.125 (the paper); must be in [0, 1). */
  ///@{
  void
  setMinInlierRatio (float ratio)
  {
    min_inlier_ratio_ = ratio;
  }
  float
  getMinInlierRatio () const
  {
    return min_inlier_ratio_;
  }
  ///@}

  /** \brief How far (metres) the inliers' keypoints must spread off the line that fits them
    * best: the largest distance of one from that line. Default 0.0035, the 5 mm inlier
    * threshold over sqrt(2): a quarter turn about the line moves a keypoint that far off it by
    * more than the threshold; must be >= 0 (0: no test). Not in the paper: keypoints along one
    * line (a row of letters, an edge) fix no turn about it, so a hypothesis turned about the
    * line keeps them all as inliers, and a model on its side or upside down passes the inlier
    * tests. A hypothesis whose inliers spread less never counts.
    */
  ///@{
  void
  setMinInlierSpread (float spread)
  {
    min_inlier_spread_ = spread;
  }
  float
  getMinInlierSpread () const
  {
    return min_inlier_spread_;
  }
  ///@}
  /** \brief RANSAC hypotheses per detection. Default 1000; must be >= 1. */
  ///@{
  void
  setMaxIterations (int iterations)
  {
    max_iterations_ = iterations;
  }
  int
  getMaxIterations () const
  {
    return max_iterations_;
  }
  ///@}

  /** \brief Seed of the random draws. Default 0. */
  ///@{
  void
  setSeed (std::uint32_t seed)
  {
    seed_ = seed;
  }
  std::uint32_t
  getSeed () const
  {
    return seed_;
  }
  ///@}

  /** \brief Most instances to find (0 = no limit). Default 0. */
  ///@{
  void
  setMaxInstances (std::size_t count)
  {
    max_instances_ = count;
  }
  std::size_t
  getMaxInstances () const
  {
    return max_instances_;
  }
  ///@}

  /** \brief Find the model's instances.
    * \param[out] instances each with its pose (model -> camera), inlier keypoints and the
    *             landmark each observes, and rms error; in the order found
    * \return false (instances cleared, PCL_ERROR printed) on missing or inconsistent input, or
    * a parameter out of its range; true otherwise, also when no instance is found
    */
  bool
  detect (ModelInstances& instances) const;

  /** \brief Check the parameters' ranges (those detect() checks besides its input).
    * \return false (with a PCL_ERROR naming the parameters) if one is out of its range
    */
  bool
  hasValidParameters () const;

private:
  bool
  checkInputs () const;

  std::shared_ptr<const ObjectModel> model_;
  KeypointCloud::ConstPtr keypoints_;
  SIFTDescriptorCloud::ConstPtr descriptors_;
  pcl::IndicesConstPtr candidates_;
  float max_descriptor_distance_ = 350.0f;
  float inlier_threshold_ = 0.005f;
  std::size_t min_inliers_ = 5;
  float min_inlier_ratio_ = 0.125f;
  float min_inlier_spread_ = 0.0035f;
  int max_iterations_ = 1000;
  std::uint32_t seed_ = 0;
  std::size_t max_instances_ = 0;
};

} // namespace mid
