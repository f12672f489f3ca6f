// consensusBoxes() on rendered boxes resting on a table, each of a model's copies lying flush
// with a neighbour of its height in a different place.
#include "resting_boxes.h"

#include <mid/segmentation/consensus_boxes.h>
#include <mid/segmentation/instance_extent.h>
#include <mid/segmentation/model_size.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

namespace {

using mid::test::kPrintedBoxSize;
using Boxes = mid::test::RestingBoxes;

/** Boxes 0 and 1 of twoJoinedTwoApart() (each lying flush with a neighbour, in a different
  * place) as one model at their true poses, the table, and the boxes of the model's instances,
  * each measured on its own surface (measureInstanceBoxes()).
  */
class ConsensusBoxes : public ::testing::Test
{
protected:
  void
  SetUp () override
  {
    const auto& organized = *scene.surface.organized;
    ASSERT_TRUE (mid::fitSupportPlane (organized, 0.01f, 0.2f, plane));
    std::vector<mid::InstanceExtents> per_model;
    ASSERT_TRUE (mid::measureInstanceBoxes (organized,
                                            plane,
                                            scene.surface.keypoint_pixels,
                                            {model},
                                            0.008f,
                                            0.3f,
                                            0.01f,
                                            per_model));
    ASSERT_EQ (per_model.size(), 1u);
    extents = per_model[0];
  }

  const Boxes scene{mid::test::twoJoinedTwoApart()};
  const mid::ObjectModel model = scene.modelOf ({0, 1});
  Eigen::Vector4f plane = Eigen::Vector4f::Zero();
  mid::InstanceExtents extents;
};

/** The box's edges (ascending) agree with the printed box's within 6 mm. */
bool
hasPrintedSize (const mid::InstanceExtent& box)
{
  Eigen::Vector3f truth = kPrintedBoxSize.cast<float>();
  std::sort (truth.data(), truth.data() + 3);
  return (box.size - truth).cwiseAbs().maxCoeff() < 0.006f;
}

TEST_F (ConsensusBoxes, MeasuresEachCopyWithoutTheNeighbourItLiesFlushWith)
{
  ASSERT_EQ (extents.size(), 2u);
  // Measured on its own, each copy's box holds its neighbour: 0.18 or 0.24 long.
  for (const auto& box : extents)
    EXPECT_FALSE (hasPrintedSize (box)) << box.size.transpose();

  // The band of the neighbour within the radius of the other copy's edge goes too: the box
  // does not grow with the radius.
  for (const float radius : {0.005f, 0.01f, 0.02f}) {
    mid::InstanceExtents consensus;
    ASSERT_TRUE (mid::consensusBoxes (
        *scene.surface.organized, plane, model, extents, radius, consensus));
    ASSERT_EQ (consensus.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) {
      EXPECT_TRUE (hasPrintedSize (consensus[i]))
          << "radius " << radius << ": " << consensus[i].size.transpose();
      // The box is the copy's own: its centre is the box's, its pixels on the copy.
      const auto& truth = scene.scene.boxes[i].pose;
      EXPECT_LT (
          (consensus[i].pose.topRightCorner<3, 1>() - truth.translation().cast<float>())
              .norm(),
          0.006f)
          << "radius " << radius << ", box " << i;
      const auto on_copy = std::count_if (
          consensus[i].surface.begin(),
          consensus[i].surface.end(),
          [&] (pcl::index_t p) {
            return mid::test::insideBox (
                scene.scene.boxes[i], (*scene.surface.organized)[p].getVector3fMap());
          });
      EXPECT_GT (static_cast<double> (on_copy),
                 0.98 * static_cast<double> (consensus[i].surface.size()))
          << "radius " << radius << ", box " << i;
    }
  }
}

TEST_F (ConsensusBoxes, GivesNoBoxWithoutASecondMeasuredCopy)
{
  extents[1] = mid::InstanceExtent();
  mid::InstanceExtents consensus;
  ASSERT_TRUE (mid::consensusBoxes (
      *scene.surface.organized, plane, model, extents, 0.02f, consensus));
  ASSERT_EQ (consensus.size(), 2u);
  for (const auto& box : consensus) {
    EXPECT_TRUE (box.surface.empty());
    EXPECT_EQ (box.size, Eigen::Vector3f::Zero());
  }
}

TEST_F (ConsensusBoxes, RefusesBadInputWithNoBoxes)
{
  const auto& organized = *scene.surface.organized;
  const auto refused = [&] (const pcl::PointCloud<pcl::PointXYZ>& cloud,
                            const mid::InstanceExtents& boxes,
                            float radius) {
    mid::InstanceExtents consensus (1);
    EXPECT_FALSE (mid::consensusBoxes (cloud, plane, model, boxes, radius, consensus));
    EXPECT_TRUE (consensus.empty());
  };
  for (const float radius : {0.0f,
                             -0.01f,
                             std::numeric_limits<float>::quiet_NaN(),
                             std::numeric_limits<float>::infinity()})
    refused (organized, extents, radius);
  refused (organized, mid::InstanceExtents (1, extents[0]), 0.02f);

  mid::InstanceExtents outside = extents;
  outside[1].surface.push_back (static_cast<int> (organized.size()));
  refused (organized, outside, 0.02f);

  pcl::PointCloud<pcl::PointXYZ> holed = organized;
  holed[static_cast<std::size_t> (extents[0].surface.front())].z =
      std::numeric_limits<float>::quiet_NaN();
  refused (holed, extents, 0.02f);

  pcl::PointCloud<pcl::PointXYZ> unorganized = organized;
  unorganized.width = static_cast<std::uint32_t> (organized.size());
  unorganized.height = 1;
  refused (unorganized, extents, 0.02f);
}

} // namespace
