#pragma once

#include <mid/features/keypoint_types.h>

#include <pcl/pcl_base.h>

namespace mid {

/** \brief SIFT keypoints with valid depth, their 128-D descriptors and surface normals, for one
  * organized colored cloud (an RGB-D frame).
  *
  * Keypoints are detected and described with OpenCV's SIFT on the cloud's color image. Only
  * keypoints whose pixel holds a finite 3D point, and whose neighbourhood gives a surface normal,
  * are kept. The normal is the smallest principal axis of the organized neighbourhood's points
  * within the normal radius, flipped to face the camera (origin). The output order is
  * deterministic: by decreasing detector response, then by row, column, size and angle.
  *
  * If indices are set (pcl::PCLBase::setIndices), only keypoints on those pixels are kept.
  *
  * \code
  * mid::SIFTKeypointExtractor<pcl::PointXYZRGB> extractor;
  * extractor.setInputCloud (cloud);          // organized, metres
  * mid::KeypointCloud keypoints;
  * mid::SIFTDescriptorCloud descriptors;
  * if (!extractor.compute (keypoints, descriptors)) { ... }
  * \endcode
  *
  * Please cite: W. Abbeloos, E. Ataer-Cansizoglu, S. Caccamo, Y. Taguchi, Y. Domae,
  * "3D Object Discovery and Modeling Using Single RGB-D Images Containing Multiple Object
  * Instances", 3DV 2017; and D. Lowe, "Distinctive Image Features from Scale-Invariant
  * Keypoints", IJCV 2004.
  *
  * \tparam PointT point type with x, y, z (metres) and r, g, b; pcl::PointXYZRGB and
  * pcl::PointXYZRGBA are precompiled, others need MID_NO_PRECOMPILE (doc/building.md)
  */
template <typename PointT>
class SIFTKeypointExtractor : public pcl::PCLBase<PointT>
{
public:
  /** \brief Shared pointer to an extractor. */
  using Ptr = std::shared_ptr<SIFTKeypointExtractor<PointT>>;
  /** \brief Shared pointer to a const extractor. */
  using ConstPtr = std::shared_ptr<const SIFTKeypointExtractor<PointT>>;
  /** \brief The input: an organized cloud with x, y, z (metres) and r, g, b. */
  using PointCloud = pcl::PointCloud<PointT>;

  SIFTKeypointExtractor() = default;

  /** \brief Keep at most this many keypoints (the strongest); 0 keeps all. Default 0; must be
    * >= 0 (compute() fails otherwise).
    */
  ///@{
  void
  setMaxKeypoints (int max_keypoints)
  {
    max_keypoints_ = max_keypoints;
  }
  int
  getMaxKeypoints () const
  {
    return max_keypoints_;
  }
  ///@}

  /** \brief SIFT layers per octave (OpenCV nOctaveLayers). Default 3; must be >= 1 (compute()
    * fails otherwise).
    */
  ///@{
  void
  setOctaveLayers (int octave_layers)
  {
    octave_layers_ = octave_layers;
  }
  int
  getOctaveLayers () const
  {
    return octave_layers_;
  }
  ///@}

  /** \brief SIFT contrast threshold: larger gives fewer keypoints in flat regions. Default 0.04;
    * must be > 0 (compute() fails otherwise).
    */
  ///@{
  void
  setContrastThreshold (double contrast_threshold)
  {
    contrast_threshold_ = contrast_threshold;
  }
  double
  getContrastThreshold () const
  {
    return contrast_threshold_;
  }
  ///@}

  /** \brief SIFT edge threshold: larger keeps more edge-like keypoints. Default 10; must be > 0
    * (compute() fails otherwise).
    */
  ///@{
  void
  setEdgeThreshold (double edge_threshold)
  {
    edge_threshold_ = edge_threshold;
  }
  double
  getEdgeThreshold () const
  {
    return edge_threshold_;
  }
  ///@}

  /** \brief Sigma of the Gaussian at octave 0, in pixels. Default 1.6; must be > 0 (compute()
    * fails otherwise).
    */
  ///@{
  void
  setSigma (double sigma)
  {
    sigma_ = sigma;
  }
  double
  getSigma () const
  {
    return sigma_;
  }
  ///@}

  /** \brief Radius (metres) of the neighbourhood a keypoint's normal is fitted to. Default 0.015;
    * must be > 0 (compute() fails otherwise).
    */
  ///@{
  void
  setNormalRadius (float normal_radius)
  {
    normal_radius_ = normal_radius;
  }
  float
  getNormalRadius () const
  {
    return normal_radius_;
  }
  ///@}

  /** \brief Fewest neighbours (keypoint included) a normal is fitted to; keypoints with fewer are
    * dropped. Default 8; must be >= 3 (compute() fails otherwise).
    */
  ///@{
  void
  setMinNormalNeighbors (int min_normal_neighbors)
  {
    min_normal_neighbors_ = min_normal_neighbors;
  }
  int
  getMinNormalNeighbors () const
  {
    return min_normal_neighbors_;
  }
  ///@}

  /** \brief Detect, describe and lift the keypoints of the input cloud's image.
    * \param[out] keypoints 3D keypoints with normals (unorganized, one per kept keypoint)
    * \param[out] descriptors one SIFT descriptor per keypoint, in the same order
    * \return false (outputs cleared, PCL_ERROR printed) if the input is missing, not organized,
    * or a parameter is out of range; true otherwise, also when no keypoint is found
    */
  bool
  compute (KeypointCloud& keypoints, SIFTDescriptorCloud& descriptors);

  /** \brief Where the keypoints of the last compute() lie in the image, in the output order. */
  const ImageKeypoints&
  getImageKeypoints () const
  {
    return image_keypoints_;
  }

protected:
  using pcl::PCLBase<PointT>::input_;
  using pcl::PCLBase<PointT>::indices_;
  using pcl::PCLBase<PointT>::fake_indices_;
  using pcl::PCLBase<PointT>::initCompute;
  using pcl::PCLBase<PointT>::deinitCompute;

private:
  /** \brief Check input and parameters; prints the problem and returns false if unusable. */
  bool
  checkInputs () const;

  /** \brief Fit the normal at pixel (u, v); false if too few valid neighbours. */
  bool
  estimateNormal (int u, int v, pcl::PointNormal& keypoint) const;

  int max_keypoints_ = 0;
  int octave_layers_ = 3;
  double contrast_threshold_ = 0.04;
  double edge_threshold_ = 10.0;
  double sigma_ = 1.6;
  float normal_radius_ = 0.015f;
  int min_normal_neighbors_ = 8;
  ImageKeypoints image_keypoints_;
};

} // namespace mid

#ifdef MID_NO_PRECOMPILE
#include <mid/features/impl/sift_keypoint_extractor.hpp>
#endif
