#pragma once

#include <mid/simulation/pinhole_camera.h>

#include <opencv2/core/mat.hpp>

#include <vector>

namespace mid {
namespace simulation {

/** \brief What one scene object shows in a frame. */
struct InstanceStats
{
  /** \brief Number of pixels whose centre ray hits the object first. */
  int visible_pixels = 0;
  /** \brief Bounding box of those pixels (x, y, width, height); empty if none is visible. */
  cv::Rect bbox;
};

/** \brief One rendered RGB-D frame with its exact ground truth. All images are
  * camera.height x camera.width and refer to the ray through each pixel's centre, except the
  * colour, which may average several rays per pixel (SceneRenderer::setSupersampling()).
  */
struct RenderedFrame
{
  /** \brief The camera the frame was rendered with. */
  PinholeCamera camera;
  /** \brief Colour image, 8-bit BGR (CV_8UC3). */
  cv::Mat color;
  /** \brief Depth (z, not ray length) in metres (CV_32FC1); 0 where there is no measurement. */
  cv::Mat depth;
  /** \brief Instance id map (CV_32SC1): the index of the scene object seen at each pixel, -1
    * for the background objects (table) and for empty space. It stays the exact truth after
    * applySensorModel(), which may remove depth under it.
    */
  cv::Mat instances;
  /** \brief Unit surface normals in the camera frame, facing the camera (CV_32FC3, x y z);
    * (0, 0, 0) where the ray hits nothing.
    */
  cv::Mat normals;
  /** \brief Per scene object (indexed like Scene::getObjects()): visible pixels and bbox. */
  std::vector<InstanceStats> instance_stats;

  /** \brief Release all images and statistics (the camera is kept). */
  void
  clear ()
  {
    color.release();
    depth.release();
    instances.release();
    normals.release();
    instance_stats.clear();
  }
};

} // namespace simulation
} // namespace mid
