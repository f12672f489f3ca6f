// mid::io::readCheckedPCD on headers: every form the PCD format allows is read to the points
// written, every damaged header is refused with a problem naming it, before PCL reads it.
#include "temporary_folder.h"

#include <mid/io/pcd_reader.h>

#include <gtest/gtest.h>
#include <pcl/common/io.h>
#include <pcl/conversions.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZRGB>;

/** A 4 x 3 organized cloud with distinct values in every field. */
Cloud
makeCloud ()
{
  Cloud cloud (4, 3);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const auto f = static_cast<float> (i);
    cloud[i].x = 0.01f * f;
    cloud[i].y = -0.02f * f;
    cloud[i].z = 0.5f + 0.03f * f;
    cloud[i].r = static_cast<std::uint8_t> (10 * i);
    cloud[i].g = static_cast<std::uint8_t> (200 - 10 * i);
    cloud[i].b = 7;
  }
  return cloud;
}

/** readCheckedPCD without the viewpoint. */
bool
readChecked (const std::string& path, pcl::PCLPointCloud2& blob, std::string& problem)
{
  Eigen::Vector4f origin;
  Eigen::Quaternionf orientation;
  return mid::io::readCheckedPCD (path, blob, origin, orientation, problem);
}

/** A replacement of some consecutive header lines ("" removes them), and what the file then is. */
struct HeaderEdit
{
  std::string lines; ///< without the last line's end
  std::string replacement;
  std::string problem; ///< part of the problem reported; empty if the file is valid
};

/** A binary PCD written by PCL, cut into its header lines and its body. */
class PCDReaderHeaders : public ::testing::Test
{
protected:
  void
  SetUp () override
  {
    const std::string original = folder_.file ("original.pcd");
    ASSERT_EQ (pcl::io::savePCDFileBinary (original, cloud_), 0);
    std::ifstream file (original, std::ios::binary);
    const std::string bytes ((std::istreambuf_iterator<char> (file)),
                             std::istreambuf_iterator<char>());
    const std::size_t body = bytes.find ("DATA binary\n") + 12;
    ASSERT_NE (body, std::string::npos + 12);
    header_ = bytes.substr (0, body);
    body_ = bytes.substr (body);
  }

  /** Writes the header with one edit (and the body) and reads it back. */
  bool
  readEdited (const HeaderEdit& edit,
              pcl::PCLPointCloud2& blob,
              std::string& problem) const
  {
    std::string header = header_;
    const std::size_t at = header.find (edit.lines + "\n");
    EXPECT_NE (at, std::string::npos) << edit.lines;
    header.replace (at, edit.lines.size() + 1, edit.replacement);
    const std::string path = folder_.file ("edited.pcd");
    std::ofstream (path, std::ios::binary) << header << body_;
    return readChecked (path, blob, problem);
  }

  const Cloud cloud_ = makeCloud();
  mid::test::TemporaryFolder folder_;
  std::string header_, body_;
};

} // namespace

TEST_F (PCDReaderHeaders, ReadsEveryFormOfHeaderTheFormatAllows)
{
  const std::vector<HeaderEdit> valid = {
      {"VERSION 0.7", "", ""},             // no VERSION
      {"COUNT 1 1 1 1", "", ""},           // no COUNT: one value each
      {"VIEWPOINT 0 0 0 1 0 0 0", "", ""}, // no VIEWPOINT
      {"VIEWPOINT 0 0 0 1 0 0 0", "VIEWPOINT 0.1 -2 3e-1 1 0 0 0\n", ""},
      {"SIZE 4 4 4 4", "SIZE\t4  4 4 4 \r\n", ""}, // tabs, spaces, CRLF
      {"FIELDS x y z rgb",
       "# a comment\nFIELDS x y z rgb\n\n",
       ""}, // comment, empty line
  };
  for (const auto& edit : valid) {
    pcl::PCLPointCloud2 blob;
    std::string problem;
    ASSERT_TRUE (readEdited (edit, blob, problem))
        << edit.replacement << ": " << problem;
    EXPECT_TRUE (problem.empty());
    Cloud read;
    pcl::fromPCLPointCloud2 (blob, read);
    ASSERT_EQ (read.width, 4u);
    ASSERT_EQ (read.height, 3u);
    for (std::size_t i = 0; i < read.size(); ++i) {
      EXPECT_EQ (read[i].getVector3fMap(), cloud_[i].getVector3fMap()) << i;
      EXPECT_EQ (read[i].rgba, cloud_[i].rgba) << i;
    }
  }
}

TEST_F (PCDReaderHeaders, ReadsEveryEncodingPCLWrites)
{
  const std::string ascii = folder_.file ("ascii.pcd");
  const std::string compressed = folder_.file ("compressed.pcd");
  ASSERT_EQ (pcl::io::savePCDFileASCII (ascii, cloud_), 0);
  ASSERT_EQ (pcl::io::savePCDFileBinaryCompressed (compressed, cloud_), 0);
  for (const std::string& path : {ascii, compressed}) {
    pcl::PCLPointCloud2 blob;
    std::string problem;
    ASSERT_TRUE (readChecked (path, blob, problem)) << path << ": " << problem;
    Cloud read;
    pcl::fromPCLPointCloud2 (blob, read);
    ASSERT_EQ (read.size(), cloud_.size());
    for (std::size_t i = 0; i < read.size(); ++i) {
      EXPECT_LT ((read[i].getVector3fMap() - cloud_[i].getVector3fMap()).norm(), 1e-6f);
      EXPECT_EQ (read[i].rgba, cloud_[i].rgba);
    }
  }
}

TEST_F (PCDReaderHeaders, ReadsABoolFieldAsPCLWritesIt)
{
  // x (4 bytes), a bool flag (TYPE B, SIZE 1), 3 bytes of padding: 8-byte points.
  pcl::PCLPointCloud2 written;
  written.width = 3;
  written.height = 1;
  written.point_step = 8;
  written.row_step = 24;
  pcl::PCLPointField x, flag;
  x.name = "x";
  x.datatype = pcl::PCLPointField::FLOAT32;
  x.count = 1;
  flag.name = "flag";
  flag.offset = 4;
  flag.datatype = pcl::PCLPointField::BOOL;
  flag.count = 1;
  written.fields = {x, flag};
  written.data.assign (24, 0);
  for (std::size_t i = 0; i < 3; ++i) {
    const float value = 0.5f * static_cast<float> (i);
    std::memcpy (&written.data[8 * i], &value, sizeof (value));
    written.data[8 * i + 4] = static_cast<std::uint8_t> (i % 2);
  }
  const std::string path = folder_.file ("bool.pcd");
  ASSERT_EQ (pcl::PCDWriter().writeBinary (path, written), 0);
  pcl::PCLPointCloud2 blob;
  std::string problem;
  ASSERT_TRUE (readChecked (path, blob, problem)) << problem;
  // PCL's writer names the padding as a field of its own ("_").
  const int f = pcl::getFieldIndex (blob, "flag");
  ASSERT_GE (f, 0);
  EXPECT_EQ (blob.fields[static_cast<std::size_t> (f)].datatype,
             pcl::PCLPointField::BOOL);
  EXPECT_EQ (blob.fields[static_cast<std::size_t> (f)].offset, 4u);
  ASSERT_EQ (blob.point_step, 8u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ (std::memcmp (&blob.data[8 * i], &written.data[8 * i], 4), 0) << i;
    EXPECT_EQ (blob.data[8 * i + 4], i % 2) << i;
  }
}

TEST_F (PCDReaderHeaders, ReadsAnUnorganizedCloudWithoutWidthAndHeight)
{
  std::string header = header_;
  for (const std::string& line :
       {std::string ("WIDTH 4\n"), std::string ("HEIGHT 3\n")})
    header.erase (header.find (line), line.size());
  const std::string path = folder_.file ("unorganized.pcd");
  std::ofstream (path, std::ios::binary) << header << body_;
  pcl::PCLPointCloud2 blob;
  std::string problem;
  ASSERT_TRUE (readChecked (path, blob, problem)) << problem;
  EXPECT_EQ (blob.width, 12u);
  EXPECT_EQ (blob.height, 1u);
}

TEST_F (PCDReaderHeaders, RefusesEveryDamagedHeaderBeforePCLReadsIt)
{
  const std::vector<HeaderEdit> damaged = {
      // Numbers PCL's int extraction fails on (it then uses an uninitialized value) or wraps.
      {"SIZE 4 4 4 4", "SIZE x 4 4 4\n", "SIZE line value 'x'"},
      {"SIZE 4 4 4 4", "SIZE 4 4 4 -2800\n", "SIZE line value '-2800'"},
      {"SIZE 4 4 4 4", "SIZE 4 4 4 +4\n", "SIZE line value '+4'"},
      {"SIZE 4 4 4 4", "SIZE 4 4 4 4x\n", "SIZE line value '4x'"},
      {"SIZE 4 4 4 4", "SIZE 4 4 4 48888888888888888888\n", "SIZE line value"},
      {"SIZE 4 4 4 4", "SIZE 4 4 4 3\n", "1, 2, 4 or 8 bytes"},
      {"COUNT 1 1 1 1", "COUNT x 1 1 1\n", "COUNT line value 'x'"},
      {"COUNT 1 1 1 1", "COUNT 1 1 1 0\n", "COUNT line value '0'"},
      {"COUNT 1 1 1 1", "COUNT 1 1 1 99999999999\n", "COUNT line value"},
      {"COUNT 1 1 1 1", "COUNT 1 1 1 16777216\n", "implausibly large"},
      {"POINTS 12", "POINTS x\n", "POINTS line must hold one whole number"},
      {"POINTS 12", "POINTS 2147483648\n", "POINTS line must hold one whole number"},
      {"WIDTH 4", "WIDTH -4\n", "WIDTH line must hold one whole number"},
      // One value per field, of a known type that fits its size.
      {"SIZE 4 4 4 4", "SIZE 4 4 4\n", "SIZE line has 3 values for 4 fields"},
      {"SIZE 4 4 4 4", "SIZE 4 4 4 4 4\n", "SIZE line has 5 values for 4 fields"},
      {"SIZE 4 4 4 4", "SIZE 4 4 4 4 \v 4\n", "control characters"},
      {"TYPE F F F U", "TYPE F F F X\n", "TYPE 'X'"},
      {"TYPE F F F U", "TYPE F F F UU\n", "TYPE 'UU'"},
      {"SIZE 4 4 4 4\nTYPE F F F U",
       "SIZE 4 4 4 2\nTYPE F F F F\n",
       "TYPE 'F' does not fit a field of 2"},
      {"FIELDS x y z rgb", "FIELDS\n", "FIELDS line names no field"},
      // The points the header announces.
      {"POINTS 12", "POINTS 13\n", "WIDTH 4 x HEIGHT 3 is not POINTS 13"},
      {"WIDTH 4\nHEIGHT 3\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 12", // 2^32 + 65536 points
       "WIDTH 65536\nHEIGHT 65537\nPOINTS 65536\n",
       "WIDTH 65536 x HEIGHT 65537 is not"},
      // 16384 x 16384 points of 16 bytes in a file of 350 bytes: PCL alone would allocate 4 GiB.
      {"WIDTH 4\nHEIGHT 3\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 12",
       "WIDTH 16384\nHEIGHT 16384\nPOINTS 268435456\n",
       "268435456 points of 16 bytes, far more"},
      {"VIEWPOINT 0 0 0 1 0 0 0", "VIEWPOINT 0 0 0 1 0 0\n", "seven numbers"},
      {"VIEWPOINT 0 0 0 1 0 0 0", "VIEWPOINT 0 0 0 nan 0 0 0\n", "seven numbers"},
      {"VIEWPOINT 0 0 0 1 0 0 0",
       "VIEWPOINT 0 0 0 1e39 0 0 0\n",
       "seven numbers"}, // > float
      {"WIDTH 4", "", "a HEIGHT line but no WIDTH line"},
      {"SIZE 4 4 4 4\nTYPE F F F U",
       "SIZE 4 4 4 4\nTYPE F F F B\n",
       "TYPE 'B' does not fit a field of 4"},
      {"DATA binary", "DATA binaryx\n", "DATA line must say"},
      {"DATA binary", "DATA binary\nHEIGHT 3\n", "('HEIGHT') follows the DATA line"},
      {"DATA binary", "", "lacks one of"},
      {"TYPE F F F U", "", "lacks one of"},
      // Keywords spelled as the format gives them, each once, in its order.
      {"SIZE 4 4 4 4", "SIZEX 4 4 4 4\n", "'SIZEX' is not a PCD v0.7 header keyword"},
      {"FIELDS x y z rgb", "COLUMNS x y z rgb\n", "'COLUMNS' is not a PCD v0.7"},
      {"COUNT 1 1 1 1", "COUNT 1 1 1 1\nCOUNT 1 1 1 1\n", "two COUNT lines"},
      {"COUNT 1 1 1 1\nWIDTH 4\nHEIGHT 3\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 12",
       "WIDTH 4\nHEIGHT 3\nPOINTS 12\nCOUNT 1 1 1 1\n",
       "COUNT line comes after POINTS"},
      {"FIELDS x y z rgb", "", "SIZE line comes before FIELDS"},
      {"SIZE 4 4 4 4", "", "TYPE line comes before SIZE"},
  };
  for (const auto& edit : damaged) {
    pcl::PCLPointCloud2 blob;
    blob.width = 1;
    std::string problem;
    EXPECT_FALSE (readEdited (edit, blob, problem)) << edit.replacement;
    EXPECT_NE (problem.find (edit.problem), std::string::npos)
        << edit.replacement << ": '" << problem << "' lacks '" << edit.problem << "'";
    EXPECT_NE (problem.find ("edited.pcd"), std::string::npos) << problem;
    EXPECT_EQ (blob.width, 0u);
    EXPECT_TRUE (blob.data.empty());
  }
}
