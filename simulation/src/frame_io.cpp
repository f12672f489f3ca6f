#include <mid/io/organized_cloud_io.h>
#include <mid/io/staged_files.h>
#include <mid/simulation/frame_io.h>

#include <opencv2/imgcodecs.hpp>
#include <pcl/console/print.h>
#include <pcl/point_types.h>

#include <cmath>
#include <limits>

namespace mid {
namespace simulation {

namespace {

template <typename PointT>
bool
failCloud (const std::string& message, pcl::PointCloud<PointT>& cloud)
{
  PCL_ERROR ("[mid::simulation::frameToCloud] %s\n", message.c_str());
  cloud.clear();
  cloud.width = cloud.height = 0;
  return false;
}

bool
writeImage (const std::string& path, const cv::Mat& image)
{
  try {
    if (cv::imwrite (path, image))
      return true;
  }
  catch (const cv::Exception& exception) {
    PCL_ERROR ("[mid::simulation::writeFrameImages] cannot write '%s': %s\n",
               path.c_str(),
               exception.what());
    return false;
  }
  PCL_ERROR ("[mid::simulation::writeFrameImages] cannot write '%s'\n", path.c_str());
  return false;
}

bool
hasExtension (const std::string& path, const std::string& extension)
{
  return path.size() >= extension.size() &&
         path.compare (path.size() - extension.size(), extension.size(), extension) ==
             0;
}

} // namespace

bool
quantizeDepth (const cv::Mat& depth, double depth_scale, cv::Mat& depth_16u)
{
  depth_16u.release();
  if (depth.empty() || depth.type() != CV_32FC1) {
    PCL_ERROR (
        "[mid::simulation::quantizeDepth] the depth image must be a non-empty CV_32FC1 "
        "image in metres\n");
    return false;
  }
  if (!std::isfinite (depth_scale) || !(depth_scale > 0.0)) {
    PCL_ERROR (
        "[mid::simulation::quantizeDepth] the depth scale must be positive, got %g\n",
        depth_scale);
    return false;
  }
  const double max_units = std::numeric_limits<std::uint16_t>::max();
  depth_16u.create (depth.size(), CV_16UC1);
  for (int v = 0; v < depth.rows; ++v) {
    const auto* in = depth.ptr<float> (v);
    auto* out = depth_16u.ptr<std::uint16_t> (v);
    for (int u = 0; u < depth.cols; ++u) {
      const double units = std::round (in[u] / depth_scale);
      out[u] = (std::isfinite (units) && units > 0.0 && units <= max_units)
                   ? static_cast<std::uint16_t> (units)
                   : 0;
    }
  }
  return true;
}

template <typename PointT>
bool
frameToCloud (const RenderedFrame& frame,
              double depth_scale,
              pcl::PointCloud<PointT>& cloud)
{
  std::string problem;
  if (!validateCamera (frame.camera, problem))
    return failCloud (problem, cloud);
  const cv::Size size (frame.camera.width, frame.camera.height);
  if (frame.color.size() != size || frame.depth.size() != size)
    return failCloud ("the frame's images do not have the camera's size", cloud);
  cv::Mat depth_16u;
  if (!quantizeDepth (frame.depth, depth_scale, depth_16u))
    return failCloud ("cannot quantize the frame's depth", cloud);
  if (!io::rgbdToCloud (frame.color,
                        depth_16u,
                        toCameraIntrinsics (frame.camera, depth_scale),
                        cloud))
    return failCloud ("mid::io::rgbdToCloud refused the frame", cloud);
  return true;
}

bool
writeFrameImages (const RenderedFrame& frame,
                  const std::string& color_path,
                  const std::string& depth_path,
                  double depth_scale)
{
  if (frame.color.empty() || frame.color.type() != CV_8UC3) {
    PCL_ERROR ("[mid::simulation::writeFrameImages] the frame has no 8-bit BGR colour "
               "image\n");
    return false;
  }
  if (!hasExtension (depth_path, ".png")) {
    PCL_ERROR (
        "[mid::simulation::writeFrameImages] the depth file '%s' must end in .png "
        "(16-bit)\n",
        depth_path.c_str());
    return false;
  }
  cv::Mat depth_16u;
  if (!quantizeDepth (frame.depth, depth_scale, depth_16u))
    return false;
  io::StagedFiles files;
  return writeImage (files.stage (color_path), frame.color) &&
         writeImage (files.stage (depth_path), depth_16u) && files.commit();
}

template bool
frameToCloud<pcl::PointXYZRGB> (const RenderedFrame&,
                                double,
                                pcl::PointCloud<pcl::PointXYZRGB>&);
template bool
frameToCloud<pcl::PointXYZRGBA> (const RenderedFrame&,
                                 double,
                                 pcl::PointCloud<pcl::PointXYZRGBA>&);

} // namespace simulation
} // namespace mid
