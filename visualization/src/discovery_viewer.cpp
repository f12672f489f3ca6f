#include <mid/visualization/display.h>
#include <mid/visualization/impl/discovery_viewer.hpp>

#include <pcl/point_types.h>
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkErrorCode.h>
#include <vtkLogger.h>
#include <vtkPNGWriter.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>
#include <vtkRenderWindow.h>
#include <vtkSmartPointer.h>
#include <vtkWindowToImageFilter.h>

#include <filesystem>
#include <memory>
#include <system_error>
#include <unistd.h>

namespace mid {
namespace visualization {
namespace detail {

namespace {

vtkRenderer*
rendererOf (pcl::visualization::PCLVisualizer& viewer, int viewport)
{
  vtkRendererCollection* renderers = viewer.getRendererCollection();
  if (viewport < 0 || viewport >= renderers->GetNumberOfItems())
    return nullptr;
  return vtkRenderer::SafeDownCast (renderers->GetItemAsObject (viewport));
}

/** One object alone in its own frame, seen from its reference camera turned a little, so that
  * its depth shows; with its frame and a caption.
  */
void
addModel (pcl::visualization::PCLVisualizer& viewer,
          const ObjectModel& model,
          std::size_t object,
          int viewport,
          int row_height)
{
  const ObjectColor color = objectColor (object);
  const std::string suffix = std::to_string (object);
  viewer.setBackgroundColor (0.13, 0.13, 0.16, viewport);
  const auto points = posedPoints (model.landmarks, Eigen::Matrix4f::Identity(), 0.0f);
  const pcl::visualization::PointCloudColorHandlerCustom<pcl::PointXYZ> colors (
      points, color.r, color.g, color.b);
  viewer.addPointCloud<pcl::PointXYZ> (points, colors, "model_" + suffix, viewport);
  viewer.setPointCloudRenderingProperties (
      pcl::visualization::PCL_VISUALIZER_POINT_SIZE,
      landmarkPointSize (1.0),
      "model_" + suffix);
  viewer.addCoordinateSystem (
      kFrameAxes, Eigen::Affine3f::Identity(), "model_frame_" + suffix, viewport);
  constexpr int kFont = 13, kMargin = 6;
  const std::string caption = "object " + suffix + ": " +
                              std::to_string (model.instances.size()) + " instances, " +
                              std::to_string (model.landmarks.size()) + " landmarks";
  viewer.addText (caption,
                  kMargin,
                  std::max (0, row_height - kFont - kMargin),
                  kFont,
                  color.r / 255.0,
                  color.g / 255.0,
                  color.b / 255.0,
                  "caption_" + suffix,
                  viewport);

  vtkRenderer* renderer = rendererOf (viewer, viewport);
  if (renderer == nullptr)
    return;
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition (0.0, 0.0, -1.0);
  camera->SetFocalPoint (0.0, 0.0, 0.0);
  camera->SetViewUp (0.0, -1.0, 0.0);
  camera->Azimuth (30.0);
  camera->Elevation (20.0);
  camera->OrthogonalizeViewUp();
  renderer->ResetCamera();
  camera->Zoom (1.3);
}

/** VTK 9.1 warns on stderr, at every render, that its own shader code calls deprecated methods;
  * while we render, only VTK's errors reach stderr.
  */
class QuietVtkWarnings
{
public:
  QuietVtkWarnings() : previous_ (vtkLogger::GetCurrentVerbosityCutoff())
  {
    vtkLogger::SetStderrVerbosity (vtkLogger::VERBOSITY_ERROR);
  }
  ~QuietVtkWarnings() { vtkLogger::SetStderrVerbosity (previous_); }
  QuietVtkWarnings (const QuietVtkWarnings&) = delete;
  QuietVtkWarnings&
  operator= (const QuietVtkWarnings&) = delete;

private:
  vtkLogger::Verbosity previous_;
};

/** A PCLVisualizer whose window uses our display connection, so that VTK never opens one
  * itself (it aborts the program when that fails).
  */
std::unique_ptr<pcl::visualization::PCLVisualizer>
makeVisualizer (const DisplayConnection& display,
                const std::string& name,
                bool interactive)
{
  const auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetDisplayId (display.get());
  window->SetOffScreenRendering (interactive ? 0 : 1);
  const auto renderer = vtkSmartPointer<vtkRenderer>::New();
  return std::make_unique<pcl::visualization::PCLVisualizer> (
      renderer, window, name, interactive);
}

/** Render the viewer's window and write it as a PNG. */
bool
saveWindowPNG (const char* caller,
               pcl::visualization::PCLVisualizer& viewer,
               const std::string& path)
{
  // VTK reports an unwritable file on stderr over several lines; check the folder first.
  const std::filesystem::path destination (path);
  const std::filesystem::path folder = destination.has_parent_path()
                                           ? destination.parent_path()
                                           : std::filesystem::path (".");
  std::error_code error;
  if (!std::filesystem::is_directory (folder, error) ||
      ::access (folder.c_str(), W_OK) != 0) {
    PCL_ERROR ("[%s] cannot write '%s': folder '%s' is missing or not writable\n",
               caller,
               path.c_str(),
               folder.string().c_str());
    return false;
  }
  vtkRenderWindow* window = viewer.getRenderWindow();
  window->Render();
  const auto grabber = vtkSmartPointer<vtkWindowToImageFilter>::New();
  grabber->SetInput (window);
  grabber->SetInputBufferTypeToRGB();
  grabber->ReadFrontBufferOff();
  grabber->Update();
  const auto writer = vtkSmartPointer<vtkPNGWriter>::New();
  writer->SetFileName (path.c_str());
  writer->SetInputConnection (grabber->GetOutputPort());
  writer->Write();
  if (writer->GetErrorCode() != vtkErrorCode::NoError) {
    PCL_ERROR ("[%s] cannot write '%s'\n", caller, path.c_str());
    return false;
  }
  return true;
}

} // namespace

pcl::PointCloud<pcl::PointXYZ>::Ptr
posedPoints (const KeypointCloud& points, const Eigen::Matrix4f& pose, float shift)
{
  auto posed = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  posed->reserve (points.size());
  for (const auto& point : points) {
    Eigen::Vector3f p = pose.topLeftCorner<3, 3>() * point.getVector3fMap() +
                        pose.topRightCorner<3, 1>();
    const float distance = p.norm();
    if (!std::isfinite (distance))
      continue;
    if (distance > shift)
      p *= (distance - shift) / distance;
    posed->push_back (pcl::PointXYZ (p.x(), p.y(), p.z()));
  }
  return posed;
}

void
addModelPanel (pcl::visualization::PCLVisualizer& viewer,
               const ObjectModels& models,
               double left,
               int height)
{
  const auto rows = static_cast<double> (models.size());
  for (std::size_t m = 0; m < models.size(); ++m) {
    int viewport = 0;
    const auto row = static_cast<double> (m);
    viewer.createViewPort (
        left, 1.0 - (row + 1.0) / rows, 1.0, 1.0 - row / rows, viewport);
    viewer.createViewPortCamera (viewport);
    addModel (viewer, models[m], m, viewport, static_cast<int> (height / rows));
  }
}

void
addBox (pcl::visualization::PCLVisualizer& viewer,
        const Eigen::Matrix4f& box_to_camera,
        const Eigen::Vector3f& size,
        const ObjectColor& color,
        const std::string& id,
        int viewport)
{
  using namespace pcl::visualization;
  const Eigen::Matrix3f rotation = box_to_camera.topLeftCorner<3, 3>();
  if (!viewer.addCube (Eigen::Vector3f (box_to_camera.topRightCorner<3, 1>()),
                       Eigen::Quaternionf (rotation),
                       size.x(),
                       size.y(),
                       size.z(),
                       id,
                       viewport))
    return;
  viewer.setShapeRenderingProperties (PCL_VISUALIZER_REPRESENTATION,
                                      PCL_VISUALIZER_REPRESENTATION_WIREFRAME,
                                      id,
                                      viewport);
  viewer.setShapeRenderingProperties (PCL_VISUALIZER_COLOR,
                                      color.r / 255.0,
                                      color.g / 255.0,
                                      color.b / 255.0,
                                      id,
                                      viewport);
  viewer.setShapeRenderingProperties (
      PCL_VISUALIZER_LINE_WIDTH, kBoxLineWidth, id, viewport);
  // Unlit, its colour all ambient: every edge in the object's colour exactly, whichever way
  // its faces turn (PCL's shapes add a diffuse term that brightens it).
  const auto shape = viewer.getShapeActorMap()->find (id);
  if (shape != viewer.getShapeActorMap()->end())
    if (auto* actor = vtkActor::SafeDownCast (shape->second)) {
      actor->GetProperty()->LightingOff();
      actor->GetProperty()->SetAmbient (1.0);
      actor->GetProperty()->SetDiffuse (0.0);
      actor->GetProperty()->SetSpecular (0.0);
    }
}

int
addOverlayLayer (pcl::visualization::PCLVisualizer& viewer, int viewport)
{
  vtkRenderer* base = rendererOf (viewer, viewport);
  if (base == nullptr)
    return viewport;
  const auto overlay = vtkSmartPointer<vtkRenderer>::New();
  overlay->SetLayer (1);
  overlay->SetInteractive (0);
  overlay->SetViewport (base->GetViewport());
  overlay->SetActiveCamera (base->GetActiveCamera());
  vtkRenderWindow* window = viewer.getRenderWindow();
  window->SetNumberOfLayers (std::max (2, window->GetNumberOfLayers()));
  window->AddRenderer (overlay);
  vtkRendererCollection* renderers = viewer.getRendererCollection();
  renderers->AddItem (overlay);
  return renderers->GetNumberOfItems() - 1;
}

bool
lookAt (pcl::visualization::PCLVisualizer& viewer,
        const Eigen::Vector3f& position,
        const Eigen::Vector3f& target,
        int viewport)
{
  vtkRenderer* renderer = rendererOf (viewer, viewport);
  if (renderer == nullptr || !position.allFinite() ||
      (target - position).norm() < 1e-6f) {
    PCL_ERROR (
        "[mid::visualization::DiscoveryViewer] unusable viewpoint (%g, %g, %g)\n",
        static_cast<double> (position.x()),
        static_cast<double> (position.y()),
        static_cast<double> (position.z()));
    return false;
  }
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition (position.x(), position.y(), position.z());
  camera->SetFocalPoint (target.x(), target.y(), target.z());
  camera->SetViewUp (0.0, -1.0, 0.0);
  camera->OrthogonalizeViewUp();
  camera->SetWindowCenter (0.0, 0.0);
  renderer->ResetCameraClippingRange();
  return true;
}

bool
renderOffScreen (
    const char* caller,
    const std::string& path,
    const std::function<bool (pcl::visualization::PCLVisualizer&)>& populate)
{
  const DisplayConnection display;
  if (!display.isOpen()) {
    PCL_ERROR (
        "[%s] no X display (DISPLAY unset or unreachable); run under xvfb-run -a\n",
        caller);
    return false;
  }
  const QuietVtkWarnings quiet;
  const auto viewer = makeVisualizer (display, "mid", false);
  return populate (*viewer) && saveWindowPNG (caller, *viewer, path);
}

bool
renderInteractive (
    const char* caller,
    const std::function<bool (pcl::visualization::PCLVisualizer&)>& populate)
{
  const DisplayConnection display;
  if (!display.isOpen()) {
    PCL_ERROR ("[%s] no X display (DISPLAY unset or unreachable)\n", caller);
    return false;
  }
  const QuietVtkWarnings quiet;
  const auto viewer = makeVisualizer (display, "mid: multi-instance discovery", true);
  if (!populate (*viewer))
    return false;
  viewer->spin();
  viewer->close();
  return true;
}

} // namespace detail

template class DiscoveryViewer<pcl::PointXYZRGB>;
template class DiscoveryViewer<pcl::PointXYZRGBA>;

} // namespace visualization
} // namespace mid
