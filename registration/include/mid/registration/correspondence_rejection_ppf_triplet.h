#pragma once

#include <mid/features/keypoint_types.h>
#include <mid/registration/triplet_match.h>

#include <pcl/registration/correspondence_rejection.h>

#include <cmath>
#include <cstddef>

namespace mid {

/** \brief Keeps the keypoint matches that form geometrically consistent matched triplets, and
  * gives each triplet the rigid pose that maps one triangle onto the other (Abbeloos et al.,
  * 3DV 2017, "Matching Triplets of Keypoints").
  *
  * Input: oriented keypoints (position + normal) and matches between them. For discovery in one
  * frame, source and target are the same cloud (set only the source) and the matches are the
  * frame's self-matches; a match a->b may then also be used as b->a. A triplet of matches gives
  * two triangles P (query side) and Q (match side); it is accepted when
  *  - every pair of its matches passes the point pair feature test: |F(p_a, p_b) - F(q_a, q_b)|
  *    within the distance and angle thresholds (applied to pairs first: triplets are only built
  *    from the graph of compatible pairs, never by enumerating all 4 C(M,3) candidates);
  *  - both triangles have all edges within [min, max] edge length and all angles above the
  *    minimum angle;
  *  - sidedness: P and Q wind the same way relative to their surface normals (a mirror image
  *    is rejected), see triangleSidedness();
  *  - (same cloud only) the triangles do not overlap: they share no keypoint and their smallest
  *    3D distance (0 when they intersect) exceeds the overlap distance;
  *  - each of its six keypoints is in fewer than L accepted triplets so far.
  * Of the 8 orientations of three matches, the 4 that are not the same triangle pair swapped are
  * tried (the first match in its given direction). Candidates are visited in a fixed order: the
  * matches ranked by descriptor distance (smallest first, ties by index), triplets in
  * lexicographic order of their ranks; so the keypoint budget L goes to the best matches, and the
  * output is identical for identical input.
  *
  * getRemainingCorrespondences() returns the input matches used by at least one accepted triplet
  * (in input order); getTripletMatches() the accepted triplets with their poses.
  *
  * \code
  * mid::CorrespondenceRejectorPPFTriplet rejector;
  * rejector.setInputSource (keypoints);               // mid::KeypointCloud, xyz + normals
  * pcl::Correspondences remaining;
  * rejector.getRemainingCorrespondences (self_matches, remaining);
  * const mid::TripletMatches& triplets = rejector.getTripletMatches ();
  * \endcode
  *
  * Please cite: W. Abbeloos, E. Ataer-Cansizoglu, S. Caccamo, Y. Taguchi, Y. Domae, "3D Object
  * Discovery and Modeling Using Single RGB-D Images Containing Multiple Object Instances",
  * 3DV 2017.
  */
class CorrespondenceRejectorPPFTriplet
: public pcl::registration::CorrespondenceRejector
{
public:
  /** \brief Shared pointer to a rejector. */
  using Ptr = std::shared_ptr<CorrespondenceRejectorPPFTriplet>;
  /** \brief Shared pointer to a const rejector. */
  using ConstPtr = std::shared_ptr<const CorrespondenceRejectorPPFTriplet>;

  CorrespondenceRejectorPPFTriplet()
  {
    rejection_name_ = "CorrespondenceRejectorPPFTriplet";
  }

  /** \brief Filter the matches; see the class description.
    * \param[in] original_correspondences the matches (index_query into the source keypoints,
    * index_match into the target keypoints, distance = descriptor distance)
    * \param[out] remaining_correspondences the matches used by an accepted triplet; empty (with
    * a PCL_ERROR) if the input is unusable or a parameter is out of its range
    */
  void
  getRemainingCorrespondences (
      const pcl::Correspondences& original_correspondences,
      pcl::Correspondences& remaining_correspondences) override;

  /** \brief The accepted triplets of the last call, with one rigid pose each. */
  const TripletMatches&
  getTripletMatches () const
  {
    return triplets_;
  }

  /** \brief Source keypoints: positions (metres) and unit normals. Required: without them, or
    * with a keypoint that a match uses lacking a finite position and unit normal,
    * getRemainingCorrespondences() gives no matches.
    */
  ///@{
  void
  setInputSource (const KeypointCloud::ConstPtr& source)
  {
    source_ = source;
  }
  const KeypointCloud::ConstPtr&
  getInputSource () const
  {
    return source_;
  }
  ///@}

  /** \brief Target keypoints; leave unset (or set the same cloud) for matches inside one frame,
    * which also enables match reversal and the overlap test.
    */
  ///@{
  void
  setInputTarget (const KeypointCloud::ConstPtr& target)
  {
    target_ = target;
  }
  const KeypointCloud::ConstPtr&
  getInputTarget () const
  {
    return target_;
  }
  ///@}

  /** \brief PCL registration hook: true, the source positions are needed. Through the hooks,
    * points and normals arrive as PCLPointCloud2 (fields x, y, z, normal_x, normal_y,
    * normal_z), e.g. from pcl::IterativeClosestPoint.
    */
  bool
  requiresSourcePoints () const override
  {
    return true;
  }
  /** \brief PCL registration hook: set the source keypoints from a PCLPointCloud2.
    * \param[in] cloud2 fields x, y, z (metres), and the normals if it has them; without them,
    * the normals of the previous source are kept if it has the same size
    */
  void
  setSourcePoints (pcl::PCLPointCloud2::ConstPtr cloud2) override;
  /** \brief PCL registration hook: true, the source normals are needed. */
  bool
  requiresSourceNormals () const override
  {
    return true;
  }
  /** \brief PCL registration hook: set the normals of the source keypoints already given.
    * \param[in] cloud2 fields normal_x, normal_y, normal_z (unit length); ignored if it has no
    * normals or its size differs from the source's
    */
  void
  setSourceNormals (pcl::PCLPointCloud2::ConstPtr cloud2) override;
  /** \brief PCL registration hook: true, the target positions are needed. */
  bool
  requiresTargetPoints () const override
  {
    return true;
  }
  /** \brief PCL registration hook: set the target keypoints from a PCLPointCloud2.
    * \param[in] cloud2 fields x, y, z (metres), and the normals if it has them; without them,
    * the normals of the previous target are kept if it has the same size
    */
  void
  setTargetPoints (pcl::PCLPointCloud2::ConstPtr cloud2) override;
  /** \brief PCL registration hook: true, the target normals are needed. */
  bool
  requiresTargetNormals () const override
  {
    return true;
  }
  /** \brief PCL registration hook: set the normals of the target keypoints already given.
    * \param[in] cloud2 fields normal_x, normal_y, normal_z (unit length); ignored if it has no
    * normals or its size differs from the target's
    */
  void
  setTargetNormals (pcl::PCLPointCloud2::ConstPtr cloud2) override;

  /** \brief Largest | |p_a - p_b| - |q_a - q_b| | of two compatible matches (metres). Default
    * 0.005; must be >= 0.
    */
  ///@{
  void
  setMaxDistanceDifference (float value)
  {
    max_distance_difference_ = value;
  }
  float
  getMaxDistanceDifference () const
  {
    return max_distance_difference_;
  }
  ///@}

  /** \brief Largest difference of each point pair feature angle (radians). Default 35 deg; must
    * be in [0, pi].
    */
  ///@{
  void
  setMaxAngleDifference (float value)
  {
    max_angle_difference_ = value;
  }
  float
  getMaxAngleDifference () const
  {
    return max_angle_difference_;
  }
  ///@}

  /** \brief Shortest triangle edge (metres). Default 0.010; must be > 0. */
  ///@{
  void
  setMinEdgeLength (float value)
  {
    min_edge_length_ = value;
  }
  float
  getMinEdgeLength () const
  {
    return min_edge_length_;
  }
  ///@}

  /** \brief Longest triangle edge (metres). Default 0.125; must be >= the shortest. */
  ///@{
  void
  setMaxEdgeLength (float value)
  {
    max_edge_length_ = value;
  }
  float
  getMaxEdgeLength () const
  {
    return max_edge_length_;
  }
  ///@}

  /** \brief Every triangle angle must exceed this (radians). Default 10 deg; must be in
    * [0, pi/3).
    */
  ///@{
  void
  setMinTriangleAngle (float value)
  {
    min_triangle_angle_ = value;
  }
  float
  getMinTriangleAngle () const
  {
    return min_triangle_angle_;
  }
  ///@}

  /** \brief Triangles closer than this (metres) overlap; 0 rejects only touching or
    * intersecting ones. Negative disables the test (e.g. for organized rows of objects).
    * Default 0.005; must not be NaN.
    */
  ///@{
  void
  setOverlapDistance (float value)
  {
    overlap_distance_ = value;
  }
  float
  getOverlapDistance () const
  {
    return overlap_distance_;
  }
  ///@}

  /** \brief L: the most accepted triplets one keypoint may take part in. Default 10; must be
    * >= 1.
    */
  ///@{
  void
  setMaxTripletsPerKeypoint (int value)
  {
    max_triplets_per_keypoint_ = value;
  }
  int
  getMaxTripletsPerKeypoint () const
  {
    return max_triplets_per_keypoint_;
  }
  ///@}

  /** \brief Hard cap on accepted triplets, which bounds memory; reaching it prints a warning.
    * Default 200000; must be >= 1.
    */
  ///@{
  void
  setMaxTriplets (std::size_t value)
  {
    max_triplets_ = value;
  }
  std::size_t
  getMaxTriplets () const
  {
    return max_triplets_;
  }
  ///@}

protected:
  /** \brief PCL's hook behind CorrespondenceRejector::getCorrespondences(): runs
    * getRemainingCorrespondences() on the input correspondences.
    * \param[out] correspondences the matches used by an accepted triplet
    */
  void
  applyRejection (pcl::Correspondences& correspondences) override
  {
    getRemainingCorrespondences (*input_correspondences_, correspondences);
  }

private:
  /** \brief Check clouds, normals, indices and parameters; prints the problem. */
  bool
  checkInputs (const pcl::Correspondences& correspondences) const;

  KeypointCloud::ConstPtr source_;
  KeypointCloud::ConstPtr target_;
  TripletMatches triplets_;
  float max_distance_difference_ = 0.005f;
  float max_angle_difference_ = static_cast<float> (35.0 * M_PI / 180.0);
  float min_edge_length_ = 0.010f;
  float max_edge_length_ = 0.125f;
  float min_triangle_angle_ = static_cast<float> (10.0 * M_PI / 180.0);
  float overlap_distance_ = 0.005f;
  int max_triplets_per_keypoint_ = 10;
  std::size_t max_triplets_ = 200000;
};

} // namespace mid
