#include <mid/io/organized_cloud_io.h>
#include <mid/io/pcd_reader.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <pcl/common/io.h>
#include <pcl/common/point_tests.h>
#include <pcl/console/print.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <locale>
#include <sstream>
#include <vector>

namespace mid {
namespace io {

namespace {

/** Median |z| above which a cloud is taken to be in millimetres rather than metres. */
constexpr float kMaxPlausibleMedianDepth = 100.0f;

/** Largest image we decode: 8K UHD (7680 x 4320) fits, and the cloud of such a frame already
  * takes 1 GiB. A few bytes of PNG or JPEG header can claim 65535 x 65535 pixels, which
  * OpenCV would allocate before it finds out that the data is missing.
  */
constexpr std::uint64_t kMaxImagePixels = std::uint64_t{1} << 25U;

constexpr std::array<std::uint8_t, 8> kPngSignature{
    0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
constexpr std::array<std::uint8_t, 3> kJpegSignature{0xFF, 0xD8, 0xFF};

template <std::size_t N>
bool
startsWith (const std::vector<std::uint8_t>& data,
            const std::array<std::uint8_t, N>& prefix)
{
  return data.size() >= N && std::equal (prefix.begin(), prefix.end(), data.begin());
}

std::uint32_t
bigEndian (const std::vector<std::uint8_t>& data, std::size_t offset, std::size_t bytes)
{
  std::uint32_t value = 0;
  for (std::size_t i = 0; i < bytes; ++i)
    value = (value << 8U) | data[offset + i];
  return value;
}

/** Offset of the next marker code at or after `at` in a JPEG, the way libjpeg resynchronises:
  * bytes before a 0xFF are skipped ("extraneous bytes before marker"), so are fill bytes
  * (repeated 0xFF) and stuffed zeros (0xFF 0x00). Returns data.size() if there is none.
  */
std::size_t
nextJpegMarker (const std::vector<std::uint8_t>& data, std::size_t at)
{
  while (at + 1 < data.size()) {
    if (data[at] != 0xFF || data[at + 1] == 0xFF) {
      ++at;
      continue;
    }
    if (data[at + 1] != 0x00)
      return at + 1;
    at += 2;
  }
  return data.size();
}

/** Width x height from a PNG's IHDR chunk or a JPEG's start-of-frame marker; 0 if the header
  * is missing or cut short (neither decoder can decode such an image).
  */
std::uint64_t
headerPixels (const std::vector<std::uint8_t>& data)
{
  if (startsWith (data, kPngSignature))
    return data.size() < 24
               ? 0
               : std::uint64_t{bigEndian (data, 16, 4)} * bigEndian (data, 20, 4);
  // JPEG: walk the marker segments up to the first SOFn (C0..CF except C4 DHT, C8, CC DAC),
  // skipping what libjpeg skips between segments, or it would find a frame we do not see.
  for (std::size_t at = nextJpegMarker (data, 2); at + 3 <= data.size();) {
    const std::uint8_t marker = data[at];
    if (marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 &&
        marker != 0xCC)
      return at + 8 > data.size() ? 0
                                  : std::uint64_t{bigEndian (data, at + 4, 2)} *
                                        bigEndian (data, at + 6, 2);
    const bool standalone = marker == 0x01 || (marker >= 0xD0 && marker <= 0xD8);
    at = nextJpegMarker (data, at + (standalone ? 1 : 1 + bigEndian (data, at + 1, 2)));
  }
  return 0;
}

/** Decodes one encoded image; `name` says which in the problem. Only PNG (color or 16-bit
  * depth) and JPEG (color) are decoded: OpenCV picks its decoder by the content, not by the file
  * name, and some of Debian's decoders end the process on bad input (GDCM asserts on a
  * damaged DICOM header, found by fuzzing).
  */
bool
decodeImage (const std::vector<std::uint8_t>& data,
             bool is_depth,
             const std::string& name,
             cv::Mat& image,
             std::string& problem)
{
  image.release();
  const bool png = startsWith (data, kPngSignature);
  if (!png && (is_depth || !startsWith (data, kJpegSignature))) {
    problem = name + (is_depth ? " is not a PNG image (depth must be a 16-bit PNG)"
                               : " is not a PNG or JPEG image");
    return false;
  }
  const std::uint64_t pixels = headerPixels (data);
  if (pixels == 0) {
    problem = name + " has no image size in its header (corrupt or truncated)";
    return false;
  }
  if (pixels > kMaxImagePixels) {
    problem = name + " claims " + std::to_string (pixels) + " pixels, more than the " +
              std::to_string (kMaxImagePixels) + " an RGB-D frame may have";
    return false;
  }
  try {
    image = cv::imdecode (
        data, is_depth ? cv::IMREAD_ANYDEPTH | cv::IMREAD_ANYCOLOR : cv::IMREAD_COLOR);
  }
  catch (const std::exception&) {
    image.release();
  }
  if (image.empty()) {
    problem = name + " is not a readable image (corrupt or truncated)";
    return false;
  }
  if (is_depth && image.type() != CV_16UC1) {
    problem = name + " is not a single-channel 16-bit depth image";
    return false;
  }
  return true;
}

bool
readFile (const std::string& path, std::vector<std::uint8_t>& data)
{
  std::ifstream file (path, std::ios::binary);
  if (!file)
    return false;
  data.assign (std::istreambuf_iterator<char> (file), std::istreambuf_iterator<char>());
  return !file.bad();
}

template <typename PointT>
bool
fail (const char* function, const std::string& message, pcl::PointCloud<PointT>& cloud)
{
  PCL_ERROR ("[mid::io::%s] %s\n", function, message.c_str());
  cloud.clear();
  cloud.width = cloud.height = 0;
  return false;
}

} // namespace

template <typename PointT>
bool
checkOrganizedCloud (const pcl::PointCloud<PointT>& cloud, std::string& problem)
{
  problem.clear();
  if (cloud.empty()) {
    problem = "the cloud is empty";
    return false;
  }
  if (cloud.height < 2 ||
      static_cast<std::size_t> (cloud.width) * cloud.height != cloud.size()) {
    problem = "the cloud is not organized (width " + std::to_string (cloud.width) +
              ", height " + std::to_string (cloud.height) + ", " +
              std::to_string (cloud.size()) +
              " points); an RGB-D frame with one point per pixel is required";
    return false;
  }
  std::vector<float> depths;
  depths.reserve (cloud.size());
  for (const auto& point : cloud)
    if (pcl::isXYZFinite (point))
      depths.push_back (std::abs (point.z));
  if (depths.empty()) {
    problem = "the cloud has no valid depth (every point is NaN)";
    return false;
  }
  auto middle = depths.begin() + static_cast<std::ptrdiff_t> (depths.size() / 2);
  std::nth_element (depths.begin(), middle, depths.end());
  if (*middle > kMaxPlausibleMedianDepth) {
    problem = "the median depth is " + std::to_string (*middle) +
              ", which looks like millimetres; coordinates must be in metres";
    return false;
  }
  return true;
}

template <typename PointT>
bool
loadOrganizedPCD (const std::string& path, pcl::PointCloud<PointT>& cloud)
{
  pcl::PCLPointCloud2 blob;
  std::string problem;
  if (!readCheckedPCD (
          path, blob, cloud.sensor_origin_, cloud.sensor_orientation_, problem))
    return fail ("loadOrganizedPCD", problem, cloud);
  if (pcl::getFieldIndex (blob, "x") < 0 || pcl::getFieldIndex (blob, "y") < 0 ||
      pcl::getFieldIndex (blob, "z") < 0)
    return fail ("loadOrganizedPCD", "'" + path + "' has no x, y, z fields", cloud);
  if (pcl::getFieldIndex (blob, "rgb") < 0 && pcl::getFieldIndex (blob, "rgba") < 0)
    return fail (
        "loadOrganizedPCD", "'" + path + "' has no color field (rgb or rgba)", cloud);
  if (blob.height < 2)
    return fail ("loadOrganizedPCD",
                 "'" + path + "' is not organized (height " +
                     std::to_string (blob.height) +
                     "); an RGB-D frame with one point per pixel is required",
                 cloud);
  try {
    pcl::fromPCLPointCloud2 (blob, cloud);
  }
  catch (const std::exception&) {
    return fail ("loadOrganizedPCD",
                 "'" + path + "' could not be converted (out of memory)",
                 cloud);
  }
  if (!checkOrganizedCloud (cloud, problem))
    return fail ("loadOrganizedPCD", "'" + path + "': " + problem, cloud);
  return true;
}

namespace {

template <typename PointT>
bool
backProject (const cv::Mat& color,
             const cv::Mat& depth,
             const CameraIntrinsics& intrinsics,
             pcl::PointCloud<PointT>& cloud)
{
  std::string problem;
  if (!validateIntrinsics (intrinsics, problem))
    return fail ("rgbdToCloud", problem, cloud);
  if (color.empty() || depth.empty())
    return fail ("rgbdToCloud", "the color or the depth image is empty", cloud);
  if (color.depth() != CV_8U || (color.channels() != 3 && color.channels() != 1))
    return fail (
        "rgbdToCloud", "the color image must be 8-bit with 1 or 3 channels", cloud);
  if (depth.type() != CV_16UC1)
    return fail (
        "rgbdToCloud", "the depth image must be a single-channel 16-bit image", cloud);
  if (color.size() != depth.size())
    return fail ("rgbdToCloud",
                 "image sizes differ: color " + std::to_string (color.cols) + "x" +
                     std::to_string (color.rows) + ", depth " +
                     std::to_string (depth.cols) + "x" + std::to_string (depth.rows),
                 cloud);
  if (color.rows < 2 || color.cols < 2)
    return fail ("rgbdToCloud",
                 "the images are " + std::to_string (color.cols) + "x" +
                     std::to_string (color.rows) +
                     " pixels, too small for an RGB-D frame",
                 cloud);

  cv::Mat bgr = color;
  if (color.channels() == 1)
    cv::cvtColor (color, bgr, cv::COLOR_GRAY2BGR);

  cloud.width = static_cast<std::uint32_t> (depth.cols);
  cloud.height = static_cast<std::uint32_t> (depth.rows);
  cloud.is_dense = false;
  cloud.resize (static_cast<std::size_t> (depth.cols) *
                static_cast<std::size_t> (depth.rows));
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (int v = 0; v < depth.rows; ++v) {
    const auto* depth_row = depth.ptr<std::uint16_t> (v);
    const auto* color_row = bgr.ptr<cv::Vec3b> (v);
    for (int u = 0; u < depth.cols; ++u) {
      PointT& point = cloud.at (u, v);
      point.b = color_row[u][0];
      point.g = color_row[u][1];
      point.r = color_row[u][2];
      point.a = 255;
      if (depth_row[u] == 0) {
        point.x = point.y = point.z = nan;
        continue;
      }
      const double z = depth_row[u] * intrinsics.depth_scale;
      point.x = static_cast<float> ((u - intrinsics.cx) * z / intrinsics.fx);
      point.y = static_cast<float> ((v - intrinsics.cy) * z / intrinsics.fy);
      point.z = static_cast<float> (z);
    }
  }
  if (!checkOrganizedCloud (cloud, problem))
    return fail ("rgbdToCloud", problem, cloud);
  return true;
}

} // namespace

template <typename PointT>
bool
rgbdToCloud (const cv::Mat& color,
             const cv::Mat& depth,
             const CameraIntrinsics& intrinsics,
             pcl::PointCloud<PointT>& cloud)
{
  try {
    return backProject (color, depth, intrinsics, cloud);
  }
  catch (const std::exception& e) {
    return fail (
        "rgbdToCloud", std::string ("cannot build the cloud: ") + e.what(), cloud);
  }
}

template <typename PointT>
bool
decodeRGBD (const std::vector<std::uint8_t>& color_data,
            const std::vector<std::uint8_t>& depth_data,
            const CameraIntrinsics& intrinsics,
            pcl::PointCloud<PointT>& cloud)
{
  cv::Mat color, depth;
  std::string problem;
  if (!decodeImage (color_data, false, "the color image", color, problem) ||
      !decodeImage (depth_data, true, "the depth image", depth, problem))
    return fail ("decodeRGBD", problem, cloud);
  return rgbdToCloud (color, depth, intrinsics, cloud);
}

template <typename PointT>
bool
loadRGBD (const std::string& color_path,
          const std::string& depth_path,
          const CameraIntrinsics& intrinsics,
          pcl::PointCloud<PointT>& cloud)
{
  std::vector<std::uint8_t> color_data, depth_data;
  if (!readFile (color_path, color_data))
    return fail (
        "loadRGBD", "cannot open '" + color_path + "' (missing or unreadable)", cloud);
  if (!readFile (depth_path, depth_data))
    return fail (
        "loadRGBD", "cannot open '" + depth_path + "' (missing or unreadable)", cloud);
  cv::Mat color, depth;
  std::string problem;
  if (!decodeImage (color_data, false, "'" + color_path + "'", color, problem) ||
      !decodeImage (depth_data, true, "'" + depth_path + "'", depth, problem))
    return fail ("loadRGBD", problem, cloud);
  return rgbdToCloud (color, depth, intrinsics, cloud);
}

#define MID_INSTANTIATE_ORGANIZED_CLOUD_IO(T)                                          \
  template bool checkOrganizedCloud<T> (const pcl::PointCloud<T>&, std::string&);      \
  template bool loadOrganizedPCD<T> (const std::string&, pcl::PointCloud<T>&);         \
  template bool rgbdToCloud<T> (                                                       \
      const cv::Mat&, const cv::Mat&, const CameraIntrinsics&, pcl::PointCloud<T>&);   \
  template bool decodeRGBD<T> (const std::vector<std::uint8_t>&,                       \
                               const std::vector<std::uint8_t>&,                       \
                               const CameraIntrinsics&,                                \
                               pcl::PointCloud<T>&);                                   \
  template bool loadRGBD<T> (const std::string&,                                       \
                             const std::string&,                                       \
                             const CameraIntrinsics&,                                  \
                             pcl::PointCloud<T>&);

MID_INSTANTIATE_ORGANIZED_CLOUD_IO (pcl::PointXYZRGB)
MID_INSTANTIATE_ORGANIZED_CLOUD_IO (pcl::PointXYZRGBA)

} // namespace io
} // namespace mid
