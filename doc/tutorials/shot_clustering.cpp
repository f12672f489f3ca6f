// Tutorial: our transformation-space clusterer in an ordinary PCL flow, fed with correspondences
// a user computed with PCL's own colour SHOT descriptors instead of SIFT
// (doc/tutorials/discovery_pipeline.md, second example).
//
//   tutorial_shot_clustering data/sample_scene/scene.pcd

#include <mid/features/sift_keypoint_extractor.h>
#include <mid/io/organized_cloud_io.h>
#include <mid/segmentation/transformation_space_clustering.h>

#include <pcl/common/io.h>
#include <pcl/common/point_tests.h>
#include <pcl/features/integral_image_normal.h>
#include <pcl/features/shot.h>
#include <pcl/filters/voxel_grid.h>
#include <pcl/kdtree/kdtree_flann.h>
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
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZRGBA>>();
  if (!mid::io::loadOrganizedPCD (argv[1], *cloud))
    return 1;

  // Keypoints: any PCL keypoint detector would do; here the positions of SIFT keypoints.
  mid::SIFTKeypointExtractor<pcl::PointXYZRGBA> extractor;
  extractor.setInputCloud (cloud);
  auto keypoints = pcl::make_shared<mid::KeypointCloud>();
  mid::SIFTDescriptorCloud unused;
  if (!extractor.compute (*keypoints, unused))
    return 1;

  // Normals of the whole surface, for PCL's descriptor.
  auto normals = pcl::make_shared<pcl::PointCloud<pcl::Normal>>();
  pcl::IntegralImageNormalEstimation<pcl::PointXYZRGBA, pcl::Normal> normal_estimation;
  normal_estimation.setNormalEstimationMethod (normal_estimation.AVERAGE_3D_GRADIENT);
  normal_estimation.setMaxDepthChangeFactor (0.02f);
  normal_estimation.setNormalSmoothingSize (10.0f);
  normal_estimation.setInputCloud (cloud);
  normal_estimation.compute (*normals);
  auto with_normals = pcl::make_shared<pcl::PointCloud<pcl::PointXYZRGBNormal>>();
  for (std::size_t i = 0; i < cloud->size(); ++i)
    if (pcl::isFinite ((*cloud)[i]) && pcl::isFinite ((*normals)[i])) {
      pcl::PointXYZRGBNormal p;
      p.getVector3fMap() = (*cloud)[i].getVector3fMap();
      p.rgba = (*cloud)[i].rgba;
      p.getNormalVector3fMap() = (*normals)[i].getNormalVector3fMap();
      with_normals->push_back (p);
    }
  auto surface = pcl::make_shared<pcl::PointCloud<pcl::PointXYZRGBNormal>>();
  pcl::VoxelGrid<pcl::PointXYZRGBNormal> grid;
  grid.setInputCloud (with_normals);
  grid.setLeafSize (0.003f, 0.003f, 0.003f);
  grid.filter (*surface);
  auto keypoint_points = pcl::make_shared<pcl::PointCloud<pcl::PointXYZRGBNormal>>();
  pcl::copyPointCloud (*keypoints, *keypoint_points);
  for (std::size_t k = 0; k < keypoints->size(); ++k)
    keypoint_points->at (k).rgba =
        cloud->at (extractor.getImageKeypoints()[k].pixel_index).rgba;
  // PCL's colour SHOT (shape and texture) at the keypoints.
  pcl::
      SHOTColorEstimation<pcl::PointXYZRGBNormal, pcl::PointXYZRGBNormal, pcl::SHOT1344>
          shot;
  shot.setInputCloud (keypoint_points);
  shot.setSearchSurface (surface);
  shot.setInputNormals (surface);
  shot.setRadiusSearch (0.03);
  pcl::PointCloud<pcl::SHOT1344> signatures;
  shot.compute (signatures);

  // Self-correspondences with PCL's kd-tree: each keypoint's nearest other signature that lies
  // at least 1 cm away.
  auto matches = pcl::make_shared<pcl::Correspondences>();
  pcl::KdTreeFLANN<pcl::SHOT1344> tree;
  auto valid = pcl::make_shared<pcl::PointCloud<pcl::SHOT1344>> (signatures);
  tree.setInputCloud (valid);
  for (std::size_t i = 0; i < signatures.size(); ++i) {
    if (!std::isfinite (signatures[i].descriptor[0]))
      continue;
    pcl::Indices neighbours;
    std::vector<float> distances;
    tree.nearestKSearch (signatures[i], 10, neighbours, distances);
    for (std::size_t n = 0; n < neighbours.size(); ++n) {
      const auto j = static_cast<std::size_t> (neighbours[n]);
      if (j != i &&
          ((*keypoints)[i].getVector3fMap() - (*keypoints)[j].getVector3fMap()).norm() >
              0.01f) {
        matches->emplace_back (
            static_cast<pcl::index_t> (i), neighbours[n], distances[n]);
        break;
      }
    }
  }

  // Our clusterer takes them like PCL's GeometricConsistencyGrouping would: the triplet
  // rejector runs inside it on these correspondences.
  mid::TransformationSpaceClustering clustering;
  clustering.setInputCloud (keypoints);
  clustering.setSceneCloud (keypoints);
  clustering.setModelSceneCorrespondences (matches);
  mid::TransformationSpaceClustering::Transformations poses;
  std::vector<pcl::Correspondences> groups;
  clustering.recognize (poses, groups);
  std::cout << "keypoints " << keypoints->size() << ", shot matches " << matches->size()
            << ", clusters " << poses.size() << "\n";
  for (std::size_t c = 0; c < poses.size(); ++c) {
    std::cout << "cluster " << c << ": " << groups[c].size() << " keypoint pairs, pose";
    for (int r = 0; r < 4; ++r)
      for (int col = 0; col < 4; ++col)
        std::cout << " " << poses[c](r, col);
    std::cout << "\n";
  }
  return 0;
}
