#define PCL_NO_PRECOMPILE
#include <mid/io/pcd_reader.h>
#include <mid/registration/json_writing.h>
#include <mid/registration/object_model_io.h>

#include <nlohmann/json.hpp>
#include <pcl/common/io.h>
#include <pcl/console/print.h>
#include <pcl/conversions.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>
#include <pcl/register_point_struct.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

namespace mid {
namespace detail {

/** \brief One stored descriptor with its landmark: a row of a model's PCD file. */
struct EIGEN_ALIGN16 ModelFilePoint
{
  PCL_ADD_POINT4D;
  PCL_ADD_NORMAL4D;
  int landmark;
  float descriptor[128];
  PCL_MAKE_ALIGNED_OPERATOR_NEW
};

} // namespace detail
} // namespace mid

POINT_CLOUD_REGISTER_POINT_STRUCT (
    mid::detail::ModelFilePoint,
    (float, x, x) (float, y, y) (float, z, z) (float, normal_x, normal_x) (
        float, normal_y, normal_y) (float, normal_z, normal_z) (
        int, landmark, landmark) (float[128], descriptor, descriptor))

namespace mid {

namespace {

using detail::ModelFilePoint;

std::string
dataPathOf (const std::string& json_path)
{
  std::filesystem::path data (json_path);
  data.replace_extension (".pcd");
  return data.string();
}

bool
fail (const std::string& message, ObjectModel& model, ModelSize& box)
{
  PCL_ERROR ("[mid::loadObjectModel] %s\n", message.c_str());
  model = ObjectModel();
  box = ModelSize();
  return false;
}

/** The finite number stored under `key` in a model file's header; false if there is none. */
bool
findNumber (const nlohmann::json& header, const char* key, double& value)
{
  const auto it = header.find (key);
  if (it == header.end() || !it->is_number())
    return false;
  value = it->get<double>();
  return std::isfinite (value);
}

/** The whole number of at least 0 stored under `key`; false if there is none. */
bool
findCount (const nlohmann::json& header, const char* key, std::uint64_t& value)
{
  const auto it = header.find (key);
  if (it == header.end() || !it->is_number_unsigned())
    return false;
  value = it->get<std::uint64_t>();
  return true;
}

/** Read `count` numbers of a JSON list into `values`; false if it is no such list or a number
  * is no finite float.
  */
bool
readNumbers (const nlohmann::json& list, std::size_t count, float* values)
{
  if (!list.is_array() || list.size() != count)
    return false;
  for (std::size_t i = 0; i < count; ++i) {
    if (!list[i].is_number())
      return false;
    const double value = list[i].get<double>();
    if (!(std::abs (value) <= static_cast<double> (std::numeric_limits<float>::max())))
      return false;
    values[i] = static_cast<float> (value);
  }
  return true;
}

/** The box in a model file's header (detail::writeJsonBox()): not valid when it is absent or
  * null.
  * \return false (box not valid) if it is malformed or no box (isModelBox())
  */
bool
readBox (const nlohmann::json& header, ModelSize& box)
{
  box = ModelSize();
  const auto it = header.find ("box");
  if (it == header.end() || it->is_null())
    return true;
  Eigen::Matrix<float, 4, 4, Eigen::RowMajor> pose;
  bool read = it->is_object() && it->contains ("size") && it->contains ("copies") &&
              it->contains ("pose") && it->at ("copies").is_number_unsigned() &&
              readNumbers (it->at ("size"), 3, box.size.data()) &&
              it->at ("pose").is_array() && it->at ("pose").size() == 4;
  for (std::size_t r = 0; read && r < 4; ++r)
    read = readNumbers (
        it->at ("pose")[r], 4, pose.row (static_cast<Eigen::Index> (r)).data());
  if (read) {
    const auto copies = it->at ("copies").get<std::uint64_t>();
    box.agreeing = static_cast<int> (
        std::min<std::uint64_t> (copies, std::numeric_limits<int>::max()));
    box.box_in_model = pose;
  }
  if (!read || !isModelBox (box)) {
    box = ModelSize();
    return false;
  }
  box.valid = true;
  return true;
}

} // namespace

bool
saveObjectModel (const std::string& path,
                 const ObjectModel& model,
                 io::StagedFiles* staged)
{
  return saveObjectModel (path, model, ModelSize(), staged);
}

bool
saveObjectModel (const std::string& path,
                 const ObjectModel& model,
                 const ModelSize& box,
                 io::StagedFiles* staged)
{
  if (std::filesystem::path (path).extension() != ".json") {
    PCL_ERROR ("[mid::saveObjectModel] '%s' must end in .json\n", path.c_str());
    return false;
  }
  if (box.valid && !isModelBox (box)) {
    PCL_ERROR ("[mid::saveObjectModel] not writing '%s': its box is no box (%s)\n",
               path.c_str(),
               MODEL_BOX_RULE);
    return false;
  }
  pcl::PointCloud<ModelFilePoint> rows;
  for (std::size_t d = 0; d < model.descriptors.size(); ++d) {
    const auto& landmark =
        model.landmarks[static_cast<std::size_t> (model.descriptor_landmarks[d])];
    ModelFilePoint row;
    row.getVector3fMap() = landmark.getVector3fMap();
    row.getNormalVector3fMap() = landmark.getNormalVector3fMap();
    row.landmark = model.descriptor_landmarks[d];
    std::copy (model.descriptors[d].histogram,
               model.descriptors[d].histogram + 128,
               row.descriptor);
    rows.push_back (row);
  }
  io::StagedFiles own;
  io::StagedFiles& files = staged != nullptr ? *staged : own;
  const std::string json_temporary = files.stage (path);
  const std::string data_temporary = files.stage (dataPathOf (path));
  if (json_temporary.empty() || data_temporary.empty())
    return false;
  std::ofstream json (json_temporary);
  json << "{\n  \"format\": \"mid-object-model\",\n  \"version\": "
       << OBJECT_MODEL_FILE_VERSION << ",\n  \"data\": \""
       << std::filesystem::path (dataPathOf (path)).filename().string()
       << "\",\n  \"landmarks\": " << model.landmarks.size()
       << ",\n  \"descriptors\": " << model.descriptors.size()
       << ",\n  \"diameter\": " << detail::jsonNumber (model.diameter)
       << ",\n  \"box\": ";
  detail::writeJsonBox (json, &box, "\n          ");
  json << "\n}\n";
  json.close();
  if (!json || rows.empty() ||
      pcl::io::savePCDFileBinaryCompressed (data_temporary, rows) != 0 ||
      (staged == nullptr && !files.commit())) {
    PCL_ERROR ("[mid::saveObjectModel] cannot write '%s'%s\n",
               path.c_str(),
               rows.empty() ? ": the model has no descriptors" : "");
    return false;
  }
  return true;
}

bool
loadObjectModel (const std::string& path, ObjectModel& model)
{
  ModelSize box;
  return loadObjectModel (path, model, box);
}

bool
loadObjectModel (const std::string& path, ObjectModel& model, ModelSize& box)
{
  model = ObjectModel();
  box = ModelSize();
  std::ifstream file (path);
  if (!file)
    return fail ("cannot open '" + path + "' (missing or unreadable)", model, box);
  std::stringstream text;
  text << file.rdbuf();
  const nlohmann::json header = nlohmann::json::parse (text.str(), nullptr, false);
  const auto format = header.is_object() ? header.find ("format") : header.end();
  if (header.is_discarded() || !header.is_object() || format == header.end() ||
      *format != "mid-object-model")
    return fail ("'" + path +
                     R"(' is not a mid object model (no JSON object with "format": )"
                     R"("mid-object-model"; truncated?))",
                 model,
                 box);
  std::uint64_t version = 0, landmarks = 0, descriptors = 0;
  double diameter = 0.0;
  if (!findCount (header, "version", version))
    return fail ("'" + path + "' has no version (a whole number)", model, box);
  if (version != static_cast<std::uint64_t> (OBJECT_MODEL_FILE_VERSION))
    return fail ("'" + path + "' is a model file of version " +
                     std::to_string (version) + "; this build reads version " +
                     std::to_string (OBJECT_MODEL_FILE_VERSION),
                 model,
                 box);
  // Every landmark has a descriptor or more, so the data's rows bound both counts.
  if (!findCount (header, "landmarks", landmarks) ||
      !findCount (header, "descriptors", descriptors) ||
      !findNumber (header, "diameter", diameter) || landmarks < 1 ||
      landmarks > descriptors || !(diameter >= 0.0) ||
      diameter > static_cast<double> (std::numeric_limits<float>::max()))
    return fail (
        "'" + path +
            "' lacks landmarks (at least 1), descriptors (at least as many) or "
            "a diameter (at least 0)",
        model,
        box);
  if (!readBox (header, box))
    return fail (
        "'" + path + "' has a malformed box (" + MODEL_BOX_RULE + ")", model, box);
  const std::string data_path = dataPathOf (path);
  pcl::PointCloud<ModelFilePoint> rows;
  pcl::PCLPointCloud2 blob;
  std::string problem;
  if (!io::readCheckedPCD (
          data_path, blob, rows.sensor_origin_, rows.sensor_orientation_, problem))
    return fail ("cannot read the model data: " + problem, model, box);
  const auto hasField =
      [&blob] (const char* name, std::uint8_t datatype, std::uint32_t count) {
        const int index = pcl::getFieldIndex (blob, name);
        return index >= 0 &&
               blob.fields[static_cast<std::size_t> (index)].datatype == datatype &&
               blob.fields[static_cast<std::size_t> (index)].count == count;
      };
  if (!hasField ("landmark", pcl::PCLPointField::INT32, 1) ||
      !hasField ("descriptor", pcl::PCLPointField::FLOAT32, 128))
    return fail ("'" + data_path +
                     "' is not model data (it needs an int landmark and 128 float "
                     "descriptor values per row)",
                 model,
                 box);
  try {
    pcl::fromPCLPointCloud2 (blob, rows);
  }
  catch (const std::exception&) {
    return fail (
        "'" + data_path + "' could not be converted (out of memory)", model, box);
  }
  if (rows.size() != descriptors)
    return fail ("'" + data_path + "' holds " + std::to_string (rows.size()) +
                     " descriptors, the header says " + std::to_string (descriptors) +
                     " (truncated or inconsistent)",
                 model,
                 box);
  model.landmarks.resize (static_cast<std::size_t> (landmarks));
  std::vector<bool> seen (model.landmarks.size(), false);
  for (const auto& row : rows) {
    if (row.landmark < 0 ||
        static_cast<std::size_t> (row.landmark) >= model.landmarks.size() ||
        !row.getVector3fMap().allFinite())
      return fail ("'" + data_path + "' refers to landmark " +
                       std::to_string (row.landmark) + " of " +
                       std::to_string (model.landmarks.size()) + " or holds NaN",
                   model,
                   box);
    auto& landmark = model.landmarks[static_cast<std::size_t> (row.landmark)];
    landmark.getVector3fMap() = row.getVector3fMap();
    landmark.getNormalVector3fMap() = row.getNormalVector3fMap();
    seen[static_cast<std::size_t> (row.landmark)] = true;
    SIFTDescriptor descriptor;
    std::copy (row.descriptor, row.descriptor + 128, descriptor.histogram);
    model.descriptors.push_back (descriptor);
    model.descriptor_landmarks.push_back (row.landmark);
  }
  if (std::find (seen.begin(), seen.end(), false) != seen.end())
    return fail ("'" + data_path + "' lacks some landmarks", model, box);
  model.diameter = static_cast<float> (diameter);
  return true;
}

} // namespace mid
