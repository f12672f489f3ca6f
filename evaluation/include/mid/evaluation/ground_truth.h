#pragma once

#include <Eigen/Core>
#include <Eigen/StdVector>
#include <opencv2/core/mat.hpp>

#include <map>
#include <string>
#include <vector>

namespace mid {
namespace evaluation {

/** \brief One annotated object instance of a frame (a BOP ground-truth entry). */
struct GroundTruthInstance
{
  /** \brief Object type (BOP obj_id). */
  int object_id = 0;
  /** \brief Model -> camera pose, metres. */
  Eigen::Matrix4f pose = Eigen::Matrix4f::Identity();
  /** \brief Visible part: bounding box (x, y, width, height) and, when available, the mask
    * (CV_8UC1, non-zero = visible); the mask decides when present, the box otherwise.
    */
  ///@{
  cv::Rect bbox_visible;
  cv::Mat mask_visible;
  ///@}
  /** \brief Visible pixels. */
  int visible_pixels = 0;
  /** \brief Visible surface this instance shares with another annotated instance of its type,
    * in cubes of a grid in the model frame (see measureSharedSurface() in shared_surface.h);
    * -1 while not measured.
    */
  int shared_surface_cells = -1;

  EIGEN_MAKE_ALIGNED_OPERATOR_NEW
};

/** \brief The annotations of one frame. */
struct GroundTruthFrame
{
  /** \brief The frame's BOP image id. */
  int image_id = 0;
  /** \brief Its annotated instances, in the order of scene_gt.json. */
  std::vector<GroundTruthInstance, Eigen::aligned_allocator<GroundTruthInstance>>
      instances;

  /** \brief True if pixel (u, v) lies on the visible part of instance k.
    * \param[in] k the instance, < instances.size () (not checked)
    * \param[in] u, v column and row, in pixels (rounded to the nearest pixel)
    * \return whether the mask, or without a mask the box, holds the pixel; false outside the
    * image
    */
  bool
  contains (std::size_t k, float u, float v) const;
};

/** \brief The annotated frames of one BOP scene folder, by image id. */
using GroundTruthScene = std::map<int, GroundTruthFrame>;

/** \brief Read a BOP scene folder: scene_gt.json (poses; cam_t_m2c in millimetres), and, when
  * present, scene_gt_info.json (visible boxes and pixel counts) and mask_visib/ (visible masks,
  * `<image>_<instance>.png`).
  * \param[in] folder the scene folder (e.g. .../test/000001)
  * \param[out] scene the frames; cleared on failure
  * \return false (with a PCL_ERROR naming the file and the problem) if scene_gt.json is missing
  * or malformed, or a referenced mask cannot be read
  */
bool
loadBopScene (const std::string& folder, GroundTruthScene& scene);

} // namespace evaluation
} // namespace mid
