#include <mid/simulation/bop_scene_writer.h>
#include <mid/simulation/frame_io.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <pcl/console/print.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <system_error>

namespace mid {
namespace simulation {

namespace {

/** Metres per unit of the depth PNGs. */
constexpr double kDepthUnit = BOP_DEPTH_SCALE_MM * 0.001;

/** A number as JSON: 12 significant digits, rounding errors of zero written as 0. */
std::string
number (double value)
{
  if (!std::isfinite (value))
    return "null";
  if (std::abs (value) < 1e-12)
    return "0";
  char buffer[32];
  std::snprintf (buffer, sizeof (buffer), "%.12g", value);
  return buffer;
}

std::string
list (const std::vector<double>& values)
{
  std::string out = "[";
  for (std::size_t i = 0; i < values.size(); ++i)
    out += (i == 0 ? "" : ", ") + number (values[i]);
  return out + "]";
}

std::string
box (const cv::Rect& rect)
{
  return list ({static_cast<double> (rect.x),
                static_cast<double> (rect.y),
                static_cast<double> (rect.width),
                static_cast<double> (rect.height)});
}

std::string
paddedId (int id)
{
  char name[16];
  std::snprintf (name, sizeof (name), "%06d", id);
  return name;
}

/** {"<key>": value, ...} with one member per line. */
std::string
object (const std::vector<std::string>& keys, const std::vector<std::string>& values)
{
  std::string out = "{\n";
  for (std::size_t i = 0; i < keys.size(); ++i)
    out += "  \"" + keys[i] + "\": " + values[i] + (i + 1 < keys.size() ? ",\n" : "\n");
  return out + "}\n";
}

bool
fail (const std::string& message)
{
  PCL_ERROR ("[mid::simulation::BopSceneWriter] %s\n", message.c_str());
  return false;
}

bool
stageText (io::StagedFiles& files, const std::string& path, const std::string& text)
{
  const std::string temporary = files.stage (path);
  if (temporary.empty())
    return false;
  std::ofstream file (temporary, std::ios::binary | std::ios::trunc);
  file << text;
  file.close();
  return file ? true : fail ("cannot write '" + path + "'");
}

bool
stageImage (io::StagedFiles& files, const std::string& path, const cv::Mat& image)
{
  const std::string temporary = files.stage (path);
  if (temporary.empty())
    return false;
  bool written = false;
  try {
    written = cv::imwrite (temporary, image);
  }
  catch (const cv::Exception&) {
    written = false;
  }
  return written ? true : fail ("cannot write '" + path + "'");
}

std::string
groundTruthEntry (const SceneObject& object, int object_id)
{
  const Eigen::Matrix3d rotation = object.pose.linear();
  const Eigen::Vector3d translation = 1000.0 * object.pose.translation();
  std::vector<double> r;
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col)
      r.push_back (rotation (row, col));
  return "{\"cam_R_m2c\": " + list (r) + ", \"cam_t_m2c\": " +
         list ({translation.x(), translation.y(), translation.z()}) +
         ", \"obj_id\": " + std::to_string (object_id) + "}";
}

std::string
infoEntry (const BopInstanceInfo& info)
{
  return "{\"bbox_obj\": " + box (info.bbox_obj) +
         ", \"bbox_visib\": " + box (info.bbox_visib) +
         ", \"px_count_all\": " + std::to_string (info.px_count_all) +
         ", \"px_count_valid\": " + std::to_string (info.px_count_valid) +
         ", \"px_count_visib\": " + std::to_string (info.px_count_visib) +
         ", \"visib_fract\": " + number (info.visib_fract) + "}";
}

std::string
array (const std::vector<std::string>& entries)
{
  std::string out = "[";
  for (std::size_t i = 0; i < entries.size(); ++i)
    out += (i == 0 ? "" : ", ") + entries[i];
  return out + "]";
}

/** BOP's symmetry members of models_info.json, each with its leading comma; empty without
  * symmetries: "symmetries_discrete" as 4 x 4 row-major motions (millimetres, here rotations
  * about the origin), "symmetries_continuous" as axes with a zero offset.
  */
std::string
symmetryMembers (const ShapeSymmetries& symmetries)
{
  std::string members;
  if (!symmetries.discrete.empty()) {
    std::vector<std::string> motions;
    for (const Eigen::Matrix3d& rotation : symmetries.discrete) {
      std::vector<double> values;
      for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
          values.push_back (r < 3 && c < 3 ? rotation (r, c) : (r == c ? 1.0 : 0.0));
      motions.push_back (list (values));
    }
    members += ", \"symmetries_discrete\": " + array (motions);
  }
  if (!symmetries.continuous_axes.empty()) {
    std::vector<std::string> axes;
    for (const Eigen::Vector3d& axis : symmetries.continuous_axes)
      axes.push_back ("{\"axis\": " + list ({axis.x(), axis.y(), axis.z()}) +
                      ", \"offset\": [0, 0, 0]}");
    members += ", \"symmetries_continuous\": " + array (axes);
  }
  return members;
}

} // namespace

BopSceneWriter::BopSceneWriter (const std::string& folder, io::StagedFiles& files)
: folder_ (folder), files_ (files)
{}

bool
BopSceneWriter::addFrame (int image_id,
                          const RenderedFrame& frame,
                          const Scene& scene,
                          const std::vector<int>& object_ids,
                          const std::vector<BopInstanceInfo>& info)
{
  const std::size_t objects = scene.getObjects().size();
  if (image_id < 0 || image_id > 999999 ||
      std::find (image_ids_.begin(), image_ids_.end(), image_id) != image_ids_.end())
    return fail ("image id " + std::to_string (image_id) +
                 " is out of [0, 999999] or was added before");
  if (object_ids.size() != objects || info.size() != objects ||
      frame.instance_stats.size() != objects || frame.instances.type() != CV_32SC1)
    return fail (
        "the object ids, the statistics and the frame do not belong to the scene");
  std::error_code error;
  for (const char* sub : {"rgb", "depth", "mask_visib", "pcd"})
    std::filesystem::create_directories (std::filesystem::path (folder_) / sub, error);
  if (error)
    return fail ("cannot create the folders of '" + folder_ + "'");

  const std::string name = paddedId (image_id);
  cv::Mat depth_16u;
  pcl::PointCloud<pcl::PointXYZRGB> cloud;
  if (!quantizeDepth (frame.depth, kDepthUnit, depth_16u) ||
      !frameToCloud (frame, kDepthUnit, cloud) ||
      !stageImage (files_, folder_ + "/rgb/" + name + ".png", frame.color) ||
      !stageImage (files_, folder_ + "/depth/" + name + ".png", depth_16u))
    return false;
  const std::string pcd_path = folder_ + "/pcd/" + name + ".pcd";
  const std::string pcd_temporary = files_.stage (pcd_path);
  if (pcd_temporary.empty() ||
      pcl::io::savePCDFileBinaryCompressed (pcd_temporary, cloud) != 0)
    return fail ("cannot write '" + pcd_path + "'");

  std::vector<std::string> gt, stats;
  for (std::size_t k = 0; k < objects; ++k) {
    const cv::Mat mask = frame.instances == static_cast<int> (k);
    if (!stageImage (files_,
                     folder_ + "/mask_visib/" + name + "_" +
                         paddedId (static_cast<int> (k)) + ".png",
                     mask))
      return false;
    gt.push_back (groundTruthEntry (scene.getObjects()[k], object_ids[k]));
    stats.push_back (infoEntry (info[k]));
  }
  const PinholeCamera& camera = frame.camera;
  camera_entries_.push_back (
      "{\"cam_K\": " +
      list ({camera.fx, 0.0, camera.cx, 0.0, camera.fy, camera.cy, 0.0, 0.0, 1.0}) +
      ", \"depth_scale\": " + number (BOP_DEPTH_SCALE_MM) + "}");
  gt_entries_.push_back (array (gt));
  info_entries_.push_back (array (stats));
  image_ids_.push_back (image_id);
  return true;
}

bool
BopSceneWriter::stageJSON()
{
  if (image_ids_.empty())
    return fail ("no frame was added to '" + folder_ + "'");
  std::vector<std::string> keys;
  for (const int id : image_ids_)
    keys.push_back (std::to_string (id));
  return stageText (
             files_, folder_ + "/scene_camera.json", object (keys, camera_entries_)) &&
         stageText (files_, folder_ + "/scene_gt.json", object (keys, gt_entries_)) &&
         stageText (
             files_, folder_ + "/scene_gt_info.json", object (keys, info_entries_));
}

std::string
formatBopModelsInfo (const ProductCatalog& catalog)
{
  std::vector<std::string> keys, values;
  for (const ProductType& product : catalog) {
    const Eigen::Vector3d size = 1000.0 * product.size;
    keys.push_back (std::to_string (product.id));
    values.push_back (
        R"({"name": ")" + product.shape->getName() + R"(", "diameter": )" +
        number (size.norm()) + ", \"min_x\": " + number (-0.5 * size.x()) +
        ", \"min_y\": " + number (-0.5 * size.y()) + ", \"min_z\": " +
        number (-0.5 * size.z()) + ", \"size_x\": " + number (size.x()) +
        ", \"size_y\": " + number (size.y()) + ", \"size_z\": " + number (size.z()) +
        symmetryMembers (product.shape->getSymmetries()) + "}");
  }
  return object (keys, values);
}

} // namespace simulation
} // namespace mid
