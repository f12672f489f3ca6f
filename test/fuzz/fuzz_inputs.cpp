#include "fuzz_inputs.h"

#include <mid/io/organized_cloud_io.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <unistd.h>

namespace mid {
namespace fuzz {

namespace {

std::string
temporaryPCDPath ()
{
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::path dir = fs::is_directory ("/dev/shm", error) ? fs::path ("/dev/shm")
                                                            : fs::temp_directory_path();
  return (dir / ("mid_fuzz_" + std::to_string (::getpid()) + ".pcd")).string();
}

} // namespace

bool
loadPCDBytes (const std::uint8_t* data, std::size_t size, Cloud& cloud)
{
  static const std::string path = temporaryPCDPath();
  {
    std::ofstream file (path, std::ios::binary | std::ios::trunc);
    file.write (reinterpret_cast<const char*> (data),
                static_cast<std::streamsize> (size));
  }
  const bool loaded = io::loadOrganizedPCD (path, cloud);
  std::remove (path.c_str());
  return loaded;
}

bool
loadRGBDBytes (const std::uint8_t* data, std::size_t size, Cloud& cloud)
{
  std::size_t color_size = 0;
  if (size >= 4)
    color_size = static_cast<std::size_t> (data[0]) |
                 static_cast<std::size_t> (data[1]) << 8U |
                 static_cast<std::size_t> (data[2]) << 16U |
                 static_cast<std::size_t> (data[3]) << 24U;
  const std::size_t body = size >= 4 ? size - 4 : 0;
  color_size = std::min (color_size, body);
  const Bytes color (data + (size - body), data + (size - body) + color_size);
  const Bytes depth (data + (size - body) + color_size, data + size);
  return io::decodeRGBD (color, depth, {kFx, kFy, kCx, kCy, kDepthScale}, cloud);
}

Bytes
packRGBD (const Bytes& color, const Bytes& depth)
{
  const auto n = static_cast<std::uint32_t> (color.size());
  Bytes packed (4 + color.size() + depth.size());
  for (std::size_t i = 0; i < 4; ++i)
    packed[i] = static_cast<std::uint8_t> ((n >> (8U * i)) & 0xFFU);
  std::copy (color.begin(), color.end(), packed.begin() + 4);
  std::copy (depth.begin(),
             depth.end(),
             packed.begin() + 4 + static_cast<std::ptrdiff_t> (color.size()));
  return packed;
}

Bytes
readFile (const std::string& path)
{
  std::ifstream file (path, std::ios::binary);
  return {std::istreambuf_iterator<char> (file), std::istreambuf_iterator<char>()};
}

bool
keepsTheContract (bool loaded, const Cloud& cloud)
{
  if (!loaded)
    return cloud.empty() && cloud.width == 0 && cloud.height == 0;
  return cloud.height >= 2 &&
         static_cast<std::size_t> (cloud.width) * cloud.height == cloud.size();
}

} // namespace fuzz
} // namespace mid
