#include <mid/io/organized_cloud_io.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <pcl/common/point_tests.h>
#include <pcl/console/print.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <vector>

namespace mid {
namespace io {

namespace {

/** Median |z| above which a cloud is taken to be in millimetres rather than metres. */
constexpr float kMaxPlausibleMedianDepth = 100.0f;

bool
isReadableFile (const std::string& path)
{
  std::ifstream file (path, std::ios::binary);
  return file.good ();
}

bool
isEmptyFile (const std::string& path)
{
  std::ifstream file (path, std::ios::binary | std::ios::ate);
  return file.tellg () <= 0;
}

/** Silences PCL's own console output while it lives: the PCD reader reports problems on several
  * lines of its own, and this module reports each problem once, in one line, itself.
  */
class QuietPCLConsole
{
public:
  QuietPCLConsole () : level_ (pcl::console::getVerbosityLevel ())
  {
    pcl::console::setVerbosityLevel (pcl::console::L_ALWAYS);
  }
  ~QuietPCLConsole () { pcl::console::setVerbosityLevel (level_); }
  QuietPCLConsole (const QuietPCLConsole&) = delete;
  QuietPCLConsole&
  operator= (const QuietPCLConsole&) = delete;

private:
  pcl::console::VERBOSITY_LEVEL level_;
};

/** Runs one call of PCL's PCD reader quietly and returns its status. The reader throws on some
  * malformed headers (std::out_of_range for a "DATA" line without a value, found by fuzzing);
  * an exception counts as a failed read (-1) instead of ending the program.
  */
template <typename ReadFunction>
int
readQuietly (ReadFunction read)
{
  QuietPCLConsole quiet;
  try {
    return read ();
  }
  catch (...) {
    return -1;
  }
}

bool
hasField (const pcl::PCLPointCloud2& header, const std::string& name)
{
  return std::any_of (header.fields.begin (), header.fields.end (),
                      [&name] (const pcl::PCLPointField& field) { return field.name == name; });
}

template <typename PointT>
bool
fail (const char* function, const std::string& message, pcl::PointCloud<PointT>& cloud)
{
  PCL_ERROR ("[mid::io::%s] %s\n", function, message.c_str ());
  cloud.clear ();
  cloud.width = cloud.height = 0;
  return false;
}

} // namespace

template <typename PointT>
bool
checkOrganizedCloud (const pcl::PointCloud<PointT>& cloud, std::string& problem)
{
  problem.clear ();
  if (cloud.empty ()) {
    problem = "the cloud is empty";
    return false;
  }
  if (cloud.height < 2 || static_cast<std::size_t> (cloud.width) * cloud.height != cloud.size ()) {
    problem = "the cloud is not organized (width " + std::to_string (cloud.width) + ", height " +
              std::to_string (cloud.height) + ", " + std::to_string (cloud.size ()) +
              " points); an RGB-D frame with one point per pixel is required";
    return false;
  }
  std::vector<float> depths;
  depths.reserve (cloud.size ());
  for (const auto& point : cloud)
    if (pcl::isXYZFinite (point))
      depths.push_back (std::abs (point.z));
  if (depths.empty ()) {
    problem = "the cloud has no valid depth (every point is NaN)";
    return false;
  }
  auto middle = depths.begin () + static_cast<std::ptrdiff_t> (depths.size () / 2);
  std::nth_element (depths.begin (), middle, depths.end ());
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
  if (!isReadableFile (path))
    return fail ("loadOrganizedPCD", "cannot open '" + path + "' (missing or unreadable)", cloud);

  if (isEmptyFile (path))
    return fail ("loadOrganizedPCD", "'" + path + "' is empty", cloud);

  pcl::PCDReader reader;
  pcl::PCLPointCloud2 header;
  Eigen::Vector4f origin;
  Eigen::Quaternionf orientation;
  int version = 0, data_type = 0;
  unsigned int data_index = 0;
  int status = readQuietly ([&] {
    return reader.readHeader (path, header, origin, orientation, version, data_type, data_index);
  });
  if (status < 0 || header.fields.empty ())
    return fail ("loadOrganizedPCD", "'" + path + "' is not a valid PCD file (bad header)", cloud);
  if (!hasField (header, "x") || !hasField (header, "y") || !hasField (header, "z"))
    return fail ("loadOrganizedPCD", "'" + path + "' has no x, y, z fields", cloud);
  if (!hasField (header, "rgb") && !hasField (header, "rgba"))
    return fail ("loadOrganizedPCD", "'" + path + "' has no color field (rgb or rgba)", cloud);
  if (header.height < 2)
    return fail ("loadOrganizedPCD",
                 "'" + path + "' is not organized (height " + std::to_string (header.height) +
                     "); an RGB-D frame with one point per pixel is required",
                 cloud);

  status = readQuietly ([&] { return reader.read (path, cloud); });
  if (status < 0)
    return fail ("loadOrganizedPCD", "'" + path + "' could not be read (truncated or corrupt data)",
                 cloud);
  std::string problem;
  if (!checkOrganizedCloud (cloud, problem))
    return fail ("loadOrganizedPCD", "'" + path + "': " + problem, cloud);
  return true;
}

template <typename PointT>
bool
rgbdToCloud (const cv::Mat& color,
             const cv::Mat& depth,
             const CameraIntrinsics& intrinsics,
             pcl::PointCloud<PointT>& cloud)
{
  std::string problem;
  if (!validateIntrinsics (intrinsics, problem))
    return fail ("rgbdToCloud", problem, cloud);
  if (color.empty () || depth.empty ())
    return fail ("rgbdToCloud", "the color or the depth image is empty", cloud);
  if (color.depth () != CV_8U || (color.channels () != 3 && color.channels () != 1))
    return fail ("rgbdToCloud", "the color image must be 8-bit with 1 or 3 channels", cloud);
  if (depth.type () != CV_16UC1)
    return fail ("rgbdToCloud", "the depth image must be a single-channel 16-bit image", cloud);
  if (color.size () != depth.size ())
    return fail ("rgbdToCloud",
                 "image sizes differ: color " + std::to_string (color.cols) + "x" +
                     std::to_string (color.rows) + ", depth " + std::to_string (depth.cols) +
                     "x" + std::to_string (depth.rows),
                 cloud);
  if (color.rows < 2 || color.cols < 2)
    return fail ("rgbdToCloud",
                 "the images are " + std::to_string (color.cols) + "x" +
                     std::to_string (color.rows) + " pixels, too small for an RGB-D frame",
                 cloud);

  cv::Mat bgr = color;
  if (color.channels () == 1)
    cv::cvtColor (color, bgr, cv::COLOR_GRAY2BGR);

  cloud.width = static_cast<std::uint32_t> (depth.cols);
  cloud.height = static_cast<std::uint32_t> (depth.rows);
  cloud.is_dense = false;
  cloud.resize (static_cast<std::size_t> (depth.cols) * static_cast<std::size_t> (depth.rows));
  const float nan = std::numeric_limits<float>::quiet_NaN ();
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

template <typename PointT>
bool
loadRGBD (const std::string& color_path,
          const std::string& depth_path,
          const CameraIntrinsics& intrinsics,
          pcl::PointCloud<PointT>& cloud)
{
  for (const std::string& path : {color_path, depth_path})
    if (!isReadableFile (path))
      return fail ("loadRGBD", "cannot open '" + path + "' (missing or unreadable)", cloud);
  const cv::Mat color = cv::imread (color_path, cv::IMREAD_COLOR);
  if (color.empty ())
    return fail ("loadRGBD", "'" + color_path + "' is not a readable image", cloud);
  const cv::Mat depth = cv::imread (depth_path, cv::IMREAD_ANYDEPTH | cv::IMREAD_ANYCOLOR);
  if (depth.empty ())
    return fail ("loadRGBD", "'" + depth_path + "' is not a readable image", cloud);
  if (depth.type () != CV_16UC1)
    return fail ("loadRGBD", "'" + depth_path + "' is not a single-channel 16-bit depth image",
                 cloud);
  return rgbdToCloud (color, depth, intrinsics, cloud);
}

#define MID_INSTANTIATE_ORGANIZED_CLOUD_IO(T)                                                  \
  template bool checkOrganizedCloud<T> (const pcl::PointCloud<T>&, std::string&);             \
  template bool loadOrganizedPCD<T> (const std::string&, pcl::PointCloud<T>&);                \
  template bool rgbdToCloud<T> (const cv::Mat&, const cv::Mat&, const CameraIntrinsics&,     \
                                pcl::PointCloud<T>&);                                         \
  template bool loadRGBD<T> (const std::string&, const std::string&, const CameraIntrinsics&, \
                             pcl::PointCloud<T>&);

MID_INSTANTIATE_ORGANIZED_CLOUD_IO (pcl::PointXYZRGB)
MID_INSTANTIATE_ORGANIZED_CLOUD_IO (pcl::PointXYZRGBA)

} // namespace io
} // namespace mid
