#pragma once

#include <mid/simulation/rendered_frame.h>
#include <mid/simulation/scene.h>

namespace mid {
namespace simulation {

/** \brief Exact CPU ray caster for Scene: one ray per pixel centre gives depth, instance ids
  * and normals; the colour is the textured surface colour with mild Lambertian shading,
  * intensity = ambient + (1 - ambient) * max (0, normal . light).
  *
  * The output is exact (no noise); apply a SensorModel with applySensorModel() for realistic
  * measurements. Rendering is single-threaded and deterministic.
  *
  * \code
  * mid::simulation::SceneRenderer renderer;
  * renderer.setCamera (mid::simulation::PinholeCamera ());
  * mid::simulation::RenderedFrame frame;
  * if (!renderer.render (scene, frame)) { ... }
  * \endcode
  */
class SceneRenderer
{
public:
  /** \brief The camera. Default: PinholeCamera (), VGA Kinect-like. */
  void
  setCamera (const PinholeCamera& camera)
  {
    camera_ = camera;
  }
  const PinholeCamera&
  getCamera () const
  {
    return camera_;
  }

  /** \brief Direction towards the (distant) light, in the camera frame; normalized when
    * rendering, must be non-zero. Default: (0.2, -0.8, -0.6), above and behind the camera.
    */
  void
  setLightDirection (const Eigen::Vector3d& direction)
  {
    light_direction_ = direction;
  }
  const Eigen::Vector3d&
  getLightDirection () const
  {
    return light_direction_;
  }

  /** \brief Ambient share of the intensity, in [0, 1]: 1 shows textures unshaded. Default 0.65,
    * mild enough for texture descriptors to stay repeatable between differently lit faces.
    */
  void
  setAmbient (double ambient)
  {
    ambient_ = ambient;
  }
  double
  getAmbient () const
  {
    return ambient_;
  }

  /** \brief Largest supported number of colour rays per pixel along each axis. */
  static constexpr int kMaxSupersampling = 16;

  /** \brief Colour rays per pixel along each axis (n x n rays averaged): anti-aliases texture
    * and edges. Depth, instances and normals always use the single pixel-centre ray.
    * Default 1; 1 to kMaxSupersampling (render() fails otherwise).
    */
  void
  setSupersampling (int samples)
  {
    supersampling_ = samples;
  }
  int
  getSupersampling () const
  {
    return supersampling_;
  }

  /** \brief Render the scene.
    * \param[in] scene the scene
    * \param[out] frame the frame and its ground truth; cleared when false is returned
    * \return false (with a PCL_ERROR naming the problem) if the camera, a parameter, a shape or
    * a pose is invalid; true otherwise
    */
  bool
  render (const Scene& scene, RenderedFrame& frame) const;

private:
  PinholeCamera camera_;
  Eigen::Vector3d light_direction_ = Eigen::Vector3d (0.2, -0.8, -0.6);
  double ambient_ = 0.65;
  int supersampling_ = 1;
};

} // namespace simulation
} // namespace mid
