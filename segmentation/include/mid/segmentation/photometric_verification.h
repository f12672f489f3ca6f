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
  * Grey levels alone confuse two products whose prints share dark small text on a light
  * ground. Where the keypoint surface also holds each pixel's chromaticity
  * (KeypointSurface::chromaticity), the same pairs compare colours too (not in the paper):
  * the mean chromaticity of one side against that of the other (|dr| + |dg| of the red and
  * green shares) is near 0 on two copies of one print, whatever the shading, and a cluster
  * whose sides differ by more than the maximum is rejected however well its grey levels
  * correlate. Means, not pixel by pixel: on a real Kinect frame the colour lies a pixel or
  * two off the depth, which moves single pairs across the print's edges (pixel by pixel, a
  * maximum of 0.1 rejected every carton cluster of an IC-BIN juice frame and 0.2 was needed to
  * keep them; compared as means, 0.1 keeps them).
  * Pairs where either pixel is too dark to have a colour do not count; with fewer colour
  * pairs than the minimum count, the colours do not decide.
  *
  * The mean of all pairs is mostly the print's light ground, which two products of one brand
  * share with their layout and font: the synthetic benchmark's apple juice and soy milk
  * cartons (dark green and dark blue ink on white) differ by 0.03-0.06 there, and their
  * grey levels correlate up to 0.7. The vivid pairs, where either pixel's colour lies at
  * least the vivid saturation from grey (|r - 1/3| + |g - 1/3| + |b - 1/3| of its shares,
  * default 0.1), hold the inks: there the same cartons differ by 0.19-0.23 and two copies of
  * one print by 0.03 at most. A cluster whose vivid pairs (the minimum count of them each
  * way) differ by more than their own maximum (default 0.15, which keeps every instance of
  * the real frames of doc/benchmark.md, where 0.10 loses coffee cups and a marker) is
  * rejected too (not in the paper).
  *
  * The pooled correlation is mostly a print's layout: two printed sides of one carton with
  * one layout and other words pass it. Each keypoint's neighbourhood also gives a
  * correlation of its own, and a pose where too large a share of them disagree can be
  * rejected too (setMaxDisagreeingShare(); off by default).
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

  /** \brief The largest difference (|dr| + |dg|) between the mean chromaticities of a kept
    * cluster's two sides, both ways together, where the keypoint surface holds the
    * chromaticity (default 0.1; 2 or more: colours never reject, as the difference stays
    * below 2).
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

  /** \brief The largest difference (|dr| + |dg|) between the mean chromaticities of the
    * vivid pairs of a kept cluster's two sides, both ways together (default 0.15; 2 or
    * more: the vivid colours never reject).
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

  /** \brief The saturation from which a pixel's colour is vivid: |r - 1/3| + |g - 1/3| +
    * |b - 1/3| of its chromaticity (in (0, 4/3], default 0.1; white paper under warm light
    * stays below it, print inks reach 0.2-0.3).
    */
  ///@{
  void
  setVividSaturation (float saturation)
  {
    vivid_saturation_ = saturation;
  }
  float
  getVividSaturation () const
  {
    return vivid_saturation_;
  }
  ///@}

  /** \brief The smallest correlation of a keypoint's own neighbourhood that agrees (in
    * [-1, 1], default 0.3; see setMaxDisagreeingShare()).
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

  /** \brief The largest share of the keypoint neighbourhoods, both ways together, whose own
    * correlation is below the neighbourhood minimum, in a kept cluster (in [0, 1]; default 1:
    * never rejects). A neighbourhood counts where its own pairs (20 or more) vary by more than
    * 5 grey levels on both sides, and the share decides from 4 such neighbourhoods on.
    *
    * The correlation of all pairs together is mostly the print's layout: two faces of one
    * carton printed with the same band, rules and logo but other words correlate at 0.6 to
    * 0.8. Where the words lie, single neighbourhoods do not correlate, and their share tells
    * the two faces apart (not in the paper). Asked only where the correlation of all pairs was
    * tested.
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
    * keypoints (isValidKeypointSurface()), has no grey level per pixel (or a chromaticity
    * that is not one per pixel), if the frame has no projection (hasProjection()), or a
    * parameter is out of range (radius, tolerance and both chromaticity differences > 0,
    * correlations in [-1, 1], vivid saturation in (0, 4/3], share of disagreeing
    * neighbourhoods in [0, 1])
    */
  bool
  filter (const TripletClusters& clusters, TripletClusters& verified) const;

  /** \brief What the frame says about one cluster's pose (compare()). */
  struct Agreement
  {
    /** \brief The smaller of the two grey-level correlations (P onto Q and back). */
    double correlation = 0.0;
    /** \brief Both directions had the minimum number of pairs and grey levels that vary. */
    bool correlation_tested = false;
    /** \brief |dr| + |dg| between the mean chromaticities of the two sides, over the pairs
      * of both directions where both pixels have a colour.
      */
    double chromaticity_difference = 0.0;
    /** \brief The surface holds the chromaticity and both directions had the minimum number
      * of colour pairs.
      */
    bool chromaticity_tested = false;
    /** \brief The same difference over the vivid pairs only (see the class). */
    double vivid_difference = 0.0;
    /** \brief The surface holds the chromaticity and both directions had the minimum number
      * of vivid pairs.
      */
    bool vivid_tested = false;
    /** \brief The keypoint neighbourhoods, both ways, that can tell on their own (see
      * setMaxDisagreeingShare()).
      */
    std::size_t neighbourhoods = 0;
    /** \brief Of those, the ones whose own correlation is below the neighbourhood minimum. */
    std::size_t disagreeing_neighbourhoods = 0;
  };

  /** \brief Compare the surface around a cluster's point sets with the frame where its pose
    * moves them, both ways.
    * \return all untested where filter() would refuse the input
    */
  Agreement
  compare (const TripletCluster& cluster) const;

  /** \brief True if the agreement rules the pose out: a tested correlation below the
    * minimum, tested colours (all of them, or the vivid ones) that differ by more than
    * their maximum, or more disagreeing neighbourhoods than their largest share. filter()
    * keeps the clusters this does not reject.
    */
  bool
  rejects (const Agreement& agreement) const;

  /** \brief The smaller of a cluster's two correlations (P onto Q and back), and whether the
    * frame could tell: both directions had the minimum number of pairs, and grey levels that
    * vary (a uniform surface, or a frame without colour, tells nothing). For reports and
    * tests (compare() gives the colours too).
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
  float max_chromaticity_difference_ = 0.1f;
  float max_vivid_chromaticity_difference_ = 0.15f;
  float vivid_saturation_ = 0.1f;
  float min_neighbourhood_correlation_ = 0.3f;
  float max_disagreeing_share_ = 1.0f;
  std::size_t min_pairs_ = 30;
};

/** \brief True if more than `max_share` of an agreement's keypoint neighbourhoods that can
  * tell on their own disagree, from 4 such neighbourhoods on
  * (PhotometricVerification::setMaxDisagreeingShare(), which rejects() applies): the layout of
  * the print agrees, not its words. No check of its own: a NaN share never rejects.
  */
bool
disagreesLocally (const PhotometricVerification::Agreement& agreement, float max_share);

/** \brief The grey level (0.299 R + 0.587 G + 0.114 B, 0 to 255) of each point of a colour
  * frame, in its order: KeypointSurface::intensity for PhotometricVerification.
  */
std::vector<float>
greyLevels (const pcl::PointCloud<pcl::PointXYZRGB>& frame);

/** \brief The chromaticity of each point of a colour frame, in its order
  * (KeypointSurface::chromaticity): its red and green shares of r + g + b, or NaN where
  * r + g + b is below `min_brightness` (0 to 765), too dark for the shares to be more than
  * the sensor's noise.
  */
std::vector<Chromaticity>
chromaticities (const pcl::PointCloud<pcl::PointXYZRGB>& frame,
                float min_brightness = 60.0f);

} // namespace mid
