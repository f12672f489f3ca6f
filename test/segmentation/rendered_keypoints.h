#pragma once

#include "rendered_objects_scene.h"

#include <mid/features/sift_keypoint_extractor.h>
#include <mid/registration/object_model.h>
#include <mid/segmentation/photometric_verification.h>

#include <gtest/gtest.h>
#include <pcl/common/io.h>

#include <functional>
#include <memory>
#include <set>
#include <vector>

namespace mid {
namespace test {

/** \brief Two prints of the textures folder, and one box size for both. */
///@{
constexpr const char* kApplePrint = "tropicana_apple_juice_front.jpg";
constexpr const char* kSoyPrint = "alpro_soya_front.jpg";
const Eigen::Vector3d kPrintedBoxSize{0.12, 0.09, 0.04};
///@}

/** \brief A rendered scene with its SIFT keypoints and what the surface steps read: the
  * descriptors, the image keypoints, the keypoint surface with its grey levels, and the box
  * under each keypoint from the truth.
  */
struct RenderedKeypoints
{
  RenderedObjectsScene scene;
  KeypointCloud::Ptr keypoints = pcl::make_shared<KeypointCloud>();
  SIFTDescriptorCloud::Ptr descriptors = pcl::make_shared<SIFTDescriptorCloud>();
  ImageKeypoints image_keypoints;
  KeypointSurface surface;
  std::vector<int> box_of; ///< per keypoint, the box it lies on (-1: the table)

  explicit RenderedKeypoints (RenderedObjectsScene rendered)
  : scene (std::move (rendered))
  {
    SIFTKeypointExtractor<pcl::PointXYZRGBA> extractor;
    extractor.setInputCloud (scene.cloud);
    EXPECT_TRUE (extractor.compute (*keypoints, *descriptors));
    image_keypoints = extractor.getImageKeypoints();
    auto points = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
    pcl::copyPointCloud (*scene.cloud, *points);
    pcl::PointCloud<pcl::PointXYZRGB> colour;
    pcl::copyPointCloud (*scene.cloud, colour);
    surface.organized = points;
    surface.intensity =
        std::make_shared<const std::vector<float>> (greyLevels (colour));
    surface.keypoint_pixels = mid::pixelIndices (image_keypoints);
    for (const auto& k : image_keypoints)
      box_of.push_back (boxUnderKeypoints (scene, {{k.u, k.v}}));
  }

  /** \brief The keypoints on the given boxes (-1: the table). */
  pcl::Indices
  on (const std::set<int>& boxes) const
  {
    pcl::Indices indices;
    for (std::size_t k = 0; k < box_of.size(); ++k)
      if (boxes.count (box_of[k]) > 0)
        indices.push_back (static_cast<pcl::index_t> (k));
    return indices;
  }

  /** \brief Add box `b` to `model` as an instance at its true pose (the model frame is the
    * box's own frame): each keypoint on the box becomes a landmark, with its descriptor; with
    * `keep`, only those whose position in the box's frame it keeps.
    */
  void
  addTruthInstance (std::size_t b,
                    ObjectModel& model,
                    const std::function<bool (const Eigen::Vector3f&)>& keep = {}) const
  {
    ModelInstance instance;
    instance.pose = scene.boxes[b].pose.matrix().cast<float>();
    const Eigen::Affine3f to_model (instance.pose.inverse());
    for (std::size_t k = 0; k < keypoints->size(); ++k) {
      if (box_of[k] != static_cast<int> (b))
        continue;
      pcl::PointNormal landmark = (*keypoints)[k];
      landmark.getVector3fMap() = to_model * (*keypoints)[k].getVector3fMap();
      if (keep && !keep (landmark.getVector3fMap()))
        continue;
      landmark.getNormalVector3fMap() =
          to_model.linear() * (*keypoints)[k].getNormalVector3fMap();
      instance.keypoints.push_back (static_cast<pcl::index_t> (k));
      instance.landmarks.push_back (static_cast<int> (model.landmarks.size()));
      model.descriptor_landmarks.push_back (instance.landmarks.back());
      model.landmarks.push_back (landmark);
      model.descriptors.push_back ((*descriptors)[k]);
    }
    model.instances.push_back (instance);
    updateModelDiameter (model);
  }

  /** \brief The box all of an instance's keypoints lie on, or -1. */
  int
  boxOf (const pcl::Indices& instance_keypoints) const
  {
    std::set<int> boxes;
    for (const auto k : instance_keypoints)
      boxes.insert (box_of[static_cast<std::size_t> (k)]);
    return boxes.size() == 1 ? *boxes.begin() : -1;
  }
};

} // namespace test
} // namespace mid
