#include "pcd_header.h"

#include <mid/io/pcd_reader.h>

#include <pcl/common/io.h>
#include <pcl/console/print.h>
#include <pcl/io/pcd_io.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <system_error>

namespace mid {
namespace io {

namespace {

bool
isReadableFile (const std::string& path)
{
  std::ifstream file (path, std::ios::binary);
  return file.good();
}

bool
isEmptyFile (const std::string& path)
{
  std::ifstream file (path, std::ios::binary | std::ios::ate);
  return file.tellg() <= 0;
}

/** A binary_compressed body starts with its compressed and uncompressed sizes; PCL only warns
  * when the uncompressed size disagrees with the header and then reads past its buffer (a heap
  * overflow found by fuzzing), so both sizes are checked first.
  */
bool
hasPlausibleCompressedBody (const std::string& path,
                            std::uint64_t file_size,
                            std::uint64_t body_offset,
                            std::uint64_t expected_size,
                            std::string& problem)
{
  std::array<unsigned char, 8> sizes{};
  std::ifstream file (path, std::ios::binary);
  file.seekg (static_cast<std::streamoff> (body_offset));
  if (body_offset + sizes.size() > file_size ||
      !file.read (reinterpret_cast<char*> (sizes.data()), sizes.size())) {
    problem = "its compressed body is missing";
    return false;
  }
  const auto little_endian = [&sizes] (std::size_t at) {
    return std::uint64_t{sizes[at]} | std::uint64_t{sizes[at + 1]} << 8U |
           std::uint64_t{sizes[at + 2]} << 16U | std::uint64_t{sizes[at + 3]} << 24U;
  };
  const std::uint64_t compressed = little_endian (0), uncompressed = little_endian (4);
  if (body_offset + sizes.size() + compressed > file_size) {
    problem = "its compressed body is truncated";
    return false;
  }
  if (uncompressed != expected_size) {
    problem = "its compressed body holds " + std::to_string (uncompressed) +
              " bytes of points, its header announces " +
              std::to_string (expected_size);
    return false;
  }
  return true;
}

/** Silences PCL's own console output while it lives: the PCD reader reports problems on several
  * lines of its own, and this module reports each problem once, in one line, itself.
  */
class QuietPCLConsole
{
public:
  QuietPCLConsole() : level_ (pcl::console::getVerbosityLevel())
  {
    pcl::console::setVerbosityLevel (pcl::console::L_ALWAYS);
  }
  ~QuietPCLConsole() { pcl::console::setVerbosityLevel (level_); }
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
    return read();
  }
  catch (...) {
    return -1;
  }
}

/** PCL's reader trusts its header: the point data is allocated when the POINTS line is read,
  * with the point step known at that moment, and later lines may change the fields; the body
  * is then written (and pcl::fromPCLPointCloud2 reads it) with the final offsets. So the layout
  * of the header (rows: false) and of the data read (rows: true, as the conversion walks it by
  * row_step) is checked before either step. Found by fuzzing: a damaged SIZE line gave 16-byte
  * points over data read as 12-byte points (a heap overflow in the conversion), other headers
  * made PCL's body reader write past the data (heap corruption), and WIDTH 0 made the
  * conversion bind a reference to the data of an empty cloud (undefined behaviour).
  */
bool
hasConsistentLayout (const pcl::PCLPointCloud2& blob, bool rows, std::string& problem)
{
  for (const auto& field : blob.fields) {
    const std::uint64_t size = pcl::getFieldSize (field.datatype);
    const std::uint64_t count = std::max<std::uint64_t> (field.count, 1);
    if (size == 0 || std::uint64_t{field.offset} + size * count > blob.point_step) {
      problem = "field '" + field.name + "' does not fit into a point of " +
                std::to_string (blob.point_step) + " bytes";
      return false;
    }
  }
  if (blob.width == 0 ||
      blob.height == 0) { // fromPCLPointCloud2 would take &cloud[0] of nothing
    problem = "it holds no points (width " + std::to_string (blob.width) + ", height " +
              std::to_string (blob.height) + ")";
    return false;
  }
  const std::uint64_t row_bytes = std::uint64_t{blob.width} * blob.point_step;
  const std::uint64_t row_step = rows ? blob.row_step : row_bytes;
  if (row_step < row_bytes || row_step * blob.height > blob.data.size()) {
    problem = "it holds " + std::to_string (blob.data.size()) +
              " bytes of points, less than the " +
              std::to_string (row_bytes * blob.height) + " its header announces";
    return false;
  }
  return true;
}

} // namespace

bool
readCheckedPCD (const std::string& path,
                pcl::PCLPointCloud2& blob,
                Eigen::Vector4f& origin,
                Eigen::Quaternionf& orientation,
                std::string& problem)
{
  blob = pcl::PCLPointCloud2();
  problem.clear();
  const auto refuse = [&blob, &problem] (const std::string& message) {
    blob = pcl::PCLPointCloud2();
    problem = message;
    return false;
  };
  if (!isReadableFile (path))
    return refuse ("cannot open '" + path + "' (missing or unreadable)");
  if (isEmptyFile (path))
    return refuse ("'" + path + "' is empty");
  std::error_code error;
  const std::uint64_t file_size = std::filesystem::file_size (path, error);
  std::string reason;
  std::ifstream file (path, std::ios::binary);
  if (error || !detail::checkPCDHeader (file, file_size, reason))
    return refuse ("'" + path + "' is not a valid PCD file: " + reason);

  pcl::PCDReader reader;
  pcl::PCLPointCloud2 header;
  int version = 0, data_type = 0;
  unsigned int data_index = 0;
  int status = readQuietly ([&] {
    return reader.readHeader (
        path, header, origin, orientation, version, data_type, data_index);
  });
  if (status < 0 || header.fields.empty())
    return refuse ("'" + path + "' is not a valid PCD file (bad header)");
  if (!hasConsistentLayout (header, false, reason))
    return refuse ("'" + path + "' is corrupt: " + reason);
  constexpr int kBinaryCompressed = 2; // PCL's data_type for DATA binary_compressed
  const std::uint64_t expected_size =
      std::uint64_t{header.width} * header.height * header.point_step;
  if (data_type == kBinaryCompressed &&
      !hasPlausibleCompressedBody (path, file_size, data_index, expected_size, reason))
    return refuse ("'" + path + "' is corrupt: " + reason);

  status = readQuietly (
      [&] { return reader.read (path, blob, origin, orientation, version); });
  if (status < 0)
    return refuse ("'" + path + "' could not be read (truncated or corrupt data)");
  if (!hasConsistentLayout (blob, true, reason))
    return refuse ("'" + path + "' is corrupt: " + reason);
  return true;
}

} // namespace io
} // namespace mid
