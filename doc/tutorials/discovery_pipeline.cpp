// Tutorial: the discovery pipeline as separate, visible steps (doc/tutorials/discovery_pipeline.md).
//
//   tutorial_discovery_pipeline data/sample_scene/scene.pcd

#include <mid/features/self_matcher.h>
#include <mid/features/sift_keypoint_extractor.h>
#include <mid/io/organized_cloud_io.h>
#include <mid/registration/correspondence_rejection_ppf_triplet.h>
#include <mid/registration/multi_instance_model_builder.h>
#include <mid/segmentation/transformation_space_clustering.h>

#include <pcl/point_types.h>

#include <cmath>
#include <iostream>

int
main (int argc, char** argv)
{
  if (argc != 2) {
    std::cerr << "usage: " << argv[0] << " SCENE.pcd\n";
    return 1;
  }

  // 1. One organized RGB-D frame, in metres.
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZRGBA>>();
  if (!mid::io::loadOrganizedPCD (argv[1], *cloud))
    return 1;

  // 2. SIFT keypoints with valid depth, their descriptors and surface normals.
  mid::SIFTKeypointExtractor<pcl::PointXYZRGBA> extractor;
  extractor.setInputCloud (cloud);
  extractor.setContrastThreshold (0.04);
  extractor.setNormalRadius (0.015f);
  auto keypoints = pcl::make_shared<mid::KeypointCloud>();
  auto descriptors = pcl::make_shared<mid::SIFTDescriptorCloud>();
  if (!extractor.compute (*keypoints, *descriptors))
    return 1;

  // 3. Every keypoint's most similar other keypoint: correspondences within one cloud.
  mid::SelfMatcher matcher;
  matcher.setInputKeypoints (keypoints);
  matcher.setInputDescriptors (descriptors);
  matcher.setMaxDescriptorDistance (350.0f);
  matcher.setMinKeypointDistance (0.01f);
  auto matches = pcl::make_shared<pcl::Correspondences>();
  if (!matcher.match (*matches))
    return 1;

  // 4. Matched triplets that pass the geometric tests, one rigid pose each.
  mid::CorrespondenceRejectorPPFTriplet rejector;
  rejector.setInputSource (keypoints); // source = target: one frame
  rejector.setMaxDistanceDifference (0.005f);
  rejector.setMaxAngleDifference (static_cast<float> (35.0 * M_PI / 180.0));
  rejector.setMinEdgeLength (0.010f);
  rejector.setMaxEdgeLength (0.125f);
  rejector.setMinTriangleAngle (static_cast<float> (10.0 * M_PI / 180.0));
  rejector.setMaxTripletsPerKeypoint (10);
  pcl::Correspondences remaining;
  rejector.getRemainingCorrespondences (*matches, remaining);
  auto triplets =
      std::make_shared<const mid::TripletMatches> (rejector.getTripletMatches());

  // 5. DBSCAN over the triplets' poses: each cluster is one pair of instances.
  mid::TransformationSpaceClustering clustering;
  clustering.setInputCloud (keypoints);
  clustering.setSceneCloud (keypoints);
  clustering.setInputTriplets (triplets);
  clustering.setClusterDistance (0.035f);
  clustering.setMinClusterSize (14);
  mid::TransformationSpaceClustering::Transformations poses;
  std::vector<pcl::Correspondences> groups;
  clustering.recognize (poses, groups);
  auto clusters =
      std::make_shared<const mid::TripletClusters> (clustering.getClusters());

  // 6. One model per connected group of clusters, with every instance's pose.
  mid::MultiInstanceModelBuilder builder;
  builder.setInputCloud (keypoints);
  builder.setInputDescriptors (descriptors);
  builder.setClusters (clusters);
  mid::ObjectModels models;
  if (!builder.compute (models))
    return 1;

  std::cout << "keypoints " << keypoints->size() << ", matches " << matches->size()
            << ", triplets " << triplets->size() << ", clusters " << clusters->size()
            << ", objects " << models.size() << "\n";
  const auto& image = extractor.getImageKeypoints();
  for (std::size_t m = 0; m < models.size(); ++m)
    for (std::size_t i = 0; i < models[m].instances.size(); ++i) {
      const auto& instance = models[m].instances[i];
      float u = 0.0f, v = 0.0f;
      for (const auto k : instance.keypoints) {
        u += image[static_cast<std::size_t> (k)].u;
        v += image[static_cast<std::size_t> (k)].v;
      }
      const auto n = static_cast<float> (instance.keypoints.size());
      std::cout << "object " << m << " instance " << i << " keypoints "
                << instance.keypoints.size() << " centre_pixel " << u / n << " "
                << v / n << " position "
                << instance.pose.topRightCorner<3, 1>().transpose() << "\n";
    }
  return 0;
}
