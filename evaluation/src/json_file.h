#pragma once

#include <nlohmann/json.hpp>
#include <pcl/console/print.h>

#include <filesystem>
#include <stdexcept>
#include <string>

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

/** \brief Read a BOP models_info.json (an object keyed by obj_id) and hand each entry to `read`
  * (its obj_id and its JSON), which throws a std::exception to refuse one.
  * \param[in] path the file
  * \param[in] caller the reader's name, for its error message
  * \param[in] read called as read (int obj_id, const nlohmann::json& entry), in key order
  * \return false (with a PCL_ERROR naming the file and the problem) if the file cannot be read,
  * is not JSON or no object, a key is no obj_id, or `read` throws
  */
template <typename Read>
bool
readBopModelsInfo (const std::filesystem::path& path,
                   const char* caller,
                   const Read& read)
{
  nlohmann::json models;
  if (!readJsonFile (path, caller, models))
    return false;
  try {
    if (!models.is_object())
      throw std::runtime_error ("not an object keyed by obj_id");
    for (const auto& [key, model] : models.items()) {
      std::size_t used = 0;
      const int id = std::stoi (key, &used);
      if (used != key.size())
        throw std::runtime_error ("key '" + key + "' is no obj_id");
      read (id, model);
    }
  }
  catch (const std::exception& error) {
    PCL_ERROR ("[%s] '%s': %s\n", caller, path.string().c_str(), error.what());
    return false;
  }
  return true;
}

} // namespace detail
} // namespace evaluation
} // namespace mid
