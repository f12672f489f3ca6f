#include "peer_grouping.h"

#include <mid/registration/rigid_transform.h>

#include <pcl/console/print.h>
#include <pcl/features/board.h>
#include <pcl/recognition/cg/geometric_consistency.h>
#include <pcl/recognition/cg/hough_3d.h>
// PCL instantiates its grouping classes for XYZ point types only; keypoints carry normals.
#include <pcl/features/impl/board.hpp>
#include <pcl/recognition/impl/cg/geometric_consistency.hpp>
#include <pcl/recognition/impl/cg/hough_3d.hpp>

#include <algorithm>
#include <set>

namespace mid {
namespace detail {

namespace {

using Transformations =
    std::vector<Eigen::Matrix4f, Eigen::aligned_allocator<Eigen::Matrix4f>>;

/** A group of correspondences and its pose as a cluster (distinct pairs, point sets, rms). */
TripletCluster
toCluster (const pcl::Correspondences& group,
           const Eigen::Matrix4f& pose,
           const KeypointCloud& keypoints)
{
  TripletCluster cluster;
  std::set<std::pair<pcl::index_t, pcl::index_t>> pairs;
  for (const auto& c : group)
    if (c.index_query != c.index_match)
      pairs.insert ({c.index_query, c.index_match});
  std::set<pcl::index_t> source, target;
  float squared = 0.0f;
  for (const auto& [p, q] : pairs) {
    const Eigen::Vector3f from =
        keypoints[static_cast<std::size_t> (p)].getVector3fMap();
    const Eigen::Vector3f to = keypoints[static_cast<std::size_t> (q)].getVector3fMap();
    const float error =
        (pose.topLeftCorner<3, 3>() * from + pose.topRightCorner<3, 1>() - to).norm();
    cluster.correspondences.emplace_back (p, q, error);
    squared += error * error;
    source.insert (p);
    target.insert (q);
  }
  cluster.transformation = pose;
  cluster.rms_error =
      pairs.empty() ? 0.0f : std::sqrt (squared / static_cast<float> (pairs.size()));
  cluster.source_indices.assign (source.begin(), source.end());
  cluster.target_indices.assign (target.begin(), target.end());
  return cluster;
}

} // namespace

bool
groupWithPeer (const DiscoveryParameters& p,
               const KeypointCloud::ConstPtr& keypoints,
               const pcl::PointCloud<pcl::PointNormal>::ConstPtr& surface,
               const pcl::Correspondences& matches,
               TripletClusters& clusters)
{
  clusters.clear();
  if (matches.empty() || keypoints->empty())
    return true;
  auto correspondences = pcl::make_shared<pcl::Correspondences> (matches);
  Transformations poses;
  std::vector<pcl::Correspondences> groups;
  if (p.grouping == Grouping::geometric_consistency) {
    pcl::GeometricConsistencyGrouping<pcl::PointNormal, pcl::PointNormal> gcg;
    gcg.setInputCloud (keypoints);
    gcg.setSceneCloud (keypoints);
    gcg.setModelSceneCorrespondences (correspondences);
    gcg.setGCSize (p.gc_size);
    gcg.setGCThreshold (p.gc_threshold);
    gcg.recognize (poses, groups);
  }
  else {
    if (!surface || surface->empty()) {
      PCL_ERROR ("[mid::groupWithPeer] Hough3D grouping needs the frame's surface with "
                 "normals.\n");
      return false;
    }
    auto frames = pcl::make_shared<pcl::PointCloud<pcl::ReferenceFrame>>();
    pcl::BOARDLocalReferenceFrameEstimation<pcl::PointNormal,
                                            pcl::PointNormal,
                                            pcl::ReferenceFrame>
        board;
    board.setFindHoles (true);
    board.setRadiusSearch (p.lrf_radius);
    board.setInputCloud (keypoints);
    board.setInputNormals (surface);
    board.setSearchSurface (surface);
    board.compute (*frames);
    pcl::Hough3DGrouping<pcl::PointNormal,
                         pcl::PointNormal,
                         pcl::ReferenceFrame,
                         pcl::ReferenceFrame>
        hough;
    hough.setHoughBinSize (p.hough_bin_size);
    hough.setHoughThreshold (p.hough_threshold);
    hough.setUseInterpolation (true);
    hough.setUseDistanceWeight (false);
    hough.setInputCloud (keypoints);
    hough.setInputRf (frames);
    hough.setSceneCloud (keypoints);
    hough.setSceneRf (frames);
    hough.setModelSceneCorrespondences (correspondences);
    hough.recognize (poses, groups);
  }
  for (std::size_t g = 0; g < groups.size() && g < poses.size(); ++g)
    if (poses[g].allFinite())
      clusters.push_back (toCluster (groups[g], poses[g], *keypoints));
  std::stable_sort (clusters.begin(),
                    clusters.end(),
                    [] (const TripletCluster& a, const TripletCluster& b) {
                      return a.correspondences.size() > b.correspondences.size();
                    });
  return true;
}

} // namespace detail
} // namespace mid
