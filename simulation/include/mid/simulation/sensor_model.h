#pragma once

#include <mid/simulation/rendered_frame.h>

#include <cstdint>
#include <string>

namespace mid {
namespace simulation {

/** \brief Imperfections of a structured-light RGB-D sensor, applied to an exact RenderedFrame by
  * applySensorModel(). Every effect is off by default (exact output); kinectSensorModel() gives
  * a Kinect v1-like preset.
  *
  * Depth effects, in this order: missing depth at depth discontinuities, at grazing angles, in
  * random holes and at random pixels; then axial noise with
  * sigma(z) = noise_sigma_base + noise_sigma_quadratic * (z - noise_reference_depth)^2
  * (Nguyen, Izadi, Lovell, 3DIMPVT 2012: 1.2 mm + 1.9 mm (z - 0.4 m)^2 for the Kinect v1);
  * then quantization. Image effects: Gaussian blur, then Gaussian noise per channel.
  */
struct SensorModel
{
  /** \brief Add axial Gaussian depth noise of standard deviation sigma(z). */
  bool depth_noise = false;
  /** \brief sigma(z) at the reference depth, metres. */
  double noise_sigma_base = 0.0012;
  /** \brief Growth of sigma(z) with the squared distance to the reference depth, 1/metres. */
  double noise_sigma_quadratic = 0.0019;
  /** \brief Depth of the smallest noise, metres. */
  double noise_reference_depth = 0.4;

  /** \brief Step of the inverse depth 1/z in 1/metres (disparity quantization: the depth step
    * grows as z^2 times this); 0 = off. Kinect v1: 1 / (8 * 580 px * 0.075 m) = 0.00287.
    */
  double disparity_quantization = 0.0;
  /** \brief Constant depth step in metres (applied after the disparity step); 0 = off. */
  double depth_quantization = 0.0;

  /** \brief A depth jump larger than this (metres) between neighbouring pixels, or between a
    * pixel with depth and one without, removes the depth of the farther side; 0 = off.
    */
  double discontinuity_threshold = 0.0;
  /** \brief Width in pixels of the band removed behind a discontinuity (>= 1). */
  int discontinuity_width = 1;
  /** \brief Probability that a pixel in that band loses its depth, in [0, 1]. */
  double discontinuity_dropout = 1.0;

  /** \brief Depth is removed where the angle between the surface normal and the viewing ray
    * exceeds this, in degrees; 90 or more = off.
    */
  double max_incidence_angle = 90.0;

  /** \brief Number of random circular holes in the depth image. */
  int hole_count = 0;
  /** \brief Largest hole radius in pixels (radii are uniform in [1, hole_max_radius]). */
  double hole_max_radius = 0.0;
  /** \brief Probability that any pixel loses its depth, in [0, 1]. */
  double random_dropout = 0.0;

  /** \brief Standard deviation of the colour Gaussian blur in pixels; 0 = off. */
  double image_blur_sigma = 0.0;
  /** \brief Standard deviation of the colour noise, in 8-bit intensity units; 0 = off. */
  double image_noise_sigma = 0.0;
};

/** \brief A Kinect v1-like sensor: the noise model of Nguyen et al., disparity quantization,
  * depth lost behind discontinuities and beyond 78 degrees of incidence, a few holes, and
  * slightly blurred, noisy colour.
  */
SensorModel
kinectSensorModel ();

/** \brief Check that all parameters are finite and within their ranges.
  * \param[in] model the model to check
  * \param[out] problem what is wrong, empty when it is valid
  * \return true if valid
  */
bool
validateSensorModel (const SensorModel& model, std::string& problem);

/** \brief sigma(z) of the model's depth noise, in metres (whether or not depth_noise is on).
  * \param[in] model the sensor model
  * \param[in] depth the depth z in metres
  * \return noise_sigma_base + noise_sigma_quadratic * (depth - noise_reference_depth)^2
  */
double
depthNoiseSigma (const SensorModel& model, double depth);

/** \brief Turn an exact frame into a simulated measurement.
  *
  * The same input, model and seed give a bit-identical output on every run and platform.
  * Only color and depth change; the instance map, normals and statistics are copied unchanged
  * as ground truth. input and output may be the same object.
  * \param[in] input an exact frame from SceneRenderer (normals are needed for the incidence
  * angle)
  * \param[in] model the sensor model
  * \param[in] seed the seed of all random effects
  * \param[out] output the measured frame; cleared when false is returned
  * \return false (with a PCL_ERROR naming the problem) if the model or the frame is invalid
  */
bool
applySensorModel (const RenderedFrame& input,
                  const SensorModel& model,
                  std::uint32_t seed,
                  RenderedFrame& output);

} // namespace simulation
} // namespace mid
