#pragma once

#include <mid/io/staged_files.h>
#include <mid/simulation/bop_ground_truth.h>
#include <mid/simulation/product_catalog.h>
#include <mid/simulation/rendered_frame.h>
#include <mid/simulation/scene.h>

#include <string>
#include <vector>

namespace mid {
namespace simulation {

/** \brief Depth unit of the depth PNGs written by BopSceneWriter: 0.1 mm, BOP depth_scale 0.1
  * (millimetres per unit), metres per unit 1e-4; 6.5 m at most.
  */
constexpr double BOP_DEPTH_SCALE_MM = 0.1;

/** \brief Writes the frames of one scene folder of a BOP dataset (https://bop.felk.cvut.cz,
  * format of BOP 2019-2023):
  *
  * \verbatim
  * FOLDER/scene_camera.json   {"<image>": {"cam_K": [fx, 0, cx, 0, fy, cy, 0, 0, 1],
  *                                          "depth_scale": 0.1}, ...}
  * FOLDER/scene_gt.json       {"<image>": [{"cam_R_m2c": [9, row-major],
  *                                          "cam_t_m2c": [3, millimetres], "obj_id": 1}, ...]}
  * FOLDER/scene_gt_info.json  {"<image>": [{"bbox_obj": [x, y, w, h], "bbox_visib": [...],
  *                                          "px_count_all": n, "px_count_valid": n,
  *                                          "px_count_visib": n, "visib_fract": f}, ...]}
  * FOLDER/rgb/<image>.png             colour, 8-bit
  * FOLDER/depth/<image>.png           depth, 16-bit, units of depth_scale millimetres
  * FOLDER/mask_visib/<image>_<k>.png  visible pixels of ground-truth entry k (255), 8-bit
  * FOLDER/pcd/<image>.pcd             organized XYZRGB cloud in metres (binary compressed),
  *                                    the depth PNG back-projected: pcl_multi_instance_discovery
  *                                    reads it
  * \endverbatim
  *
  * with <image> = %06d of the image id (the keys of the JSON files are the ids without
  * padding). Entry k of an image is scene object k; poses are model-to-camera, the model frame
  * being the shape's (centred on the product). Every file is staged in the given StagedFiles
  * and appears only when the caller commits it, so a dataset is written all or nothing.
  *
  * \code
  * mid::io::StagedFiles files;
  * mid::simulation::BopSceneWriter writer ("dataset/000000", files);
  * writer.addFrame (0, frame, scene, product_ids, info);   // for each image
  * if (!writer.stageJSON () || !files.commit ()) ...
  * \endcode
  */
class BopSceneWriter
{
public:
  /** \brief A writer for one scene folder (created, with its sub-folders, by addFrame()). */
  BopSceneWriter (const std::string& folder, io::StagedFiles& files);

  /** \brief Stage the images and the cloud of one frame and remember its ground truth.
    * \param[in] image_id image id (0 .. 999999), not added before
    * \param[in] frame the frame (colour, depth as measured, exact instance map)
    * \param[in] scene the scene it was rendered from
    * \param[in] object_ids BOP obj_id of each scene object
    * \param[in] info computeBopInstanceInfo() of the frame
    * \return false (with a PCL_ERROR) if an argument does not fit or a file cannot be written
    */
  bool
  addFrame (int image_id,
            const RenderedFrame& frame,
            const Scene& scene,
            const std::vector<int>& object_ids,
            const std::vector<BopInstanceInfo>& info);

  /** \brief Stage scene_camera.json, scene_gt.json and scene_gt_info.json of the frames added.
    * \return false (with a PCL_ERROR) if no frame was added or a file cannot be written
    */
  bool
  stageJSON ();

  /** \brief The scene folder. */
  const std::string&
  getFolder () const
  {
    return folder_;
  }

private:
  std::string folder_;
  io::StagedFiles& files_;
  /** \brief One JSON member per image, in the order added. */
  std::vector<std::string> camera_entries_, gt_entries_, info_entries_;
  std::vector<int> image_ids_;
};

/** \brief models_info.json of a catalog (keyed by obj_id, millimetres): diameter (of the
  * model's bounding box), min_x/y/z and size_x/y/z as in BOP, the product's name, and, as BOP
  * lists them, the global symmetries of its shape (Shape::getSymmetries(); texture not
  * considered): "symmetries_discrete" (4 x 4 row-major) and "symmetries_continuous" (axis and
  * offset), each left out when the shape has none.
  */
std::string
formatBopModelsInfo (const ProductCatalog& catalog);

} // namespace simulation
} // namespace mid
