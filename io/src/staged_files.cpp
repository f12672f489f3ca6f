#include <mid/io/staged_files.h>

#include <pcl/console/print.h>

#include <filesystem>
#include <system_error>
#include <unistd.h>

namespace mid {
namespace io {

StagedFiles::~StagedFiles() { discard(); }

std::string
StagedFiles::stage (const std::string& path)
{
  const std::filesystem::path destination (path);
  const std::filesystem::path folder = destination.has_parent_path()
                                           ? destination.parent_path()
                                           : std::filesystem::path (".");
  std::error_code error;
  if (!std::filesystem::is_directory (folder, error) ||
      ::access (folder.c_str(), W_OK) != 0) {
    PCL_ERROR ("[mid::io::StagedFiles::stage] cannot write '%s': folder '%s' is "
               "missing or not "
               "writable\n",
               path.c_str(),
               folder.string().c_str());
    return {};
  }
  std::filesystem::path temporary = destination;
  temporary.replace_filename (destination.stem().string() + ".partial" +
                              destination.extension().string());
  entries_.push_back ({temporary.string(), path});
  return entries_.back().temporary;
}

bool
StagedFiles::commit()
{
  for (const Entry& entry : entries_) {
    std::error_code error;
    if (!std::filesystem::is_regular_file (entry.temporary, error)) {
      PCL_ERROR ("[mid::io::StagedFiles::commit] '%s' was not written\n",
                 entry.temporary.c_str());
      discard();
      return false;
    }
  }
  for (const Entry& entry : entries_) {
    std::error_code error;
    std::filesystem::rename (entry.temporary, entry.destination, error);
    if (error) {
      PCL_ERROR ("[mid::io::StagedFiles::commit] cannot rename '%s' to '%s': %s\n",
                 entry.temporary.c_str(),
                 entry.destination.c_str(),
                 error.message().c_str());
      discard();
      return false;
    }
  }
  entries_.clear();
  return true;
}

void
StagedFiles::discard()
{
  for (const Entry& entry : entries_) {
    std::error_code error;
    std::filesystem::remove (entry.temporary,
                             error); // a file never written is no error
  }
  entries_.clear();
}

} // namespace io
} // namespace mid
