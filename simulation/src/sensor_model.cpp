#include <mid/simulation/deterministic_random.h>
#include <mid/simulation/sensor_model.h>

#include <opencv2/imgproc.hpp>
#include <pcl/console/print.h>

#include <cmath>

namespace mid {
namespace simulation {

namespace {

constexpr double kPi = 3.14159265358979323846;

/** One independent random stream per effect, so that switching one effect on or off does not
  * change the numbers the others draw.
  */
enum RandomStream : std::uint32_t {
  DISCONTINUITY_STREAM = 1,
  HOLE_STREAM = 2,
  DROPOUT_STREAM = 3,
  DEPTH_NOISE_STREAM = 4,
  IMAGE_NOISE_STREAM = 5
};

bool
fail (const std::string& message, RenderedFrame& output)
{
  PCL_ERROR ("[mid::simulation::applySensorModel] %s\n", message.c_str());
  output.clear();
  return false;
}

bool
isProbability (double value)
{
  return value >= 0.0 && value <= 1.0;
}

bool
checkFrame (const RenderedFrame& frame, bool need_normals, std::string& problem)
{
  if (!validateCamera (frame.camera, problem))
    return false;
  const cv::Size size (frame.camera.width, frame.camera.height);
  if (frame.color.type() != CV_8UC3 || frame.color.size() != size)
    problem =
        "the frame's colour image is missing or is not 8-bit BGR of the camera's size";
  else if (frame.depth.type() != CV_32FC1 || frame.depth.size() != size)
    problem =
        "the frame's depth image is missing or is not CV_32FC1 of the camera's size";
  else if (need_normals &&
           (frame.normals.type() != CV_32FC3 || frame.normals.size() != size))
    problem =
        "the incidence angle needs the frame's normals (CV_32FC3 of the camera's size)";
  return problem.empty();
}

/** Whether depths a and b (0 = none) form a discontinuity; if so, sets which one is farther. */
inline bool
isDiscontinuity (float a, float b, double threshold, bool& a_is_farther)
{
  if ((a > 0.0f) != (b > 0.0f)) {
    a_is_farther = a > 0.0f;
    return true;
  }
  if (a > 0.0f && std::abs (a - b) > threshold) {
    a_is_farther = a > b;
    return true;
  }
  return false;
}

/** Remove depth in a band of model.discontinuity_width pixels on the far side of every depth
  * discontinuity, each pixel with probability model.discontinuity_dropout.
  */
void
removeDiscontinuities (const SensorModel& model, std::uint32_t seed, cv::Mat& depth)
{
  const double threshold = model.discontinuity_threshold;
  cv::Mat band = cv::Mat::zeros (depth.size(), CV_8UC1);
  bool first_farther = false;
  for (int v = 0; v < depth.rows; ++v)
    for (int u = 0; u < depth.cols; ++u) {
      const float z = depth.at<float> (v, u);
      if (u + 1 < depth.cols &&
          isDiscontinuity (z, depth.at<float> (v, u + 1), threshold, first_farther))
        band.at<std::uint8_t> (v, first_farther ? u : u + 1) = 1;
      if (v + 1 < depth.rows &&
          isDiscontinuity (z, depth.at<float> (v + 1, u), threshold, first_farther))
        band.at<std::uint8_t> (first_farther ? v : v + 1, u) = 1;
    }
  // Widen the band onto the same (far) surface only: grow into neighbours of similar depth.
  const int offsets[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  for (int step = 1; step < model.discontinuity_width; ++step) {
    cv::Mat grown = band.clone();
    for (int v = 0; v < depth.rows; ++v)
      for (int u = 0; u < depth.cols; ++u) {
        const float z = depth.at<float> (v, u);
        if (band.at<std::uint8_t> (v, u) || z <= 0.0f)
          continue;
        for (const auto& offset : offsets) {
          const int nu = u + offset[0], nv = v + offset[1];
          if (nu < 0 || nv < 0 || nu >= depth.cols || nv >= depth.rows ||
              !band.at<std::uint8_t> (nv, nu))
            continue;
          if (std::abs (depth.at<float> (nv, nu) - z) <= threshold) {
            grown.at<std::uint8_t> (v, u) = 1;
            break;
          }
        }
      }
    band = grown;
  }
  DeterministicRandom random (seed, DISCONTINUITY_STREAM);
  for (int v = 0; v < depth.rows; ++v)
    for (int u = 0; u < depth.cols; ++u)
      if (band.at<std::uint8_t> (v, u) &&
          random.uniform() < model.discontinuity_dropout)
        depth.at<float> (v, u) = 0.0f;
}

/** Remove depth where the viewing ray meets the surface at more than the maximum incidence. */
void
removeGrazing (const SensorModel& model, const RenderedFrame& frame, cv::Mat& depth)
{
  const double min_cosine = std::cos (model.max_incidence_angle * kPi / 180.0);
  for (int v = 0; v < depth.rows; ++v)
    for (int u = 0; u < depth.cols; ++u) {
      auto& z = depth.at<float> (v, u);
      if (z <= 0.0f)
        continue;
      const auto& n = frame.normals.at<cv::Vec3f> (v, u);
      const Eigen::Vector3d ray = pixelRay (frame.camera, u, v);
      const double cosine =
          std::abs (n[0] * ray.x() + n[1] * ray.y() + n[2] * ray.z()) / ray.norm();
      if (cosine < min_cosine)
        z = 0.0f;
    }
}

void
punchHoles (const SensorModel& model, std::uint32_t seed, cv::Mat& depth)
{
  DeterministicRandom random (seed, HOLE_STREAM);
  for (int hole = 0; hole < model.hole_count; ++hole) {
    const double center_u = random.uniform (0.0, depth.cols);
    const double center_v = random.uniform (0.0, depth.rows);
    const double radius = random.uniform (1.0, model.hole_max_radius);
    const int v_begin = std::max (0, static_cast<int> (std::floor (center_v - radius)));
    const int v_end =
        std::min (depth.rows - 1, static_cast<int> (std::ceil (center_v + radius)));
    const int u_begin = std::max (0, static_cast<int> (std::floor (center_u - radius)));
    const int u_end =
        std::min (depth.cols - 1, static_cast<int> (std::ceil (center_u + radius)));
    for (int v = v_begin; v <= v_end; ++v)
      for (int u = u_begin; u <= u_end; ++u)
        if ((u - center_u) * (u - center_u) + (v - center_v) * (v - center_v) <=
            radius * radius)
          depth.at<float> (v, u) = 0.0f;
  }
}

void
dropRandomPixels (const SensorModel& model, std::uint32_t seed, cv::Mat& depth)
{
  DeterministicRandom random (seed, DROPOUT_STREAM);
  for (int v = 0; v < depth.rows; ++v) {
    auto* row = depth.ptr<float> (v);
    for (int u = 0; u < depth.cols; ++u)
      if (random.uniform() < model.random_dropout)
        row[u] = 0.0f;
  }
}

/** Noise, then quantization, of every valid depth. */
void
perturbDepth (const SensorModel& model, std::uint32_t seed, cv::Mat& depth)
{
  DeterministicRandom random (seed, DEPTH_NOISE_STREAM);
  for (int v = 0; v < depth.rows; ++v) {
    auto* row = depth.ptr<float> (v);
    for (int u = 0; u < depth.cols; ++u) {
      if (row[u] <= 0.0f)
        continue;
      double z = row[u];
      if (model.depth_noise)
        z += depthNoiseSigma (model, z) * random.normal();
      if (z > 0.0 && model.disparity_quantization > 0.0) {
        const double step = model.disparity_quantization;
        const double inverse = std::round (1.0 / z / step) * step;
        z = inverse > 0.0 ? 1.0 / inverse : 0.0;
      }
      if (z > 0.0 && model.depth_quantization > 0.0)
        z = std::round (z / model.depth_quantization) * model.depth_quantization;
      row[u] = z > 0.0 ? static_cast<float> (z) : 0.0f;
    }
  }
}

void
perturbColor (const SensorModel& model, std::uint32_t seed, cv::Mat& color)
{
  if (model.image_blur_sigma > 0.0)
    cv::GaussianBlur (color,
                      color,
                      cv::Size (0, 0),
                      model.image_blur_sigma,
                      model.image_blur_sigma,
                      cv::BORDER_REFLECT_101);
  if (model.image_noise_sigma <= 0.0)
    return;
  DeterministicRandom random (seed, IMAGE_NOISE_STREAM);
  for (int v = 0; v < color.rows; ++v) {
    auto* row = color.ptr<cv::Vec3b> (v);
    for (int u = 0; u < color.cols; ++u)
      for (int channel = 0; channel < 3; ++channel)
        row[u][channel] = cv::saturate_cast<uchar> (
            row[u][channel] + model.image_noise_sigma * random.normal());
  }
}

} // namespace

SensorModel
kinectSensorModel ()
{
  SensorModel model;
  model.depth_noise = true;
  model.disparity_quantization = 1.0 / (8.0 * 580.0 * 0.075);
  model.discontinuity_threshold = 0.02;
  model.discontinuity_width = 2;
  model.discontinuity_dropout = 0.8;
  model.max_incidence_angle = 78.0;
  model.hole_count = 6;
  model.hole_max_radius = 5.0;
  model.random_dropout = 0.002;
  model.image_blur_sigma = 0.6;
  model.image_noise_sigma = 2.0;
  return model;
}

bool
validateSensorModel (const SensorModel& model, std::string& problem)
{
  problem.clear();
  const double values[] = {model.noise_sigma_base,
                           model.noise_sigma_quadratic,
                           model.noise_reference_depth,
                           model.disparity_quantization,
                           model.depth_quantization,
                           model.discontinuity_threshold,
                           model.discontinuity_dropout,
                           model.max_incidence_angle,
                           model.hole_max_radius,
                           model.random_dropout,
                           model.image_blur_sigma,
                           model.image_noise_sigma};
  for (const double value : values)
    if (!std::isfinite (value)) {
      problem = "the sensor model contains a non-finite value";
      return false;
    }
  if (model.noise_sigma_base < 0.0 || model.noise_sigma_quadratic < 0.0)
    problem = "the depth noise coefficients must be non-negative";
  else if (model.disparity_quantization < 0.0 || model.depth_quantization < 0.0)
    problem = "the quantization steps must be non-negative (0 = off)";
  else if (model.discontinuity_threshold < 0.0)
    problem = "the discontinuity threshold must be non-negative (0 = off)";
  else if (model.discontinuity_width < 1)
    problem = "the discontinuity width must be at least 1 pixel";
  else if (!isProbability (model.discontinuity_dropout) ||
           !isProbability (model.random_dropout))
    problem = "the dropout probabilities must be in [0, 1]";
  else if (!(model.max_incidence_angle > 0.0))
    problem = "the maximum incidence angle must be positive (90 or more = off)";
  else if (model.hole_count < 0)
    problem = "the hole count must be non-negative";
  else if (model.hole_count > 0 && model.hole_max_radius < 1.0)
    problem = "the largest hole radius must be at least 1 pixel when holes are enabled";
  else if (model.image_blur_sigma < 0.0 || model.image_noise_sigma < 0.0)
    problem = "the image blur and noise sigmas must be non-negative (0 = off)";
  return problem.empty();
}

double
depthNoiseSigma (const SensorModel& model, double depth)
{
  const double offset = depth - model.noise_reference_depth;
  return model.noise_sigma_base + model.noise_sigma_quadratic * offset * offset;
}

bool
applySensorModel (const RenderedFrame& input,
                  const SensorModel& model,
                  std::uint32_t seed,
                  RenderedFrame& output)
{
  std::string problem;
  if (!validateSensorModel (model, problem))
    return fail (problem, output);
  const bool grazing = model.max_incidence_angle < 90.0;
  if (!checkFrame (input, grazing, problem))
    return fail (problem, output);

  RenderedFrame result;
  result.camera = input.camera;
  result.color = input.color.clone();
  result.depth = input.depth.clone();
  result.instances = input.instances.clone();
  result.normals = input.normals.clone();
  result.instance_stats = input.instance_stats;

  if (model.discontinuity_threshold > 0.0)
    removeDiscontinuities (model, seed, result.depth);
  if (grazing)
    removeGrazing (model, input, result.depth);
  if (model.hole_count > 0)
    punchHoles (model, seed, result.depth);
  if (model.random_dropout > 0.0)
    dropRandomPixels (model, seed, result.depth);
  perturbDepth (model, seed, result.depth);
  perturbColor (model, seed, result.color);
  output = std::move (result);
  return true;
}

} // namespace simulation
} // namespace mid
