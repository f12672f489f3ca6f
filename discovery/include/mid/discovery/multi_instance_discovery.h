#pragma once

#include <mid/discovery/discovery_parameters.h>
#include <mid/discovery/discovery_result.h>

#include <pcl/pcl_base.h>

namespace mid {

/** \brief The whole method in one call: discover the objects that appear several times in one
  * organized RGB-D frame, model them, and localize every instance (Abbeloos et al., 3DV 2017).
  *
  * Runs, in order: SIFTKeypointExtractor, SelfMatcher, CorrespondenceRejectorPPFTriplet,
  * TransformationSpaceClustering, MultiInstanceModelBuilder, then ModelInstanceDetector twice:
  * each model against the others (models found to be one object are merged; also through the
  * keypoints around their instances, RegionModelMerger) and against the keypoints no model uses
  * yet (new instances extend the model). Every stage is also usable
  * on its own; this class only wires them with one DiscoveryParameters.
  *
  * \code
  * mid::MultiInstanceDiscovery<pcl::PointXYZRGBA> discovery;
  * discovery.setInputCloud (cloud);          // organized, metres
  * mid::DiscoveryResult result;
  * if (discovery.discover (result))
  *   for (const auto& model : result.models) ...   // model.instances[i].pose
  * \endcode
  *
  * Please cite: W. Abbeloos, E. Ataer-Cansizoglu, S. Caccamo, Y. Taguchi, Y. Domae, "3D Object
  * Discovery and Modeling Using Single RGB-D Images Containing Multiple Object Instances",
  * 3DV 2017.
  *
  * \tparam PointT point type with x, y, z (metres) and r, g, b; pcl::PointXYZRGB and
  * pcl::PointXYZRGBA are precompiled, others need MID_NO_PRECOMPILE (doc/building.md)
  */
template <typename PointT>
class MultiInstanceDiscovery : public pcl::PCLBase<PointT>
{
public:
  /** \brief All parameters (defaults: the paper's); discover() fails on one out of its range
    * (see validateDiscoveryParameters()).
    */
  ///@{
  void
  setParameters (const DiscoveryParameters& parameters)
  {
    parameters_ = parameters;
  }
  const DiscoveryParameters&
  getParameters () const
  {
    return parameters_;
  }
  ///@}

  /** \brief Run the pipeline on the input cloud.
    * \param[out] result keypoints, matches, counts, models with instances, timings; reset first
    * \return false (with a PCL_ERROR from the stage that refused its input) if the input or a
    * parameter is unusable; true otherwise, also when nothing repeats (no models)
    */
  bool
  discover (DiscoveryResult& result);

protected:
  using pcl::PCLBase<PointT>::input_;
  using pcl::PCLBase<PointT>::indices_;
  using pcl::PCLBase<PointT>::fake_indices_;

private:
  DiscoveryParameters parameters_;
};

} // namespace mid

#ifdef MID_NO_PRECOMPILE
#include <mid/discovery/impl/multi_instance_discovery.hpp>
#endif
