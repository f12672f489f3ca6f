#define PCL_NO_PRECOMPILE
#include <mid/io/pcd_reader.h>
#include <mid/registration/object_model_io.h>

#include <pcl/common/io.h>
#include <pcl/console/print.h>
#include <pcl/conversions.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>
#include <pcl/register_point_struct.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <regex>
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
fail (const std::string& message, ObjectModel& model)
{
  PCL_ERROR ("[mid::loadObjectModel] %s\n", message.c_str());
  model = ObjectModel();
  return false;
}

/** The value of "key": number in a flat JSON object written by saveObjectModel(). */
bool
findNumber (const std::string& json, const std::string& key, double& value)
{
  std::smatch match;
  if (!std::regex_search (json, match, std::regex ("\"" + key + "\": (-?[0-9.eE+-]+)")))
    return false;
  value = std::stod (match[1]);
  return true;
}

} // namespace

bool
saveObjectModel (const std::string& path,
                 const ObjectModel& model,
                 io::StagedFiles* staged)
{
  if (std::filesystem::path (path).extension() != ".json") {
    PCL_ERROR ("[mid::saveObjectModel] '%s' must end in .json\n", path.c_str());
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
       << ",\n  \"diameter\": " << model.diameter << "\n}\n";
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
  model = ObjectModel();
  std::ifstream file (path);
  if (!file)
    return fail ("cannot open '" + path + "' (missing or unreadable)", model);
  std::stringstream text;
  text << file.rdbuf();
  const std::string json = text.str();
  if (json.find (R"("format": "mid-object-model")") == std::string::npos)
    return fail ("'" + path +
                     R"(' is not a mid object model (no "format": "mid-object-model"))",
                 model);
  double version = 0.0, landmarks = 0.0, descriptors = 0.0, diameter = 0.0;
  if (!findNumber (json, "version", version) ||
      !findNumber (json, "landmarks", landmarks) ||
      !findNumber (json, "descriptors", descriptors) ||
      !findNumber (json, "diameter", diameter))
    return fail (
        "'" + path +
            "' is truncated or lacks version, landmarks, descriptors or diameter",
        model);
  if (static_cast<int> (version) != OBJECT_MODEL_FILE_VERSION)
    return fail ("'" + path + "' is a model file of version " +
                     std::to_string (static_cast<int> (version)) +
                     "; this build reads version " +
                     std::to_string (OBJECT_MODEL_FILE_VERSION),
                 model);
  const std::string data_path = dataPathOf (path);
  pcl::PointCloud<ModelFilePoint> rows;
  pcl::PCLPointCloud2 blob;
  std::string problem;
  if (!io::readCheckedPCD (
          data_path, blob, rows.sensor_origin_, rows.sensor_orientation_, problem))
    return fail ("cannot read the model data: " + problem, model);
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
                 model);
  try {
    pcl::fromPCLPointCloud2 (blob, rows);
  }
  catch (const std::exception&) {
    return fail ("'" + data_path + "' could not be converted (out of memory)", model);
  }
  if (rows.size() != static_cast<std::size_t> (descriptors) || landmarks < 1.0)
    return fail ("'" + data_path + "' holds " + std::to_string (rows.size()) +
                     " descriptors, the header says " +
                     std::to_string (static_cast<long> (descriptors)) +
                     " (truncated or inconsistent)",
                 model);
  model.landmarks.resize (static_cast<std::size_t> (landmarks));
  std::vector<bool> seen (model.landmarks.size(), false);
  for (const auto& row : rows) {
    if (row.landmark < 0 ||
        static_cast<std::size_t> (row.landmark) >= model.landmarks.size() ||
        !row.getVector3fMap().allFinite())
      return fail ("'" + data_path + "' refers to landmark " +
                       std::to_string (row.landmark) + " of " +
                       std::to_string (model.landmarks.size()) + " or holds NaN",
                   model);
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
    return fail ("'" + data_path + "' lacks some landmarks", model);
  model.diameter = static_cast<float> (diameter);
  return true;
}

} // namespace mid
