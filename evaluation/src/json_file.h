#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>

namespace mid {
namespace evaluation {
namespace detail {

/** \brief Read a JSON file of the annotations.
  * \param[in] path the file
  * \param[in] caller the reader's name, for its error message
  * \param[out] value the document
  * \return false (with a PCL_ERROR naming the file) if it cannot be opened or is not valid JSON
  */
bool
readJsonFile (const std::filesystem::path& path,
              const char* caller,
              nlohmann::json& value);

} // namespace detail
} // namespace evaluation
} // namespace mid
