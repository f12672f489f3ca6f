// loadBopModelSizes() and boxSizeErrorMm(): the products' true sizes and how far a measured box
// is from one.
#include "temporary_folder.h"

#include <mid/evaluation/object_size.h>

#include <gtest/gtest.h>

#include <fstream>

TEST (ObjectSize, ReadsBopModelsInfoSizesAndRefusesBadEntries)
{
  const mid::test::TemporaryFolder folder;
  const std::string path = folder.file ("models_info.json");
  std::ofstream (path) << R"({
    "1": {"diameter": 223, "size_x": 70, "size_y": 70, "size_z": 200},
    "2": {"diameter": 200, "size_x": 160, "size_y": 110, "size_z": 50},
    "7": {"diameter": 50}})";
  mid::evaluation::ObjectSizeTable table;
  ASSERT_TRUE (mid::evaluation::loadBopModelSizes (path, table));
  ASSERT_EQ (table.size(), 2u); // 7 gives no size
  EXPECT_TRUE (table.at (1).isApprox (Eigen::Vector3d (0.07, 0.07, 0.2)));
  EXPECT_TRUE (table.at (2).isApprox (Eigen::Vector3d (0.05, 0.11, 0.16))); // ascending

  for (const char* bad : {R"({"1": {"size_x": 70, "size_y": 70}})",
                          R"({"1": {"size_x": 70, "size_y": 0, "size_z": 200}})",
                          R"({"1": {"size_x": 70, "size_y": "wide", "size_z": 200}})",
                          R"({"one": {"size_x": 70, "size_y": 70, "size_z": 200}})",
                          "{ not json"}) {
    std::ofstream (path) << bad;
    table[3] = Eigen::Vector3d::Ones();
    EXPECT_FALSE (mid::evaluation::loadBopModelSizes (path, table)) << bad;
    EXPECT_TRUE (table.empty()) << bad;
  }
  EXPECT_FALSE (
      mid::evaluation::loadBopModelSizes (folder.file ("missing.json"), table));
}

TEST (ObjectSize, TheErrorIsTheLargestDifferenceOfTheSortedEdges)
{
  // Which edge is x does not matter: a carton lying or standing has one size.
  EXPECT_NEAR (mid::evaluation::boxSizeErrorMm (Eigen::Vector3d (0.2, 0.071, 0.068),
                                                Eigen::Vector3d (0.07, 0.07, 0.2)),
               2.0,
               1e-9);
  EXPECT_NEAR (mid::evaluation::boxSizeErrorMm (Eigen::Vector3d (0.07, 0.14, 0.2),
                                                Eigen::Vector3d (0.2, 0.07, 0.07)),
               70.0,
               1e-9); // two copies joined side by side
  EXPECT_EQ (mid::evaluation::boxSizeErrorMm (Eigen::Vector3d (0.05, 0.11, 0.16),
                                              Eigen::Vector3d (0.16, 0.05, 0.11)),
             0.0);
}
