#include "temporary_folder.h"

#include <mid/io/organized_cloud_io.h>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <limits>
#include <vector>

namespace {

namespace fs = std::filesystem;
using Cloud = pcl::PointCloud<pcl::PointXYZRGB>;

const mid::io::CameraIntrinsics kIntrinsics{500.0, 510.0, 3.5, 2.5, 0.001};

/** A fresh folder per test (and process), removed afterwards. */
class OrganizedCloudIO : public ::testing::Test
{
protected:
  std::string
  path (const std::string& name) const
  {
    return folder_.file (name);
  }

  mid::test::TemporaryFolder folder_;
};

using Bytes = std::vector<std::uint8_t>;

/** A JPEG's baseline start-of-frame marker. */
const std::array<std::uint8_t, 2> kSof0{0xFF, 0xC0};

Bytes
encode (const char* extension, const cv::Mat& image)
{
  std::vector<uchar> bytes;
  EXPECT_TRUE (cv::imencode (extension, image, bytes));
  return {bytes.begin(), bytes.end()};
}

/** An 8 x 6 frame: depth (mm) grows with the pixel index, some pixels missing. */
void
makeFrame (cv::Mat& color, cv::Mat& depth)
{
  color.create (6, 8, CV_8UC3);
  depth.create (6, 8, CV_16UC1);
  for (int v = 0; v < 6; ++v)
    for (int u = 0; u < 8; ++u) {
      color.at<cv::Vec3b> (v, u) =
          cv::Vec3b (static_cast<uchar> (u * 30), static_cast<uchar> (v * 40), 7);
      depth.at<std::uint16_t> (v, u) =
          (u + v) % 5 == 0 ? 0 : static_cast<std::uint16_t> (700 + 10 * (v * 8 + u));
    }
}

/** A valid organized cloud in metres. */
Cloud
makeOrganizedCloud ()
{
  cv::Mat color, depth;
  makeFrame (color, depth);
  Cloud cloud;
  EXPECT_TRUE (mid::io::rgbdToCloud (color, depth, kIntrinsics, cloud));
  return cloud;
}

void
expectCleared (const Cloud& cloud)
{
  EXPECT_TRUE (cloud.empty());
  EXPECT_EQ (cloud.width, 0u);
  EXPECT_EQ (cloud.height, 0u);
}

} // namespace

TEST_F (OrganizedCloudIO, BackProjectsEveryPixelWithThePinholeModel)
{
  cv::Mat color, depth;
  makeFrame (color, depth);
  Cloud cloud;
  ASSERT_TRUE (mid::io::rgbdToCloud (color, depth, kIntrinsics, cloud));
  ASSERT_EQ (cloud.width, 8u);
  ASSERT_EQ (cloud.height, 6u);
  for (int v = 0; v < 6; ++v)
    for (int u = 0; u < 8; ++u) {
      const auto& p = cloud.at (u, v);
      const std::uint16_t d = depth.at<std::uint16_t> (v, u);
      EXPECT_EQ (p.b, color.at<cv::Vec3b> (v, u)[0]);
      EXPECT_EQ (p.g, color.at<cv::Vec3b> (v, u)[1]);
      EXPECT_EQ (p.r, color.at<cv::Vec3b> (v, u)[2]);
      if (d == 0) {
        EXPECT_TRUE (std::isnan (p.z));
        continue;
      }
      const double z = d * 0.001;
      EXPECT_FLOAT_EQ (p.z, static_cast<float> (z));
      EXPECT_FLOAT_EQ (p.x, static_cast<float> ((u - 3.5) * z / 500.0));
      EXPECT_FLOAT_EQ (p.y, static_cast<float> ((v - 2.5) * z / 510.0));
    }
}

TEST_F (OrganizedCloudIO, LoadsPngPairsLikeTheInMemoryPath)
{
  cv::Mat color, depth;
  makeFrame (color, depth);
  ASSERT_TRUE (cv::imwrite (path ("rgb.png"), color));
  ASSERT_TRUE (cv::imwrite (path ("depth.png"), depth));
  Cloud from_files;
  ASSERT_TRUE (mid::io::loadRGBD (
      path ("rgb.png"), path ("depth.png"), kIntrinsics, from_files));
  const Cloud expected = makeOrganizedCloud();
  ASSERT_EQ (from_files.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ (from_files[i].rgba, expected[i].rgba);
    if (std::isfinite (expected[i].z)) {
      EXPECT_EQ (from_files[i].getVector3fMap(), expected[i].getVector3fMap());
    }
  }
}

TEST_F (OrganizedCloudIO, RoundTripsAnOrganizedPcdInBothPointTypes)
{
  const Cloud cloud = makeOrganizedCloud();
  ASSERT_EQ (pcl::io::savePCDFileBinaryCompressed (path ("scene.pcd"), cloud), 0);
  Cloud loaded;
  ASSERT_TRUE (mid::io::loadOrganizedPCD (path ("scene.pcd"), loaded));
  EXPECT_EQ (loaded.width, cloud.width);
  EXPECT_EQ (loaded.height, cloud.height);
  pcl::PointCloud<pcl::PointXYZRGBA> rgba;
  ASSERT_TRUE (mid::io::loadOrganizedPCD (path ("scene.pcd"), rgba));
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    EXPECT_EQ (loaded[i].rgba, cloud[i].rgba);
    EXPECT_EQ (rgba[i].r, cloud[i].r);
    if (std::isfinite (cloud[i].z)) {
      EXPECT_EQ (loaded[i].getVector3fMap(), cloud[i].getVector3fMap());
    }
  }
}

TEST_F (OrganizedCloudIO, RefusesAMissingFile)
{
  Cloud cloud = makeOrganizedCloud();
  EXPECT_FALSE (mid::io::loadOrganizedPCD (path ("missing.pcd"), cloud));
  expectCleared (cloud);
}

TEST_F (OrganizedCloudIO, RefusesGarbageAndEmptyFiles)
{
  std::ofstream (path ("garbage.pcd")) << "this is not a point cloud\n\x01\x02";
  std::ofstream (path ("empty.pcd")).flush();
  for (const char* name : {"garbage.pcd", "empty.pcd"}) {
    Cloud cloud = makeOrganizedCloud();
    EXPECT_FALSE (mid::io::loadOrganizedPCD (path (name), cloud)) << name;
    expectCleared (cloud);
  }
}

TEST_F (OrganizedCloudIO, RefusesATruncatedBinaryPcd)
{
  const Cloud cloud = makeOrganizedCloud();
  ASSERT_EQ (pcl::io::savePCDFileBinary (path ("full.pcd"), cloud), 0);
  const auto size = fs::file_size (path ("full.pcd"));
  fs::copy_file (path ("full.pcd"), path ("cut.pcd"));
  fs::resize_file (path ("cut.pcd"), size - 100);
  Cloud loaded;
  EXPECT_FALSE (mid::io::loadOrganizedPCD (path ("cut.pcd"), loaded));
  expectCleared (loaded);
}

TEST_F (OrganizedCloudIO, RefusesAnUnorganizedCloud)
{
  Cloud cloud = makeOrganizedCloud();
  cloud.width = static_cast<std::uint32_t> (cloud.size());
  cloud.height = 1;
  ASSERT_EQ (pcl::io::savePCDFileBinary (path ("flat.pcd"), cloud), 0);
  Cloud loaded;
  EXPECT_FALSE (mid::io::loadOrganizedPCD (path ("flat.pcd"), loaded));
  expectCleared (loaded);
}

TEST_F (OrganizedCloudIO, RefusesACloudWithoutColor)
{
  pcl::PointCloud<pcl::PointXYZ> xyz;
  pcl::copyPointCloud (makeOrganizedCloud(), xyz);
  ASSERT_EQ (pcl::io::savePCDFileBinary (path ("xyz.pcd"), xyz), 0);
  Cloud loaded;
  EXPECT_FALSE (mid::io::loadOrganizedPCD (path ("xyz.pcd"), loaded));
  expectCleared (loaded);
}

TEST_F (OrganizedCloudIO, RefusesACloudWithoutValidDepth)
{
  Cloud cloud = makeOrganizedCloud();
  for (auto& p : cloud)
    p.x = p.y = p.z = std::numeric_limits<float>::quiet_NaN();
  ASSERT_EQ (pcl::io::savePCDFileBinary (path ("nan.pcd"), cloud), 0);
  Cloud loaded;
  EXPECT_FALSE (mid::io::loadOrganizedPCD (path ("nan.pcd"), loaded));
  expectCleared (loaded);
}

TEST_F (OrganizedCloudIO, RefusesACloudInMillimetres)
{
  Cloud cloud = makeOrganizedCloud();
  for (auto& p : cloud)
    p.getVector3fMap() *= 1000.0f;
  std::string problem;
  EXPECT_FALSE (mid::io::checkOrganizedCloud (cloud, problem));
  EXPECT_NE (problem.find ("millimetres"), std::string::npos);
}

TEST_F (OrganizedCloudIO, RefusesMismatchedOrMalformedImages)
{
  cv::Mat color, depth;
  makeFrame (color, depth);
  Cloud cloud;
  EXPECT_FALSE (
      mid::io::rgbdToCloud (color (cv::Rect (0, 0, 7, 6)), depth, kIntrinsics, cloud));
  cv::Mat depth8;
  depth.convertTo (depth8, CV_8U);
  EXPECT_FALSE (mid::io::rgbdToCloud (color, depth8, kIntrinsics, cloud));
  EXPECT_FALSE (mid::io::rgbdToCloud (
      color, cv::Mat::zeros (6, 8, CV_16UC1), kIntrinsics, cloud));
  EXPECT_FALSE (
      mid::io::rgbdToCloud (color, depth, {0.0, 0.0, 0.0, 0.0, 0.001}, cloud));
  EXPECT_FALSE (mid::io::rgbdToCloud (color (cv::Rect (0, 0, 1, 1)),
                                      depth (cv::Rect (0, 0, 1, 1)),
                                      kIntrinsics,
                                      cloud));
  expectCleared (cloud);

  ASSERT_TRUE (cv::imwrite (path ("rgb.png"), color));
  ASSERT_TRUE (cv::imwrite (path ("depth8.png"), depth8));
  EXPECT_FALSE (
      mid::io::loadRGBD (path ("rgb.png"), path ("depth8.png"), kIntrinsics, cloud));
  EXPECT_FALSE (
      mid::io::loadRGBD (path ("rgb.png"), path ("missing.png"), kIntrinsics, cloud));
  std::ofstream (path ("bad.png")) << "not a png";
  EXPECT_FALSE (
      mid::io::loadRGBD (path ("bad.png"), path ("rgb.png"), kIntrinsics, cloud));
  expectCleared (cloud);
}

TEST_F (OrganizedCloudIO, DecodesImagesInMemoryLikeFromFiles)
{
  cv::Mat color, depth;
  makeFrame (color, depth);
  const Cloud expected = makeOrganizedCloud();
  for (const char* color_format : {".png", ".jpg"}) {
    Cloud cloud;
    ASSERT_TRUE (mid::io::decodeRGBD (
        encode (color_format, color), encode (".png", depth), kIntrinsics, cloud))
        << color_format;
    ASSERT_EQ (cloud.size(), expected.size());
    for (std::size_t i = 0; i < cloud.size(); ++i)
      if (std::isfinite (expected[i].z)) {
        EXPECT_EQ (cloud[i].getVector3fMap(), expected[i].getVector3fMap());
      }
  }
}

TEST_F (OrganizedCloudIO, DecodesOnlyPngAndJpeg)
{
  cv::Mat color, depth;
  makeFrame (color, depth);
  Cloud cloud;
  // OpenCV reads these too, but the input path only hands PNG and JPEG to a decoder.
  EXPECT_FALSE (mid::io::decodeRGBD (
      encode (".bmp", color), encode (".png", depth), kIntrinsics, cloud));
  EXPECT_FALSE (mid::io::decodeRGBD (
      encode (".png", color), encode (".tiff", depth), kIntrinsics, cloud));
  // Depth must be a PNG (16-bit); a JPEG cannot hold it.
  EXPECT_FALSE (mid::io::decodeRGBD (
      encode (".png", color), encode (".jpg", color), kIntrinsics, cloud));
  EXPECT_FALSE (mid::io::decodeRGBD ({}, encode (".png", depth), kIntrinsics, cloud));
  expectCleared (cloud);
  // The same through files, whatever their names say.
  const Bytes bmp = encode (".bmp", color);
  std::ofstream (path ("rgb.png"), std::ios::binary)
      .write (reinterpret_cast<const char*> (bmp.data()),
              static_cast<std::streamsize> (bmp.size()));
  ASSERT_TRUE (cv::imwrite (path ("depth.png"), depth));
  EXPECT_FALSE (
      mid::io::loadRGBD (path ("rgb.png"), path ("depth.png"), kIntrinsics, cloud));
  expectCleared (cloud);
}

TEST_F (OrganizedCloudIO, RefusesAnImageHeaderClaimingTooManyPixels)
{
  cv::Mat color, depth;
  makeFrame (color, depth);
  // A valid PNG whose IHDR is rewritten to 65535 x 65535 (the CRC no longer matches, but the
  // size is checked before anything is decoded or allocated).
  Bytes huge = encode (".png", depth);
  for (const std::size_t at : {16u, 20u}) {
    huge[at] = huge[at + 1] = 0;
    huge[at + 2] = huge[at + 3] = 0xFF;
  }
  Cloud cloud;
  EXPECT_FALSE (mid::io::decodeRGBD (encode (".png", color), huge, kIntrinsics, cloud));
  expectCleared (cloud);
}

TEST_F (OrganizedCloudIO, FindsTheSizeOfAJpegWithStrayBytesBeforeItsFrameHeader)
{
  cv::Mat color, depth;
  makeFrame (color, depth);
  const Bytes clean = encode (".jpg", color);
  Cloud expected;
  ASSERT_TRUE (
      mid::io::decodeRGBD (clean, encode (".png", depth), kIntrinsics, expected));
  // libjpeg skips stray bytes between marker segments (with a warning) and decodes the image,
  // so the size check must find the frame header behind them too (a fuzzer found an image of
  // 65493 x 15104 pixels announced there, which OpenCV allocated: 3 GB).
  const auto sof = std::search (clean.begin(), clean.end(), kSof0.begin(), kSof0.end());
  ASSERT_NE (sof, clean.end());
  Bytes stray (clean.begin(), sof);
  stray.insert (stray.end(), {0x0A, 0x0A, 0xFF, 0x00, 0x0A});
  stray.insert (stray.end(), sof, clean.end());
  Cloud cloud;
  ASSERT_TRUE (mid::io::decodeRGBD (stray, encode (".png", depth), kIntrinsics, cloud));
  ASSERT_EQ (cloud.size(), expected.size());
  for (std::size_t i = 0; i < cloud.size(); ++i)
    EXPECT_EQ (cloud[i].rgba, expected[i].rgba);
  // The same header claiming 65535 x 65535 pixels is refused for its size, before anything is
  // decoded or allocated (the error names the claim).
  const std::size_t height_at = static_cast<std::size_t> (sof - clean.begin()) + 5 + 5;
  for (std::size_t i = 0; i < 4; ++i)
    stray[height_at + i] = 0xFF;
  testing::internal::CaptureStderr();
  EXPECT_FALSE (
      mid::io::decodeRGBD (stray, encode (".png", depth), kIntrinsics, cloud));
  EXPECT_NE (testing::internal::GetCapturedStderr().find ("claims 4294836225 pixels"),
             std::string::npos);
  expectCleared (cloud);
  // A JPEG cut before its frame header has no size: refused.
  const Bytes cut (clean.begin(), sof);
  EXPECT_FALSE (mid::io::decodeRGBD (cut, encode (".png", depth), kIntrinsics, cloud));
  expectCleared (cloud);
}

TEST_F (OrganizedCloudIO, RefusesAPcdWhoseHeaderAnnouncesMoreDataThanTheFileHolds)
{
  // 16384 x 16384 points in a 160-byte file: PCL alone would allocate and zero 4 GiB.
  std::ofstream (path ("huge.pcd"))
      << "VERSION 0.7\nFIELDS x y z rgb\nSIZE 4 4 4 4\nTYPE F F F U\nCOUNT 1 1 1 1\n"
         "WIDTH 16384\nHEIGHT 16384\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 268435456\nDATA "
         "binary\n";
  Cloud cloud;
  EXPECT_FALSE (mid::io::loadOrganizedPCD (path ("huge.pcd"), cloud));
  expectCleared (cloud);
}
