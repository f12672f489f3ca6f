#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace mid {
namespace fuzz {

using Cloud = pcl::PointCloud<pcl::PointXYZRGBA>;
using Bytes = std::vector<std::uint8_t>;

/** \brief The intrinsics every fuzzed RGB-D pair is back-projected with. */
constexpr double kFx = 525.0, kFy = 525.0, kCx = 1.5, kCy = 1.5, kDepthScale = 0.001;

/** \brief Load the bytes as a PCD file with mid::io::loadOrganizedPCD. PCL's PCD reader only
  * reads files (a body read from memory would skip the size checks PCL makes against the
  * file), so the bytes go through a temporary file of this process, in /dev/shm if it exists.
  */
bool
loadPCDBytes (const std::uint8_t* data, std::size_t size, Cloud& cloud);

/** \brief An RGB-D pair packed into one buffer: a 4-byte little-endian length N, N bytes of an
  * encoded color image, then the encoded 16-bit depth image; loaded with mid::io::decodeRGBD,
  * the in-memory path of mid::io::loadRGBD (cv::imdecode, then mid::io::rgbdToCloud).
  */
bool
loadRGBDBytes (const std::uint8_t* data, std::size_t size, Cloud& cloud);

/** \brief Pack an encoded color and depth image the way loadRGBDBytes() expects them. */
Bytes
packRGBD (const Bytes& color, const Bytes& depth);

/** \brief The whole content of a file (empty if it cannot be read). */
Bytes
readFile (const std::string& path);

/** \brief What loadOrganizedPCD/rgbdToCloud promise: an organized cloud on success, a
  * cleared one (no points, width = height = 0) on failure.
  */
bool
keepsTheContract (bool loaded, const Cloud& cloud);

} // namespace fuzz
} // namespace mid
