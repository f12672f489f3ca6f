// flatTopParts() on rendered boxes lying flush side by side on a table seen from above, with
// the boxes' true poses: the part found by one box's top is that box, for the lower box and
// for the taller one, and a box of no size there finds nothing.
#include "rendered_objects_scene.h"

#include <mid/segmentation/flat_top_parts.h>
#include <mid/segmentation/instance_extent.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace {

constexpr double kTable = 0.95;

/** The table's plane, facing the camera at kTable. */
const Eigen::Vector4f kPlane (0.0f, 0.0f, -1.0f, static_cast<float> (kTable));

/** A box of edges (x, y, height) lying on the table at (x, y). */
mid::test::BoxSpec
lyingBox (double x, double y, const Eigen::Vector3d& size)
{
  mid::test::BoxSpec box;
  box.texture = "tropicana_apple_juice_front.jpg";
  box.size = size;
  box.pose = mid::test::boxPose (x, y, kTable - 0.5 * size.z(), 0.0);
  return box;
}

/** A 120 x 90 x 40 mm box and a 120 x 70 x 80 mm one flush beside it, along y. */
const Eigen::Vector3d kLow (0.12, 0.09, 0.04);
const Eigen::Vector3d kTall (0.12, 0.07, 0.08);

struct FlushScene
{
  mid::test::RenderedObjectsScene rendered;
  pcl::PointCloud<pcl::PointXYZ> organized;
  pcl::Indices surface; ///< every pixel off the table
};

FlushScene
flushScene ()
{
  FlushScene scene;
  scene.rendered = mid::test::renderBoxes (
      {lyingBox (0.0, 0.0, kLow), lyingBox (0.0, 0.5 * (kLow.y() + kTall.y()), kTall)},
      kTable);
  const auto& cloud = *scene.rendered.cloud;
  scene.organized = pcl::PointCloud<pcl::PointXYZ> (cloud.width, cloud.height);
  for (std::size_t p = 0; p < cloud.size(); ++p) {
    scene.organized[p] = pcl::PointXYZ (cloud[p].x, cloud[p].y, cloud[p].z);
    if (std::isfinite (cloud[p].z) &&
        mid::planeDistance (kPlane, cloud[p].getVector3fMap()) > 0.003f)
      scene.surface.push_back (static_cast<pcl::index_t> (p));
  }
  return scene;
}

/** The surface's pixels whose point lies in box `b` of the scene (1 mm margin). */
pcl::Indices
pixelsOfBox (const FlushScene& scene, std::size_t b)
{
  const auto& box = scene.rendered.boxes[b];
  const Eigen::Isometry3d to_box = box.pose.inverse();
  pcl::Indices pixels;
  for (const auto p : scene.surface) {
    const Eigen::Vector3d local =
        to_box *
        scene.organized[static_cast<std::size_t> (p)].getVector3fMap().cast<double>();
    if ((local.array().abs() <= 0.5 * box.size.array() + 0.001).all())
      pixels.push_back (p);
  }
  return pixels;
}

/** Edges ascending. */
Eigen::Vector3f
ascending (const Eigen::Vector3d& size)
{
  Eigen::Vector3f edges = size.cast<float>();
  std::sort (edges.data(), edges.data() + 3);
  return edges;
}

TEST (FlatTopParts, FindsTheLowerAndTheTallerBoxOfAJoinByTheirTops)
{
  const FlushScene scene = flushScene();
  for (std::size_t b = 0; b < 2; ++b) {
    const pcl::Indices truth = pixelsOfBox (scene, b);
    ASSERT_GT (truth.size(), 1000u);
    std::vector<pcl::Indices> parts;
    ASSERT_TRUE (mid::flatTopParts (scene.organized,
                                    kPlane,
                                    scene.surface,
                                    ascending (scene.rendered.boxes[b].size),
                                    parts));
    ASSERT_EQ (parts.size(), 1u) << "box " << b;
    pcl::Indices part = parts.front(), sorted_truth = truth;
    std::sort (part.begin(), part.end());
    std::sort (sorted_truth.begin(), sorted_truth.end());
    pcl::Indices common;
    std::set_intersection (part.begin(),
                           part.end(),
                           sorted_truth.begin(),
                           sorted_truth.end(),
                           std::back_inserter (common));
    // The whole box (but where the taller one's side meets the lower one's top), and next to
    // nothing of its neighbour.
    EXPECT_GE (common.size(), 0.97 * static_cast<double> (truth.size())) << "box " << b;
    EXPECT_LE (part.size() - common.size(), 0.01 * static_cast<double> (truth.size()))
        << "box " << b;
    // Measured on its own, the part is the box.
    mid::InstanceExtent extent;
    ASSERT_TRUE (mid::fitInstanceBox (scene.organized, kPlane, part, extent));
    EXPECT_LT (
        (extent.size - ascending (scene.rendered.boxes[b].size)).cwiseAbs().maxCoeff(),
        0.004f)
        << "box " << b;
  }
}

TEST (FlatTopParts, FindsNoPartOfABoxWhoseTopIsNotThere)
{
  const FlushScene scene = flushScene();
  std::vector<pcl::Indices> parts;
  // Of the low box's height but longer, and of the join's whole footprint: no top fits.
  for (const Eigen::Vector3f& size : {Eigen::Vector3f (0.04f, 0.09f, 0.15f),
                                      Eigen::Vector3f (0.04f, 0.12f, 0.16f),
                                      Eigen::Vector3f (0.06f, 0.09f, 0.12f)}) {
    ASSERT_TRUE (
        mid::flatTopParts (scene.organized, kPlane, scene.surface, size, parts));
    EXPECT_TRUE (parts.empty()) << size.transpose();
  }
}

TEST (FlatTopParts, RefusesBadInput)
{
  const FlushScene scene = flushScene();
  std::vector<pcl::Indices> parts = {{1, 2}};
  EXPECT_FALSE (mid::flatTopParts (scene.organized,
                                   kPlane,
                                   scene.surface,
                                   Eigen::Vector3f (0.0f, 0.1f, 0.2f),
                                   parts));
  EXPECT_TRUE (parts.empty());
  EXPECT_FALSE (mid::flatTopParts (scene.organized,
                                   kPlane,
                                   scene.surface,
                                   Eigen::Vector3f (0.05f, 0.1f, std::nanf ("")),
                                   parts));
  pcl::Indices outside = {static_cast<pcl::index_t> (scene.organized.size())};
  EXPECT_FALSE (
      mid::flatTopParts (scene.organized, kPlane, outside, ascending (kLow), parts));
  pcl::PointCloud<pcl::PointXYZ> unorganized;
  unorganized.push_back (pcl::PointXYZ (0.0f, 0.0f, 1.0f));
  EXPECT_FALSE (mid::flatTopParts (unorganized, kPlane, {0}, ascending (kLow), parts));
  EXPECT_TRUE (parts.empty());
}

TEST (FlatTopSizes, SuggestsTheSizeOfEachBoxOfAJoin)
{
  const FlushScene scene = flushScene();
  std::vector<Eigen::Vector3f> sizes;
  ASSERT_TRUE (mid::flatTopSizes (scene.organized, kPlane, scene.surface, sizes));
  ASSERT_EQ (sizes.size(), 2u);
  // One per top, whatever their order: each within a few millimetres of its box.
  for (const Eigen::Vector3d& box : {kLow, kTall})
    EXPECT_TRUE (std::any_of (sizes.begin(),
                              sizes.end(),
                              [&] (const Eigen::Vector3f& size) {
                                return (size - ascending (box)).cwiseAbs().maxCoeff() <
                                       0.006f;
                              }))
        << "no size near " << box.transpose();
}

TEST (FlatTopSizes, RefusesBadInput)
{
  const FlushScene scene = flushScene();
  std::vector<Eigen::Vector3f> sizes = {Eigen::Vector3f::Ones()};
  pcl::Indices outside = scene.surface;
  outside.push_back (static_cast<pcl::index_t> (scene.organized.size()));
  EXPECT_FALSE (mid::flatTopSizes (scene.organized, kPlane, outside, sizes));
  EXPECT_TRUE (sizes.empty());
  sizes = {Eigen::Vector3f::Ones()};
  pcl::PointCloud<pcl::PointXYZ> unorganized;
  unorganized.push_back (pcl::PointXYZ (0.0f, 0.0f, 1.0f));
  EXPECT_FALSE (mid::flatTopSizes (unorganized, kPlane, {0}, sizes));
  EXPECT_TRUE (sizes.empty());
}

} // namespace
