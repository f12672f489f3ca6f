#pragma once

#include <mid/features/keypoint_types.h>
#include <mid/registration/correspondence_rejection_ppf_triplet.h>
#include <mid/registration/triplet_cluster.h>
#include <mid/registration/triplet_match.h>
#include <mid/segmentation/surface_gap.h>

#include <pcl/recognition/cg/correspondence_grouping.h>

#include <memory>

namespace mid {

/** \brief Groups triplet matches by their relative pose with DBSCAN in transformation space
  * (Abbeloos et al., 3DV 2017, "Clustering"); each group is one pair of object instances.
  *
  * The distance between triplet matches (P, Q) and (A, B) is the paper's
  * D = sum_i |T_pq(a_i) - b_i| + sum_i |T_ab(p_i) - q_i| (see tripletDistance()), computed
  * exactly for every pair that the centroid lower bound (tripletDistanceLowerBound()) does not
  * already put beyond eps. A cluster needs min cluster size triplets (DBSCAN's min samples).
  * The same pair of instances may appear twice, once in each direction; such inverse clusters
  * are detected (at least half of one cluster's reversed triplets agree with the other's pose
  * within eps) and merged. Each cluster's pose is then re-estimated from all its point pairs.
  *
  * It belongs to PCL's correspondence grouping family: the model is the source keypoint cloud
  * (setInputCloud), the scene the target (setSceneCloud; the same cloud for discovery in one
  * frame), and the model-scene correspondences the keypoint matches. The triplets come either
  * from setInputTriplets(), or are made from the correspondences by the triplet rejector
  * (setTripletRejector(), default settings otherwise).
  *
  * Clusters are ordered by decreasing number of triplets (ties: smaller first triplet). The
  * result does not depend on the order of the input triplets.
  *
  * \code
  * mid::TransformationSpaceClustering clustering;
  * clustering.setInputCloud (keypoints);
  * clustering.setSceneCloud (keypoints);
  * clustering.setInputTriplets (triplets);        // from CorrespondenceRejectorPPFTriplet
  * std::vector<Eigen::Matrix4f, Eigen::aligned_allocator<Eigen::Matrix4f>> poses;
  * std::vector<pcl::Correspondences> groups;
  * clustering.recognize (poses, groups);
  * const mid::TripletClusters& clusters = clustering.getClusters ();   // with both point sets
  * \endcode
  *
  * Please cite: W. Abbeloos et al., "3D Object Discovery and Modeling Using Single RGB-D Images
  * Containing Multiple Object Instances", 3DV 2017; M. Ester et al., "A Density-Based Algorithm
  * for Discovering Clusters in Large Spatial Databases with Noise", KDD 1996.
  */
class TransformationSpaceClustering
: public pcl::CorrespondenceGrouping<pcl::PointNormal, pcl::PointNormal>
{
public:
  /** \brief Shared pointer to a clusterer. */
  using Ptr = std::shared_ptr<TransformationSpaceClustering>;
  /** \brief Shared pointer to a const clusterer. */
  using ConstPtr = std::shared_ptr<const TransformationSpaceClustering>;
  /** \brief Shared pointer to the const input triplets. */
  using TripletMatchesConstPtr = std::shared_ptr<const TripletMatches>;
  /** \brief One pose per cluster (4x4, Eigen-aligned), as PCL's recognize() returns them. */
  using Transformations =
      std::vector<Eigen::Matrix4f, Eigen::aligned_allocator<Eigen::Matrix4f>>;

  /** \brief Triplet matches to cluster (indices into the model and scene clouds). Also sets
    * the model-scene correspondences to theirs, as PCL's grouping interface requires them.
    * Clustering fails (no clusters, PCL_ERROR) if a triplet has a non-finite pose or refers to
    * a keypoint that is missing or not finite.
    */
  ///@{
  void
  setInputTriplets (const TripletMatchesConstPtr& triplets);
  const TripletMatchesConstPtr&
  getInputTriplets () const
  {
    return triplets_;
  }
  ///@}

  /** \brief Set keypoint matches; the triplets are then made from them by the rejector (the
    * triplets given with setInputTriplets() are forgotten).
    * \param[in] correspondences index_query into the model cloud, index_match into the scene
    */
  void
  setModelSceneCorrespondences (
      const pcl::CorrespondencesConstPtr& correspondences) override;

  /** \brief The rejector that turns correspondences into triplets (when no triplets are set);
    * unset means one with default settings.
    */
  ///@{
  void
  setTripletRejector (const CorrespondenceRejectorPPFTriplet::Ptr& rejector)
  {
    rejector_ = rejector;
  }
  const CorrespondenceRejectorPPFTriplet::Ptr&
  getTripletRejector () const
  {
    return rejector_;
  }
  ///@}

  /** \brief DBSCAN's eps: the largest distance D between neighbouring triplet matches (metres).
    * Default 0.035; must be > 0 (no clusters, with a PCL_ERROR, otherwise).
    */
  ///@{
  void
  setClusterDistance (float eps)
  {
    eps_ = eps;
  }
  float
  getClusterDistance () const
  {
    return eps_;
  }
  ///@}

  /** \brief DBSCAN's min samples (a core triplet has this many within eps, itself included), so
    * also the smallest cluster. Default 14; must be >= 1 (no clusters, with a PCL_ERROR,
    * otherwise).
    */
  ///@{
  void
  setMinClusterSize (std::size_t size)
  {
    min_cluster_size_ = size;
  }
  std::size_t
  getMinClusterSize () const
  {
    return min_cluster_size_;
  }
  ///@}

  /** \brief Merge clusters that are the same pair of instances in opposite directions.
    * Default true.
    */
  ///@{
  void
  setMergeInverseClusters (bool merge)
  {
    merge_inverse_ = merge;
  }
  bool
  getMergeInverseClusters () const
  {
    return merge_inverse_;
  }
  ///@}

  /** \brief Split clusters that link a regular row of copies (one relative pose between
    * neighbours) into one cluster per pair of neighbouring copies, with splitChainCluster();
    * only for triplets within one frame, only for poses that rotate less than 20 degrees.
    * Default true; false gives the paper's behaviour.
    */
  ///@{
  void
  setSplitChains (bool split)
  {
    split_chains_ = split;
  }
  bool
  getSplitChains () const
  {
    return split_chains_;
  }
  ///@}

  /** \brief Make each cluster's two point sets lie on one copy each: a cluster whose pose is a
    * half turn swapping two touching copies is oriented one way (orientHalfTurnCluster()), and
    * a cluster with a point set spanning the two copies of another cluster is split in two
    * (splitStraddlingCluster()), or removed when none of its triplets lies on one copy; given
    * the keypoint surface, a cluster whose point sets lie on objects with a gap between them
    * is split there (splitClusterAtSurfaceGaps()); only for triplets within one frame, after
    * the chains. Default true; false gives the paper's behaviour, whose models then cover two
    * touching copies.
    */
  ///@{
  void
  setSplitCompounds (bool split)
  {
    split_compounds_ = split;
  }
  bool
  getSplitCompounds () const
  {
    return split_compounds_;
  }
  ///@}

  /** \brief The organized frame behind the keypoints, and each keypoint's pixel in it: lets
    * the compound splitting orient a half turn between two copies lying apart that no third
    * copy anchors, where the surface shows the gap between them (orientHalfTurnCluster()).
    * Unset by default (only anchors orient half turns); a surface whose cloud is null counts
    * as unset, whatever its pixels. Used only when the input and scene clouds are one frame
    * (as the compound splitting is); cluster() refuses a set surface that is not organized or
    * does not give a pixel inside it for every keypoint of the input cloud.
    */
  ///@{
  void
  setKeypointSurface (const KeypointSurface& surface)
  {
    surface_ = surface;
  }
  const KeypointSurface&
  getKeypointSurface () const
  {
    return surface_;
  }
  ///@}

  /** \brief Most neighbour entries (16 bytes each) kept in memory. Within this budget each
    * pair of triplets is compared once; beyond it every region query compares again (same
    * result, about four times the work). Default 8 Mi entries (128 MiB).
    */
  ///@{
  void
  setMaxStoredNeighbors (std::size_t entries)
  {
    max_stored_neighbors_ = entries;
  }
  std::size_t
  getMaxStoredNeighbors () const
  {
    return max_stored_neighbors_;
  }
  ///@}

  /** \brief Cluster; one group of correspondences per cluster (PCL's grouping interface).
    * Hides pcl::CorrespondenceGrouping::cluster to also clear this class's results first.
    * \param[out] clustered_corrs each cluster's distinct keypoint pairs; empty (with a
    * PCL_ERROR) on bad input
    */
  void
  cluster (std::vector<pcl::Correspondences>& clustered_corrs);

  /** \brief Cluster and return one pose per cluster (mapping its set P onto its set Q) with the
    * cluster's correspondences. Both outputs are empty (with a PCL_ERROR) on bad input.
    * \param[out] transformations one pose per cluster, in the order of getClusters()
    * \param[out] clustered_corrs each cluster's distinct keypoint pairs, in the same order
    */
  void
  recognize (Transformations& transformations,
             std::vector<pcl::Correspondences>& clustered_corrs);
  /** \brief Cluster and return one pose per cluster (mapping its set P onto its set Q); empty
    * (with a PCL_ERROR) on bad input.
    * \param[out] transformations one pose per cluster, in the order of getClusters()
    */
  void
  recognize (Transformations& transformations);

  /** \brief The clusters of the last run, with poses, point sets and member triplets. */
  const TripletClusters&
  getClusters () const
  {
    return clusters_;
  }

  /** \brief The triplets of the last run (given, or made by the rejector); cluster members
    * index into these.
    */
  const TripletMatches&
  getTriplets () const
  {
    return used_triplets_;
  }

protected:
  /** \brief PCL's hook behind cluster(): makes the triplets if none are given, checks the
    * input, runs DBSCAN and merges inverse clusters (see the class description).
    * \param[out] clustered_corrs each cluster's distinct keypoint pairs; empty (with a
    * PCL_ERROR) on bad input
    */
  void
  clusterCorrespondences (std::vector<pcl::Correspondences>& clustered_corrs) override;

private:
  /** \brief Check the triplets and the parameters; prints the problem. */
  bool
  checkInputs (const TripletMatches& triplets) const;

  TripletMatchesConstPtr triplets_;
  CorrespondenceRejectorPPFTriplet::Ptr rejector_;
  float eps_ = 0.035f;
  std::size_t min_cluster_size_ = 14;
  bool merge_inverse_ = true;
  bool split_chains_ = true;
  bool split_compounds_ = true;
  KeypointSurface surface_;
  std::size_t max_stored_neighbors_ = std::size_t{8} << 20;
  TripletMatches used_triplets_;
  TripletClusters clusters_;
};

} // namespace mid
