#include "json_file.h"

#include <pcl/console/print.h>

#include <fstream>

namespace mid {
namespace evaluation {
namespace detail {

bool
readJsonFile (const std::filesystem::path& path,
              const char* caller,
              nlohmann::json& value)
{
  std::ifstream file (path);
  if (!file) {
    PCL_ERROR ("[%s] cannot open '%s'\n", caller, path.string().c_str());
    return false;
  }
  try {
    file >> value;
  }
  catch (const std::exception& error) {
    PCL_ERROR ("[%s] '%s' is not valid JSON: %s\n",
               caller,
               path.string().c_str(),
               error.what());
    return false;
  }
  return true;
}

} // namespace detail
} // namespace evaluation
} // namespace mid
