#pragma once

#include <mid/features/keypoint_types.h>
#include <mid/registration/object_model.h>
#include <mid/registration/triplet_cluster.h>

#include <pcl/pcl_base.h>

#include <memory>

namespace mid {

/** \brief Builds object models and their instances from clusters of triplet matches (Abbeloos
  * et al., 3DV 2017, "Initial Model Creation").
  *
  * Each cluster holds two point sets (keypoints on two instances) and the rigid motion between
  * them. The sets become the nodes of a graph: a cluster joins its two sets with an edge weighted
  * by its alignment error (rms), and two sets that share keypoints (so lie on one instance) are
  * joined with the small weight delta and the identity. Every connected component is one object:
  * the set with the most matches and shared points is the reference, and every other set is
  * brought into its frame along its Dijkstra shortest path (Boost Graph). Sets joined by shared
  * keypoints form one instance; instances whose poses coincide (within the duplicate thresholds)
  * are merged. Keypoints matched to each other across instances form one landmark. Landmarks and
  * instance poses are then refined jointly (refineModel(), alternating Procrustes; the reference
  * instance fixes the frame), and the model frame is centred on the landmarks.
  *
  * \code
  * mid::MultiInstanceModelBuilder builder;
  * builder.setInputCloud (keypoints);              // the frame's keypoints (xyz + normal)
  * builder.setInputDescriptors (descriptors);
  * builder.setClusters (clusters);                 // from TransformationSpaceClustering
  * mid::ObjectModels models;
  * builder.compute (models);
  * \endcode
  *
  * Please cite: W. Abbeloos et al., "3D Object Discovery and Modeling Using Single RGB-D Images
  * Containing Multiple Object Instances", 3DV 2017.
  */
class MultiInstanceModelBuilder : public pcl::PCLBase<pcl::PointNormal>
{
public:
  /** \brief Shared pointer to a model builder. */
  using Ptr = std::shared_ptr<MultiInstanceModelBuilder>;
  /** \brief Shared pointer to a const model builder. */
  using ConstPtr = std::shared_ptr<const MultiInstanceModelBuilder>;
  /** \brief Shared pointer to the const input clusters. */
  using TripletClustersConstPtr = std::shared_ptr<const TripletClusters>;

  /** \brief One descriptor per keypoint of the input cloud (pcl::PCLBase::setInputCloud(), the
    * frame's keypoints with normals, metres). Required; compute() fails if the counts differ.
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

  /** \brief The clusters of triplet matches (indices into the input cloud). Required; compute()
    * fails if a cluster has a non-finite pose or an index outside the input cloud.
    */
  ///@{
  void
  setClusters (const TripletClustersConstPtr& clusters)
  {
    clusters_ = clusters;
  }
  const TripletClustersConstPtr&
  getClusters () const
  {
    return clusters_;
  }
  ///@}

  /** \brief The weight delta of an edge between sets that share keypoints (metres, like the rms
    * weights of the other edges). Default 1e-4; must be >= 0.
    */
  ///@{
  void
  setSharedPointWeight (double delta)
  {
    shared_point_weight_ = delta;
  }
  double
  getSharedPointWeight () const
  {
    return shared_point_weight_;
  }
  ///@}

  /** \brief Most alternations of the joint refinement; 0 skips it. Default 20; must be >= 0. */
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

  /** \brief Two instances of one object are the same if their poses differ by less than this
    * rotation (radians) and this distance at the model centre (metres). Defaults 10 deg, 0.01.
    * \param[in] angle rotation threshold in radians, >= 0
    * \param[in] distance distance threshold in metres, >= 0
    */
  void
  setDuplicateThresholds (float angle, float distance)
  {
    duplicate_angle_ = angle;
    duplicate_distance_ = distance;
  }
  /** \brief Rotation threshold of two duplicate instances (radians). Default 10 deg. */
  float
  getDuplicateAngle () const
  {
    return duplicate_angle_;
  }
  /** \brief Distance threshold of two duplicate instances (metres). Default 0.01. */
  float
  getDuplicateDistance () const
  {
    return duplicate_distance_;
  }

  /** \brief Largest disagreement of a shared-keypoint link (metres; not in the paper). Two
    * point sets that share a keypoint are taken to lie on one instance; one stray keypoint can
    * tie sets on two copies together, typically in a row of copies. The cluster edges are
    * joined first, then the shared-keypoint links from the most shared keypoints down, and a
    * link between two sets already joined is dropped when their poses put the sets' centroid
    * this far apart or farther. Copies tied by mistake lie at least a product's width apart;
    * smaller disagreements come from the clusters' own pose errors around a loop (20 to 25 mm
    * seen on the development frames). Default 0.04; must be > 0 (a huge value keeps every
    * link, the paper's behaviour).
    */
  ///@{
  void
  setLinkTolerance (float distance)
  {
    link_tolerance_ = distance;
  }
  float
  getLinkTolerance () const
  {
    return link_tolerance_;
  }
  ///@}

  /** \brief Build the models.
    * \param[out] models one per connected component, largest (most observations) first
    * \return false (models cleared, PCL_ERROR printed) on missing or inconsistent input, or a
    * parameter out of its range; true otherwise, also when no model is found
    */
  bool
  compute (ObjectModels& models);

  /** \brief Keypoints that belong to no model after the last compute(), in ascending order:
    * the candidates for additional instances.
    */
  const pcl::Indices&
  getUnusedKeypoints () const
  {
    return unused_keypoints_;
  }

private:
  /** \brief Check inputs and parameters; prints the problem. */
  bool
  checkInputs () const;

  SIFTDescriptorCloud::ConstPtr descriptors_;
  TripletClustersConstPtr clusters_;
  double shared_point_weight_ = 1e-4;
  int refinement_iterations_ = 20;
  float duplicate_angle_ = static_cast<float> (10.0 * M_PI / 180.0);
  float duplicate_distance_ = 0.01f;
  float link_tolerance_ = 0.04f;
  pcl::Indices unused_keypoints_;
};

} // namespace mid
