#pragma once

#include <mid/segmentation/transformation_space_clustering.h>

#include <memory>
#include <vector>

namespace mid {
namespace test {

/** \brief Cluster triplets within one frame with TransformationSpaceClustering (at least 5
  * triplets per cluster, so that small synthetic scenes form clusters) and return the clusters.
  * \param[in] keypoints the frame's keypoints
  * \param[in] triplets the triplet matches between them
  * \param[in] split_chains TransformationSpaceClustering::setSplitChains()
  * \param[in] split_compounds TransformationSpaceClustering::setSplitCompounds()
  * \param[in] surface TransformationSpaceClustering::setKeypointSurface(), or null for none
  */
inline TripletClusters
clusterTriplets (const KeypointCloud::ConstPtr& keypoints,
                 const std::shared_ptr<const TripletMatches>& triplets,
                 bool split_chains = true,
                 bool split_compounds = true,
                 const KeypointSurface* surface = nullptr)
{
  TransformationSpaceClustering clustering;
  clustering.setInputCloud (keypoints);
  clustering.setSceneCloud (keypoints);
  clustering.setInputTriplets (triplets);
  clustering.setMinClusterSize (5);
  clustering.setSplitChains (split_chains);
  clustering.setSplitCompounds (split_compounds);
  if (surface)
    clustering.setKeypointSurface (*surface);
  std::vector<pcl::Correspondences> groups;
  clustering.cluster (groups);
  return clustering.getClusters();
}

} // namespace test
} // namespace mid
