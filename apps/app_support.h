#pragma once

// What the command-line apps share: reading the scene from the command line, printing a
// result, and writing the result JSON, model files and pictures all-or-nothing.

#include "strict_options.h"

#include <mid/discovery/discovery_result.h>
#include <mid/io/camera_intrinsics.h>
#include <mid/io/staged_files.h>
#include <mid/registration/object_model_io.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <string>

namespace mid {
namespace apps {

using PointT = pcl::PointXYZRGBA;

/** \brief The scene of a command line: an organized PCD, or color + depth + intrinsics. */
struct SceneInput
{
  std::string pcd_path;
  std::string color_path;
  std::string depth_path;
  io::CameraIntrinsics intrinsics;

  /** \brief The file that names the scene (the PCD or the color image). */
  const std::string&
  name () const
  {
    return pcd_path.empty() ? color_path : pcd_path;
  }
};

/** \brief Print the help lines of the scene options. */
void
printSceneInputHelp ();

/** \brief The scene options (for onlyKnownArguments; SCENE.pcd is a file argument). */
OptionSpecs
sceneInputOptions ();

/** \brief Read the scene options; false after a one-line error if they are unusable. */
bool
parseSceneInput (int argc, char** argv, SceneInput& input);

/** \brief Load the scene; false after a one-line error (PCL_ERROR) if it is unusable. */
bool
loadScene (const SceneInput& input, pcl::PointCloud<PointT>& cloud);

/** \brief The files an app writes: the result JSON and, optionally, one model file pair per
  * object. They are staged before the work, so that a missing or unwritable folder fails at once,
  * and committed together at the end.
  */
class ResultFiles
{
public:
  /** \brief Stage the outputs; false after a one-line error if a folder is unusable. */
  bool
  stage (const std::string& json_path, const std::string& model_prefix);

  /** \brief Stage one more output that the app writes itself (an image), committed with the
    * others.
    * \return the temporary path to write it to; empty after a one-line error if its folder is
    * missing or not writable
    */
  std::string
  stageFile (const std::string& path)
  {
    return files_.stage (path);
  }

  /** \brief Save a model (saveObjectModel()) under temporary names, committed by write() with
    * the other outputs; false after a one-line error.
    */
  bool
  saveModel (const std::string& path, const ObjectModel& model, const ModelSize& box)
  {
    return saveObjectModel (path, model, box, &files_);
  }

  /** \brief Whether a file can be written at `path` (its folder exists and is writable);
    * false after a one-line error.
    */
  static bool
  canStage (const std::string& path)
  {
    return !io::StagedFiles().stage (path).empty();
  }

  /** \brief Whether the result JSON gives each instance's "group" (formatDiscoveryJson();
    * default true: discovery). The detect app sets false: its instances are each posed on the
    * stored model by their own matches.
    */
  ///@{
  void
  setInstanceGroups (bool written)
  {
    groups_ = written;
  }
  bool
  getInstanceGroups () const
  {
    return groups_;
  }
  ///@}

  /** \brief Write and commit everything; false after a one-line error. */
  bool
  write (const DiscoveryResult& result, const std::string& input_name);

private:
  io::StagedFiles files_;
  std::string json_path_;
  std::string json_temporary_;
  std::string model_prefix_;
  bool groups_ = true;
};

/** \brief Print the counts, objects and timings of a result. */
void
printResult (const pcl::PointCloud<PointT>& cloud,
             const DiscoveryResult& result,
             double load_ms);

} // namespace apps
} // namespace mid
