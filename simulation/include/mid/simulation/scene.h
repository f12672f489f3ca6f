#pragma once

#include <mid/simulation/shape.h>

#include <Eigen/Geometry>

#include <vector>

namespace mid {
namespace simulation {

/** \brief A shape placed in the camera frame. */
struct SceneObject
{
  /** \brief The shape; several objects may share one (identical instances). */
  Shape::ConstPtr shape;
  /** \brief Rigid transform from the shape's model frame to the camera frame (OpenCV
    * convention: x right, y down, z forward), in metres.
    */
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
};

/** \brief What the SceneRenderer draws: the objects (the instances whose ground truth is
  * reported, indexed in the order they were added), background objects such as a table
  * (rendered, instance id -1), and the colour of rays that hit nothing.
  */
class Scene
{
public:
  /** \brief Add an object; its index (0, 1, ...) is its instance id in RenderedFrame.
    * \param[in] shape the shape (may be shared with other objects)
    * \param[in] pose model-to-camera rigid transform, metres
    * \return the object's index
    */
  int
  addObject (const Shape::ConstPtr& shape, const Eigen::Isometry3d& pose);

  /** \brief The objects, indexed by instance id. */
  const std::vector<SceneObject>&
  getObjects () const
  {
    return objects_;
  }

  /** \brief Add a background object (a table, a wall): rendered, but labelled -1 and given no
    * instance statistics.
    * \param[in] shape the shape, typically a TablePlane
    * \param[in] pose model-to-camera rigid transform, metres
    */
  void
  addBackgroundObject (const Shape::ConstPtr& shape, const Eigen::Isometry3d& pose);

  /** \brief The background objects, in the order they were added. */
  const std::vector<SceneObject>&
  getBackgroundObjects () const
  {
    return background_;
  }

  /** \brief BGR colour of pixels whose ray hits nothing. Default: dark grey (40, 40, 40). */
  void
  setBackgroundColor (const cv::Vec3b& color)
  {
    background_color_ = color;
  }
  const cv::Vec3b&
  getBackgroundColor () const
  {
    return background_color_;
  }

  /** \brief Remove all objects and background objects (the background colour stays). */
  void
  clear ();

private:
  std::vector<SceneObject> objects_;
  std::vector<SceneObject> background_;
  cv::Vec3b background_color_ = cv::Vec3b (40, 40, 40);
};

} // namespace simulation
} // namespace mid
