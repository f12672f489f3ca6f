#pragma once

#include <mid/registration/triplet_cluster.h>
#include <mid/segmentation/frame_pinhole.h>
#include <mid/segmentation/surface_gap.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstddef>
#include <string>
#include <vector>

namespace mid {

/** \brief Keeps the clusters whose pose carries the look of the surface around one point set
  * onto the other (not in the paper).
  *
  * A cluster says that its point set P, moved by its transform, lies on another copy of the
  * object as set Q. Triplets check the geometry of a few keypoints only; on shiny or periodic
  * surfaces (a bin of metal pins beside a bin of pulleys) chance matches can agree on a pose
  * that moves a pin onto a pulley. This check looks at the surface between the keypoints:
  * around each keypoint of P, the frame's points within the radius are moved by the cluster's
  * transform and projected into the frame; where the frame shows a surface at the moved
  * point's depth (within the depth tolerance: neither occluded nor missing), the grey level at
  * the point's own pixel and at its new pixel form a pair. The normalized cross-correlation of
  * those pairs is near 1 for two copies of one object (same print, same light, whatever the
  * gain) and near 0 for unrelated surfaces. The same is done from Q back to P, and a cluster is
  * kept when both correlations reach the minimum, or when the frame cannot tell: fewer pairs
  * than the minimum count either way (everything moved is occluded, say), or grey levels that
  * do not vary (a uniform surface, a frame without colour).
  *
  * The camera need not be given: unless the keypoint surface holds the projection
  * (KeypointSurface::pinhole), it is fitted to the organized frame (fitFramePinhole()).
  */
class PhotometricVerification
{
public:
  /** \brief The frame, its grey levels (KeypointSurface::intensity) and the pixel of each
    * keypoint the clusters refer to. Takes the frame's projection from
    * KeypointSurface::pinhole, or fits it here (fitFramePinhole()) when that is null.
    */
  ///@{
  void
  setKeypointSurface (const KeypointSurface& surface);
  const KeypointSurface&
  getKeypointSurface () const
  {
    return surface_;
  }
  ///@}

  /** \brief How far around a keypoint the surface is compared (metres; default 0.015). */
  ///@{
  void
  setRadius (float radius)
  {
    radius_ = radius;
  }
  float
  getRadius () const
  {
    return radius_;
  }
  ///@}

  /** \brief How far (metres, along the view) the frame's surface may lie from a moved point
    * for the pair to count (default 0.01: Kinect-class noise at 1 m).
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

  /** \brief The smallest correlation of a kept cluster, each way (default 0.4). */
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

  /** \brief Fewer pairs than this, either way, keep the cluster untested (default 30). */
  ///@{
  void
  setMinPairs (std::size_t pairs)
  {
    min_pairs_ = pairs;
  }
  std::size_t
  getMinPairs () const
  {
    return min_pairs_;
  }
  ///@}

  /** \brief Keep the clusters the frame's look confirms.
    * \param[in] clusters the clusters (their source and target keypoints index the keypoint
    * surface's keypoint pixels)
    * \param[out] verified the kept clusters, in their input order (cleared on failure)
    * \return false (with a PCL_ERROR) if the keypoint surface is not valid for the clusters'
    * keypoints (isValidKeypointSurface()), has no grey level per pixel, if the frame has no
    * projection (hasProjection()), or a parameter is out of range (radius and tolerance > 0,
    * correlation in [-1, 1])
    */
  bool
  filter (const TripletClusters& clusters, TripletClusters& verified) const;

  /** \brief The smaller of a cluster's two correlations (P onto Q and back), and whether the
    * frame could tell: both directions had the minimum number of pairs, and grey levels that
    * vary (a uniform surface, or a frame without colour, tells nothing). For reports and
    * tests; filter() decides with it.
    * \return 0, untested, where filter() would refuse the input
    */
  double
  correlation (const TripletCluster& cluster, bool& tested) const;

  /** \brief True if the keypoint surface's frame has a projection: a valid
    * KeypointSurface::pinhole, or else a pinhole camera that fits the frame
    * (fitFramePinhole()). Without one, filter() refuses. A frame that is not in its camera's
    * coordinates (moved into a robot's frame, say) has none.
    */
  bool
  hasProjection () const
  {
    return has_pinhole_;
  }

  /** \brief What is wrong with the parameters or the keypoint surface, as filter() would
    * report it; empty if nothing (for the steps that compare surfaces with this class).
    */
  std::string
  inputProblem () const;

private:
  KeypointSurface surface_;
  FramePinhole pinhole_;
  bool has_pinhole_ = false;
  float radius_ = 0.015f;
  float depth_tolerance_ = 0.01f;
  float min_correlation_ = 0.4f;
  std::size_t min_pairs_ = 30;
};

/** \brief The grey level (0.299 R + 0.587 G + 0.114 B, 0 to 255) of each point of a colour
  * frame, in its order: KeypointSurface::intensity for PhotometricVerification.
  */
std::vector<float>
greyLevels (const pcl::PointCloud<pcl::PointXYZRGB>& frame);

} // namespace mid
