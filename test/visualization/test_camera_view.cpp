// fitImage places the camera's image in a viewport; the viewer refuses to render without a
// display instead of letting VTK abort.

#include "temporary_folder.h"
#include "two_copies_scene.h"

#include <mid/visualization/camera_view.h>
#include <mid/visualization/discovery_viewer.h>
#include <mid/visualization/display.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

TEST (CameraView, FitsTheWholeImageCentred)
{
  using mid::visualization::fitImage;
  const auto same = fitImage (640, 480, 640, 480);
  EXPECT_DOUBLE_EQ (same.scale, 1.0);
  EXPECT_DOUBLE_EQ (same.offset_u, 0.0);
  EXPECT_DOUBLE_EQ (same.offset_v, 0.0);
  const auto square = fitImage (640, 480, 480, 480); // letterbox: bands above and below
  EXPECT_DOUBLE_EQ (square.scale, 0.75);
  EXPECT_DOUBLE_EQ (square.offset_u, 0.0);
  EXPECT_DOUBLE_EQ (square.offset_v, 60.0);
  const auto wide = fitImage (640, 480, 1280, 480); // bands left and right
  EXPECT_DOUBLE_EQ (wide.scale, 1.0);
  EXPECT_DOUBLE_EQ (wide.offset_u, 320.0);
  EXPECT_DOUBLE_EQ (fitImage (640, 480, 0, 480).scale, 0.0);
}

TEST (DiscoveryViewer, RefusesToRenderWithoutADisplay)
{
  const char* display = std::getenv ("DISPLAY");
  const std::string saved = display != nullptr ? display : "";
  ::unsetenv ("DISPLAY");
  EXPECT_FALSE (mid::visualization::displayAvailable());
  const mid::test::TemporaryFolder folder;
  mid::visualization::DiscoveryViewer<pcl::PointXYZRGB> viewer;
  viewer.setInputCloud (mid::test::makeTwoCopiesScene().cloud);
  EXPECT_FALSE (viewer.saveScreenshot (folder.file ("shot.png"), 640, 480));
  EXPECT_FALSE (viewer.spin (640, 480));
  EXPECT_FALSE (std::filesystem::exists (folder.file ("shot.png")));
  if (display != nullptr)
    ::setenv ("DISPLAY", saved.c_str(), 1);
}
