#pragma once

#include <mid/features/keypoint_types.h>
#include <mid/registration/object_model.h>
#include <mid/segmentation/instance_extent.h>
#include <mid/segmentation/support_plane_measurement.h>
#include <mid/segmentation/surface_gap.h>

#include <Eigen/Core>
#include <Eigen/StdVector>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/types.h>

#include <string>
#include <vector>

namespace mid {

/** \brief Whether two box sizes (edges ascending, metres) are one size: each edge differs by
  * at most the larger of an absolute tolerance and a relative one times the longer edge.
  */
class SizeAgreement
{
public:
  /** \param[in] absolute metres, >= 0
    * \param[in] relative share of the longer of two edges, >= 0
    */
  SizeAgreement (float absolute, float relative)
  : absolute_ (absolute), relative_ (relative)
  {}

  /** \brief True if the sizes a and b agree edge by edge. */
  bool
  operator() (const Eigen::Vector3f& a, const Eigen::Vector3f& b) const;

  /** \brief True if the sizes a and b disagree on every edge: the boxes of two products, not
    * one box measured once whole and once joined with a neighbour or partly hidden (which
    * changes one or two edges, seldom the height too).
    */
  bool
  differOnEveryEdge (const Eigen::Vector3f& a, const Eigen::Vector3f& b) const;

  /** \brief True if the edges x and y (metres) agree. */
  bool
  edgesAgree (float x, float y) const;

  /** \brief The same agreement with both tolerances multiplied by `factor`. */
  SizeAgreement
  scaled (float factor) const
  {
    return {factor * absolute_, factor * relative_};
  }

private:
  float absolute_, relative_;
};

/** \brief Boxes that instances occupy on the support plane, one per instance; an instance whose
  * surface holds too few points for a box (fitInstanceBox()) has an empty surface and a zero
  * size.
  */
using InstanceExtents =
    std::vector<InstanceExtent, Eigen::aligned_allocator<InstanceExtent>>;

/** \brief The pixels of each instance's keypoints, instance after instance and model after
  * model: the seeds from which their surfaces grow (growInstanceSurfaces()).
  * \param[in] models the models; their observations must index keypoint_pixels (not checked)
  * \param[in] keypoint_pixels each keypoint's pixel (row * width + column)
  */
std::vector<pcl::Indices>
instanceSeedPixels (const ObjectModels& models, const pcl::Indices& keypoint_pixels);

/** \brief Measure the box every instance of every model occupies on the support plane: the
  * surfaces of all instances grow at once from their keypoints' pixels
  * (growInstanceSurfaces()), and a box is fitted to each (fitInstanceBox()).
  * \param[in] organized the frame (camera frame, metres; NaN where the depth is missing)
  * \param[in] plane the support plane (fitSupportPlane())
  * \param[in] keypoint_pixels each keypoint's pixel in `organized` (row * width + column)
  * \param[in] models the models; their observations must index keypoint_pixels (not checked)
  * \param[in] max_step, max_radius, plane_tolerance the growth (growInstanceSurfaces())
  * \param[out] extents one list per model, one box per instance, in order (InstanceExtents)
  * \return false (with a PCL_ERROR, extents empty) if the growth refuses the frame or a seed
  */
bool
measureInstanceBoxes (const pcl::PointCloud<pcl::PointXYZ>& organized,
                      const Eigen::Vector4f& plane,
                      const pcl::Indices& keypoint_pixels,
                      const ObjectModels& models,
                      float max_step,
                      float max_radius,
                      float plane_tolerance,
                      std::vector<InstanceExtents>& extents);

/** \brief The indices of the boxes in `extents` that have a size (a surface they were fitted
  * to), in order.
  */
std::vector<std::size_t>
measuredInstances (const InstanceExtents& extents);

/** \brief The largest group of boxes of one size: among `candidates`, the box that agrees with
  * the most of them; ties go to the box that the most agree with at twice the tolerances (two
  * copies measured whole differ by a few millimetres more than the tolerance now and then, a
  * box too small or too large, hidden in part or joined, by far more), then to the one with
  * the smaller surface (a surface is more often too large, joined with something, than too
  * small). Returns the candidates that agree with it.
  * \param[in] extents the boxes
  * \param[in] candidates indices into `extents` of the boxes to group, each with a size
  * \param[in] agree when two sizes are one
  * \param[out] representative the index (into `extents`) of the box the group agrees with;
  * unchanged when there are no candidates
  * \return the group, in the order of `candidates`; empty if there are no candidates
  */
std::vector<std::size_t>
largestSizeGroup (const InstanceExtents& extents,
                  const std::vector<std::size_t>& candidates,
                  const SizeAgreement& agree,
                  std::size_t& representative);

/** \brief Measure the box every model's copies occupy on the support plane.
  *
  * The surfaces of all instances of all models grow at once from their keypoints' pixels
  * (growInstanceSurfaces()), a box is fitted to each (fitInstanceBox()), and each model takes
  * the size that most of its measured instances agree on (largestSizeGroup(), which also says
  * how ties are broken).
  * \param[in] organized the frame (camera frame, metres; NaN where the depth is missing)
  * \param[in] plane the support plane (fitSupportPlane())
  * \param[in] keypoint_pixels each keypoint's pixel in `organized` (row * width + column)
  * \param[in] models the models; their observations must index keypoint_pixels (not checked)
  * \param[in] max_step, max_radius, plane_tolerance the growth (growInstanceSurfaces())
  * \param[in] agree when two sizes are one
  * \param[in] min_agreeing measured instances that must agree on a size (ModelSize::valid;
  * a model with no measured instance has no size, whatever this is)
  * \param[out] sizes one per model, in order
  * \return false (with a PCL_ERROR, sizes empty) if the growth refuses the frame or a seed
  */
bool
measureModelSizes (const pcl::PointCloud<pcl::PointXYZ>& organized,
                   const Eigen::Vector4f& plane,
                   const pcl::Indices& keypoint_pixels,
                   const ObjectModels& models,
                   float max_step,
                   float max_radius,
                   float plane_tolerance,
                   const SizeAgreement& agree,
                   int min_agreeing,
                   ModelSizes& sizes);

/** \brief Each model's size from its instances' boxes (measureInstanceBoxes()): the size
  * that most of its measured instances agree on (largestSizeGroup()), valid when at least
  * `min_agreeing` do.
  * \param[in] models the models
  * \param[in] extents one list per model, one box per instance, in order
  * \param[in] agree when two sizes are one
  * \param[in] min_agreeing measured instances that must agree on a size (ModelSize::valid)
  * \param[out] sizes one per model, in order
  */
void
modelSizesOfBoxes (const ObjectModels& models,
                   const std::vector<InstanceExtents>& extents,
                   const SizeAgreement& agree,
                   int min_agreeing,
                   ModelSizes& sizes);

/** \brief A box of `size` in `model` (box frame -> model frame): the model's own box when its
  * size (`own`, if valid) agrees with `size`, else the box of the first of its measured
  * instances (`extents`, one per instance) that has `size`. A copy measured whole gives the
  * size of a model whose other copies, joined with a neighbour or hidden in part, gave another.
  * \param[in] size the size looked for (edges ascending, metres)
  * \param[in] own the model's size
  * \param[in] model the model
  * \param[in] extents its instances' boxes, in order
  * \param[in] agree when two sizes are one
  * \param[out] box_in_model the box's frame in the model frame; unchanged if none
  * \return false if neither the model's size nor a box of its instances agrees with `size`
  */
bool
boxOfSize (const Eigen::Vector3f& size,
           const ModelSize& own,
           const ObjectModel& model,
           const InstanceExtents& extents,
           const SizeAgreement& agree,
           Eigen::Matrix4f& box_in_model);

/** \brief What the steps that measure the boxes of models on the support plane and compare
  * their sizes share (ModelSizeMerger, ModelSizeSplitter, ModelBoxExtender,
  * SizeInstanceSearch, ModelBoxPruning, InterpenetrationFilter, SizeDisagreementFilter): the
  * SupportPlaneMeasurement, and when two sizes agree.
  */
class ModelSizeMeasurement : public SupportPlaneMeasurement
{
public:
  /** \brief Two sizes agree when each edge differs by at most the larger of `absolute`
    * (metres, default 0.006, >= 0) and `relative` times the longer of the two edges (default
    * 0.03, >= 0).
    */
  ///@{
  void
  setSizeTolerance (float absolute, float relative)
  {
    size_tolerance_ = absolute;
    relative_size_tolerance_ = relative;
  }
  float
  getSizeTolerance () const
  {
    return size_tolerance_;
  }
  float
  getRelativeSizeTolerance () const
  {
    return relative_size_tolerance_;
  }
  ///@}

  /** \brief Measured instances that must agree on a model's size before it has one
    * (default 1, >= 1).
    */
  ///@{
  void
  setMinAgreeing (int count)
  {
    min_agreeing_ = count;
  }
  int
  getMinAgreeing () const
  {
    return min_agreeing_;
  }
  ///@}

  /** \brief Measure the box each model's copies occupy on the support plane
    * (measureModelSizes()), for a user who wants the objects' sizes: a gripper's opening, a
    * place to put an object down. The steps that derive from this class measure the same way.
    * \param[in] models the models; their observations index the input keypoints
    * \param[out] sizes one per model, in order; all invalid when the frame has no support plane
    * (none given, and none holds kMinSupportPlaneShare of the frame)
    * \return false (with a PCL_ERROR naming the problem, sizes empty) if an input or a
    * parameter is unusable
    */
  bool
  measure (const ObjectModels& models, ModelSizes& sizes) const;

protected:
  /** \brief SupportPlaneMeasurement's input problem, or what is wrong with the size
    * parameters; empty if nothing.
    */
  std::string
  measurementProblem (const ObjectModels& models) const;

  /** \brief measureModelSizes() on the support plane with the parameters above. */
  bool
  measureSizes (const ObjectModels& models,
                const Eigen::Vector4f& plane,
                ModelSizes& sizes) const;

  /** \brief measureInstanceBoxes() on the support plane with the parameters above. */
  bool
  measureBoxes (const ObjectModels& models,
                const Eigen::Vector4f& plane,
                std::vector<InstanceExtents>& extents) const;

  /** \brief When two sizes agree, by the size tolerances. */
  SizeAgreement
  agreement () const
  {
    return {size_tolerance_, relative_size_tolerance_};
  }

  float size_tolerance_ = 0.006f;         ///< see setSizeTolerance()
  float relative_size_tolerance_ = 0.03f; ///< see setSizeTolerance()
  int min_agreeing_ = 1;                  ///< see setMinAgreeing()
};

} // namespace mid
