#include "json_file.h"

#include <mid/evaluation/shared_surface.h>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iterator>
#include <limits>
#include <vector>

namespace mid {
namespace evaluation {

namespace {

namespace fs = std::filesystem;

/** True if pixel (x, y) and its eight neighbours all lie on the visible part of instance k: the
  * mask eroded by one pixel, so that mixed depth at the silhouette does not count.
  */
bool
insideVisiblePart (const GroundTruthFrame& frame, std::size_t k, int x, int y)
{
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx)
      if (!frame.contains (k, static_cast<float> (x + dx), static_cast<float> (y + dy)))
        return false;
  return true;
}

/** One key per grid cube: its three indices, 21 bits each (cubes within +-10 km at 1 cm). */
std::uint64_t
cellKey (const Eigen::Vector3f& point, float cell_size)
{
  const auto index = [cell_size] (float v) {
    return static_cast<std::uint64_t> (
               static_cast<std::int64_t> (std::floor (v / cell_size)) + (1 << 20)) &
           0x1FFFFFu;
  };
  return (index (point.x()) << 42) | (index (point.y()) << 21) | index (point.z());
}

/** A cube of the model-frame grid that an instance shows, with the mean surface normal there
  * and the mean direction towards the camera (unit vectors in the model frame).
  */
struct SeenCell
{
  std::uint64_t key = 0;
  Eigen::Vector3f normal = Eigen::Vector3f::Zero();
  Eigen::Vector3f view = Eigen::Vector3f::Zero();
  /** Sum and number of the local contrasts of its pixels whose window lies on the instance. */
  float contrast_sum = 0.0f;
  int contrast_pixels = 0;
  /** True if the view shows texture there (or no contrast test is asked for). */
  bool textured = true;
};

/** Half the edge of the window of the local contrast (5 x 5 pixels). */
constexpr int kContrastRadius = 2;

/** The local contrast of every pixel: the standard deviation of the grey levels (0 to 255) in
  * the (2 kContrastRadius + 1)^2 window around it.
  */
cv::Mat
localContrast (const cv::Mat& image)
{
  cv::Mat grey;
  if (image.channels() == 3)
    cv::cvtColor (image, grey, cv::COLOR_BGR2GRAY);
  else
    grey = image;
  cv::Mat value, mean, square_mean;
  grey.convertTo (value, CV_32FC1);
  const cv::Size window (2 * kContrastRadius + 1, 2 * kContrastRadius + 1);
  cv::boxFilter (value, mean, CV_32FC1, window);
  cv::boxFilter (value.mul (value), square_mean, CV_32FC1, window);
  cv::Mat variance = square_mean - mean.mul (mean);
  cv::Mat contrast;
  cv::sqrt (cv::max (variance, 0.0), contrast);
  return contrast;
}

/** Pixel step of the central differences that give a pixel's surface normal. */
constexpr int kNormalStep = 2;

/** The camera-frame point and unit surface normal (towards the camera) of every pixel of
  * instance k's visible part (the mask eroded by one pixel) whose depth and the depth of the
  * four pixels kNormalStep away on the instance are known; NaN elsewhere. Both CV_32FC3.
  */
void
pointsAndNormals (const GroundTruthFrame& frame,
                  std::size_t k,
                  const cv::Mat& depth,
                  const Eigen::Matrix3f& intrinsics,
                  cv::Mat& points,
                  cv::Mat& normals)
{
  const float nan = std::numeric_limits<float>::quiet_NaN();
  points = cv::Mat (depth.size(), CV_32FC3, cv::Scalar (nan, nan, nan));
  normals = points.clone();
  const float fx = intrinsics (0, 0), fy = intrinsics (1, 1), cx = intrinsics (0, 2),
              cy = intrinsics (1, 2);
  const auto point = [&] (int x, int y, Eigen::Vector3f& p) {
    if (x < 0 || y < 0 || x >= depth.cols || y >= depth.rows ||
        !frame.contains (k, static_cast<float> (x), static_cast<float> (y)))
      return false;
    const float z = depth.at<float> (y, x);
    p = Eigen::Vector3f ((static_cast<float> (x) - cx) * z / fx,
                         (static_cast<float> (y) - cy) * z / fy,
                         z);
    return std::isfinite (z) && z > 0.0f;
  };
  const GroundTruthInstance& instance = frame.instances[k];
  const cv::Rect area =
      (instance.mask_visible.empty() ? instance.bbox_visible
                                     : cv::Rect (0, 0, depth.cols, depth.rows)) &
      cv::Rect (0, 0, depth.cols, depth.rows);
  for (int y = area.y; y < area.y + area.height; ++y)
    for (int x = area.x; x < area.x + area.width; ++x) {
      Eigen::Vector3f p, left, right, up, down;
      if (!point (x, y, p) || !insideVisiblePart (frame, k, x, y) ||
          !point (x - kNormalStep, y, left) || !point (x + kNormalStep, y, right) ||
          !point (x, y - kNormalStep, up) || !point (x, y + kNormalStep, down))
        continue;
      Eigen::Vector3f normal = (right - left).cross (down - up);
      if (!(normal.norm() > 0.0f))
        continue;
      normal *= normal.dot (p) < 0.0f ? 1.0f : -1.0f; // towards the camera
      normal.normalize();
      points.at<cv::Vec3f> (y, x) = cv::Vec3f (p.x(), p.y(), p.z());
      normals.at<cv::Vec3f> (y, x) = cv::Vec3f (normal.x(), normal.y(), normal.z());
    }
}

/** True if the contrast window around (x, y) lies on instance k's visible pixels only, so that
  * neither the background nor an occluder adds to its contrast. A crease between two faces of
  * different shading does count: the depth of a Kinect-like sensor is too coarse to tell it
  * from a printed edge, and the count stays an upper bound.
  */
bool
windowOnInstance (const GroundTruthFrame& frame, std::size_t k, int x, int y)
{
  for (int dy = -kContrastRadius; dy <= kContrastRadius; ++dy)
    for (int dx = -kContrastRadius; dx <= kContrastRadius; ++dx)
      if (!frame.contains (k, static_cast<float> (x + dx), static_cast<float> (y + dy)))
        return false;
  return true;
}

/** The sorted cubes of the model frame that instance k's visible pixels fall in
  * (pointsAndNormals()). With a contrast image (localContrast()), a cube is textured where the
  * mean contrast of its pixels whose window is on the instance (windowOnInstance()) reaches
  * min_contrast; without, every cube is.
  */
std::vector<SeenCell>
visibleCells (const GroundTruthFrame& frame,
              std::size_t k,
              const cv::Mat& depth,
              const Eigen::Matrix3f& intrinsics,
              float cell_size,
              const cv::Mat& contrast,
              float min_contrast)
{
  cv::Mat points, normals;
  pointsAndNormals (frame, k, depth, intrinsics, points, normals);
  const GroundTruthInstance& instance = frame.instances[k];
  const Eigen::Matrix3f to_model = instance.pose.topLeftCorner<3, 3>().transpose();
  const Eigen::Vector3f translation = instance.pose.topRightCorner<3, 1>();
  std::vector<SeenCell> seen;
  for (int y = 0; y < points.rows; ++y)
    for (int x = 0; x < points.cols; ++x) {
      const cv::Vec3f& p = points.at<cv::Vec3f> (y, x);
      if (!std::isfinite (p[0]))
        continue;
      const Eigen::Vector3f point (p[0], p[1], p[2]);
      const cv::Vec3f& n = normals.at<cv::Vec3f> (y, x);
      SeenCell cell;
      cell.key = cellKey (to_model * (point - translation), cell_size);
      cell.normal = to_model * Eigen::Vector3f (n[0], n[1], n[2]);
      cell.view = -(to_model * point.normalized());
      if (!contrast.empty() && windowOnInstance (frame, k, x, y)) {
        cell.contrast_sum = contrast.at<float> (y, x);
        cell.contrast_pixels = 1;
      }
      seen.push_back (cell);
    }
  std::sort (seen.begin(), seen.end(), [] (const SeenCell& a, const SeenCell& b) {
    return a.key < b.key;
  });
  std::vector<SeenCell> cells;
  for (const SeenCell& cell : seen)
    if (!cells.empty() && cells.back().key == cell.key) {
      cells.back().normal += cell.normal;
      cells.back().view += cell.view;
      cells.back().contrast_sum += cell.contrast_sum;
      cells.back().contrast_pixels += cell.contrast_pixels;
    }
    else
      cells.push_back (cell);
  for (SeenCell& cell : cells) {
    cell.normal.normalize();
    cell.view.normalize();
    cell.textured =
        contrast.empty() ||
        (cell.contrast_pixels > 0 &&
         cell.contrast_sum >= min_contrast * static_cast<float> (cell.contrast_pixels));
  }
  return cells;
}

/** The transition tilt between two views of a surface patch with unit normal n (Morel and Yu,
  * ASIFT, 2009): the largest foreshortening of the affine map between the two images, from the
  * absolute tilts t = 1 / cos (view, n) of each view and the angle between the views' longitudes
  * (their projections onto the patch).
  */
double
transitionTilt (const Eigen::Vector3f& n,
                const Eigen::Vector3f& a,
                const Eigen::Vector3f& b)
{
  constexpr double kMinCosine = 0.05; // beyond 87 deg the tilt is capped at 20
  const double t = 1.0 / std::max (kMinCosine, static_cast<double> (n.dot (a)));
  const double s = 1.0 / std::max (kMinCosine, static_cast<double> (n.dot (b)));
  const Eigen::Vector3f pa = a - a.dot (n) * n, pb = b - b.dot (n) * n;
  const auto norms = static_cast<double> (pa.norm() * pb.norm());
  const double cosine = norms > 1e-9 ? static_cast<double> (pa.dot (pb)) / norms : 1.0;
  const double cos2 = std::min (1.0, cosine * cosine);
  // tau + 1 / tau = (t / s + s / t) cos^2 phi + (t s + 1 / (t s)) sin^2 phi
  const double c = (t / s + s / t) * cos2 + (t * s + 1.0 / (t * s)) * (1.0 - cos2);
  return 0.5 * (c + std::sqrt (std::max (0.0, c * c - 4.0)));
}

/** The cubes both a and b show, textured in both views, with a transition tilt of at most
  * max_tilt between the views.
  */
std::size_t
commonCount (const std::vector<SeenCell>& a,
             const std::vector<SeenCell>& b,
             float max_tilt)
{
  std::size_t count = 0;
  for (auto i = a.begin(), j = b.begin(); i != a.end() && j != b.end();) {
    if (i->key < j->key)
      ++i;
    else if (j->key < i->key)
      ++j;
    else {
      const Eigen::Vector3f normal = (i->normal + j->normal).normalized();
      count += i->textured && j->textured &&
                       transitionTilt (normal, i->view, j->view) <= max_tilt
                   ? 1
                   : 0;
      ++i;
      ++j;
    }
  }
  return count;
}

void
clearMeasurements (GroundTruthFrame& frame)
{
  for (auto& instance : frame.instances)
    instance.shared_surface_cells = -1;
}

/** The file name of a BOP image: its six-digit number and the extension. */
std::string
imageName (int image, const char* extension)
{
  char name[32];
  std::snprintf (name, sizeof (name), "%06d%s", image, extension);
  return name;
}

} // namespace

bool
measureSharedSurface (const cv::Mat& depth,
                      const Eigen::Matrix3f& intrinsics,
                      float cell_size,
                      float max_transition_tilt,
                      GroundTruthFrame& frame)
{
  return measureSharedSurface (
      depth, cv::Mat(), intrinsics, cell_size, max_transition_tilt, 0.0f, frame);
}

bool
measureSharedSurface (const cv::Mat& depth,
                      const cv::Mat& image,
                      const Eigen::Matrix3f& intrinsics,
                      float cell_size,
                      float max_transition_tilt,
                      float min_contrast,
                      GroundTruthFrame& frame)
{
  clearMeasurements (frame);
  if (depth.empty() || depth.type() != CV_32FC1) {
    PCL_ERROR (
        "[mid::evaluation::measureSharedSurface] the depth image must be a non-empty "
        "CV_32FC1 image (metres).\n");
    return false;
  }
  if (!(intrinsics (0, 0) != 0.0f && intrinsics (1, 1) != 0.0f) ||
      !intrinsics.allFinite()) {
    PCL_ERROR (
        "[mid::evaluation::measureSharedSurface] the camera matrix has no usable "
        "focal length.\n");
    return false;
  }
  if (!(cell_size > 0.0f) || !std::isfinite (cell_size)) {
    PCL_ERROR (
        "[mid::evaluation::measureSharedSurface] cell_size is %g, must be a positive "
        "number of metres.\n",
        static_cast<double> (cell_size));
    return false;
  }
  if (!(max_transition_tilt >= 1.0f)) {
    PCL_ERROR (
        "[mid::evaluation::measureSharedSurface] max_transition_tilt is %g, must be "
        "1 or more.\n",
        static_cast<double> (max_transition_tilt));
    return false;
  }
  if (!(min_contrast >= 0.0f) || !std::isfinite (min_contrast)) {
    PCL_ERROR ("[mid::evaluation::measureSharedSurface] min_contrast is %g, must be 0 "
               "(no texture test) or a positive number of grey levels.\n",
               static_cast<double> (min_contrast));
    return false;
  }
  if (min_contrast > 0.0f && (image.size() != depth.size() || image.depth() != CV_8U ||
                              (image.channels() != 1 && image.channels() != 3))) {
    PCL_ERROR (
        "[mid::evaluation::measureSharedSurface] the texture test needs an 8-bit "
        "grey or BGR image of the depth image's size (%d x %d); the image is %d x "
        "%d with %d channels.\n",
        depth.cols,
        depth.rows,
        image.cols,
        image.rows,
        image.channels());
    return false;
  }
  for (std::size_t k = 0; k < frame.instances.size(); ++k) {
    const cv::Mat& mask = frame.instances[k].mask_visible;
    if (!mask.empty() && mask.size() != depth.size()) {
      PCL_ERROR (
          "[mid::evaluation::measureSharedSurface] the mask of instance %zu is %d x "
          "%d pixels, the depth image %d x %d.\n",
          k,
          mask.cols,
          mask.rows,
          depth.cols,
          depth.rows);
      return false;
    }
  }
  const cv::Mat contrast = min_contrast > 0.0f ? localContrast (image) : cv::Mat();
  std::vector<std::vector<SeenCell>> cells;
  cells.reserve (frame.instances.size());
  for (std::size_t k = 0; k < frame.instances.size(); ++k)
    cells.push_back (
        visibleCells (frame, k, depth, intrinsics, cell_size, contrast, min_contrast));
  for (std::size_t a = 0; a < frame.instances.size(); ++a) {
    std::size_t shared = 0;
    for (std::size_t b = 0; b < frame.instances.size(); ++b)
      if (b != a && frame.instances[b].object_id == frame.instances[a].object_id)
        shared =
            std::max (shared, commonCount (cells[a], cells[b], max_transition_tilt));
    frame.instances[a].shared_surface_cells = static_cast<int> (shared);
  }
  return true;
}

bool
measureSharedSurface (const std::string& folder,
                      float cell_size,
                      float max_transition_tilt,
                      float min_contrast,
                      GroundTruthScene& scene)
{
  const auto fail = [&scene] {
    for (auto& entry : scene)
      clearMeasurements (entry.second);
    return false;
  };
  const fs::path root (folder);
  nlohmann::json cameras;
  if (!detail::readJsonFile (
          root / "scene_camera.json", "mid::evaluation::measureSharedSurface", cameras))
    return fail();
  for (auto& [image, frame] : scene) {
    Eigen::Matrix3f intrinsics;
    double depth_scale = 1.0;
    char key[16];
    std::snprintf (key, sizeof (key), "%d", image);
    try {
      const auto& camera = cameras.at (key);
      const auto k = camera.at ("cam_K").get<std::vector<double>>();
      if (k.size() != 9)
        throw std::runtime_error ("cam_K needs 9 values");
      intrinsics =
          Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> (k.data())
              .cast<float>();
      depth_scale = camera.value ("depth_scale", 1.0);
    }
    catch (const std::exception& error) {
      PCL_ERROR ("[mid::evaluation::measureSharedSurface] '%s', image %d: %s\n",
                 (root / "scene_camera.json").string().c_str(),
                 image,
                 error.what());
      return fail();
    }
    const fs::path depth_path = root / "depth" / imageName (image, ".png");
    const cv::Mat raw = cv::imread (depth_path.string(), cv::IMREAD_ANYDEPTH);
    if (raw.empty() || raw.type() != CV_16UC1) {
      PCL_ERROR (
          "[mid::evaluation::measureSharedSurface] '%s' is missing or not a 16-bit "
          "depth image.\n",
          depth_path.string().c_str());
      return fail();
    }
    cv::Mat metres;
    raw.convertTo (metres, CV_32FC1, depth_scale / 1000.0);
    cv::Mat colour;
    if (min_contrast > 0.0f) {
      // BOP datasets store their colour images as PNG or JPEG.
      const fs::path png = root / "rgb" / imageName (image, ".png");
      const fs::path jpg = root / "rgb" / imageName (image, ".jpg");
      colour = cv::imread ((fs::exists (png) ? png : jpg).string(), cv::IMREAD_COLOR);
      if (colour.empty()) {
        PCL_ERROR ("[mid::evaluation::measureSharedSurface] '%s' is missing or not an "
                   "image (the texture test needs the colour images).\n",
                   png.string().c_str());
        return fail();
      }
    }
    if (!measureSharedSurface (metres,
                               colour,
                               intrinsics,
                               cell_size,
                               max_transition_tilt,
                               min_contrast,
                               frame))
      return fail();
  }
  return true;
}

} // namespace evaluation
} // namespace mid
