#pragma once

#include <mid/io/camera_intrinsics.h>

#include <pcl/visualization/pcl_visualizer.h>

namespace mid {
namespace visualization {

/** \brief Where the RGB-D camera's image lies in a viewport that looks through that camera: the
  * whole image, scaled by `scale` (viewport pixels per image pixel, the largest that fits) and
  * centred, i.e. image pixel (u, v) (pixel centres at whole numbers) covers the viewport pixel
  * whose centre is at (offset_u + (u + 0.5) * scale - 0.5, offset_v + (v + 0.5) * scale - 0.5),
  * counted from the viewport's top left corner.
  */
struct ImageFit
{
  /** \brief Viewport pixels per image pixel. */
  double scale = 1.0;
  /** \brief Viewport pixels left of and above the image (the bands that letterbox it). */
  ///@{
  double offset_u = 0.0;
  double offset_v = 0.0;
  ///@}
};

/** \brief Fit an image into a viewport (see ImageFit); the identity when the sizes agree.
  * \param[in] image_width image width, pixels
  * \param[in] image_height image height, pixels
  * \param[in] viewport_width viewport width, pixels
  * \param[in] viewport_height viewport height, pixels
  * \return the fit; scale 0 if a size is not positive
  */
ImageFit
fitImage (int image_width, int image_height, int viewport_width, int viewport_height);

/** \brief Make a viewport of a PCLVisualizer look through the RGB-D camera.
  *
  * The VTK camera is put at the origin, looking along +z with +y pointing down the screen (the
  * camera frame of the point cloud), with the view angle and window centre chosen so that a 3D
  * point projects where the pinhole model puts it (u = fx * x / z + cx, v = fy * y / z + cy),
  * mapped into the viewport by fitImage(). VTK's pixels are square: the vertical scale follows
  * fy, and the horizontal one matches only as far as fx equals fy. The clipping range is reset to
  * the viewport's props, so call this after adding them. Set the render window's size first; the
  * fit is computed from it and the viewport's extent, and is not updated when the window is
  * resized later.
  * \param[in,out] viewer the visualizer
  * \param[in] intrinsics fx, fy, cx, cy of the camera, pixels
  * \param[in] image_width width of the camera's image, pixels
  * \param[in] image_height height of the camera's image, pixels
  * \param[in] viewport the viewport's index in the viewer's renderer collection (the id that
  * PCLVisualizer::createViewPort() returned; 0 is the visualizer's first renderer)
  * \return false (with a PCL_ERROR) if the viewport does not exist or a size or focal length is
  * not positive
  */
bool
setCameraView (pcl::visualization::PCLVisualizer& viewer,
               const io::CameraIntrinsics& intrinsics,
               int image_width,
               int image_height,
               int viewport);

} // namespace visualization
} // namespace mid
