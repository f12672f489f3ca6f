#include <mid/visualization/camera_view.h>

#include <pcl/console/print.h>
#include <vtkCamera.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>
#include <vtkRenderWindow.h>

#include <algorithm>
#include <cmath>

namespace mid {
namespace visualization {

ImageFit
fitImage (int image_width, int image_height, int viewport_width, int viewport_height)
{
  ImageFit fit;
  if (image_width <= 0 || image_height <= 0 || viewport_width <= 0 ||
      viewport_height <= 0) {
    fit.scale = 0.0;
    return fit;
  }
  fit.scale = std::min (static_cast<double> (viewport_width) / image_width,
                        static_cast<double> (viewport_height) / image_height);
  fit.offset_u = 0.5 * (viewport_width - fit.scale * image_width);
  fit.offset_v = 0.5 * (viewport_height - fit.scale * image_height);
  return fit;
}

bool
setCameraView (pcl::visualization::PCLVisualizer& viewer,
               const io::CameraIntrinsics& intrinsics,
               int image_width,
               int image_height,
               int viewport)
{
  vtkRendererCollection* renderers = viewer.getRendererCollection();
  vtkRenderer* renderer =
      viewport >= 0 && viewport < renderers->GetNumberOfItems()
          ? vtkRenderer::SafeDownCast (renderers->GetItemAsObject (viewport))
          : nullptr;
  if (renderer == nullptr) {
    PCL_ERROR ("[mid::visualization::setCameraView] no viewport %d\n", viewport);
    return false;
  }
  // The viewport's size in pixels, from the window's size (also before the window is shown).
  const int* window_size = viewer.getRenderWindow()->GetSize();
  const double* extent = renderer->GetViewport();
  const int width =
      static_cast<int> (std::lround ((extent[2] - extent[0]) * window_size[0]));
  const int height =
      static_cast<int> (std::lround ((extent[3] - extent[1]) * window_size[1]));
  const ImageFit fit = fitImage (image_width, image_height, width, height);
  if (!(fit.scale > 0.0) || !(intrinsics.fx > 0.0) || !(intrinsics.fy > 0.0)) {
    PCL_ERROR ("[mid::visualization::setCameraView] unusable sizes or focal lengths "
               "(image %d x "
               "%d, viewport %d x %d, fx %g, fy %g)\n",
               image_width,
               image_height,
               width,
               height,
               intrinsics.fx,
               intrinsics.fy);
    return false;
  }
  // VTK's perspective maps a point to normalized viewport coordinates
  //   x_n = (x / z) / (tan (angle / 2) * width / height) - center_x,
  //   y_n = (-y / z) / tan (angle / 2) - center_y      (y points down, the screen's up is -y),
  // and the pinhole model with the fit puts it at the viewport pixel (top left origin)
  //   offset_u + (fx * x / z + cx + 0.5) * scale, offset_v + (fy * y / z + cy + 0.5) * scale.
  // Equating both for every point gives the angle and the window centre below.
  const double tangent = height / (2.0 * fit.scale * intrinsics.fy);
  const double center_x =
      1.0 - 2.0 * (fit.offset_u + (intrinsics.cx + 0.5) * fit.scale) / width;
  const double center_y =
      2.0 * (fit.offset_v + (intrinsics.cy + 0.5) * fit.scale) / height - 1.0;
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition (0.0, 0.0, 0.0);
  camera->SetFocalPoint (0.0, 0.0, 1.0);
  camera->SetViewUp (0.0, -1.0, 0.0);
  camera->SetUseHorizontalViewAngle (0);
  camera->SetViewAngle (2.0 * std::atan (tangent) * 180.0 / M_PI);
  camera->SetWindowCenter (center_x, center_y);
  renderer->ResetCameraClippingRange();
  return true;
}

} // namespace visualization
} // namespace mid
