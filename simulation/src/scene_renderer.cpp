#include <mid/simulation/scene_renderer.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace mid {
namespace simulation {

namespace {

/** A scene object with everything a ray needs precomputed. */
struct PreparedObject
{
  const Shape* shape;
  int id;                     // instance id: object index, or -1 for the background
  Eigen::Matrix3d rotation;   // model to camera
  Eigen::Matrix3d rotation_t; // camera to model
  Eigen::Vector3d camera_in_model; // the ray origin (camera centre) in the model frame
  Eigen::Vector3d center;          // model origin in the camera frame
  double radius_squared;           // bounding sphere; infinity if unbounded
};

/** The first surface along a camera ray. */
struct RayHit
{
  const PreparedObject* object = nullptr;
  SurfaceHit surface;
};

bool
fail (const std::string& message, RenderedFrame& frame)
{
  PCL_ERROR ("[mid::simulation::SceneRenderer::render] %s\n", message.c_str());
  frame.clear();
  return false;
}

bool
isRigid (const Eigen::Isometry3d& pose)
{
  if (!pose.matrix().allFinite())
    return false;
  const Eigen::Matrix3d rotation = pose.linear();
  return (rotation.transpose() * rotation - Eigen::Matrix3d::Identity()).norm() <
             1e-6 &&
         rotation.determinant() > 0.0;
}

/** Check an object and append it, prepared, to prepared; false with a message if invalid. */
bool
prepareObject (const SceneObject& object,
               int id,
               const std::string& label,
               std::vector<PreparedObject>& prepared,
               std::string& problem)
{
  if (!object.shape) {
    problem = label + " has no shape";
    return false;
  }
  std::string shape_problem;
  if (!object.shape->validate (shape_problem)) {
    problem = label + ": " + shape_problem;
    return false;
  }
  if (!isRigid (object.pose)) {
    problem =
        label + ": the pose is not a finite rigid transform (rotation not orthonormal)";
    return false;
  }
  PreparedObject entry;
  entry.shape = object.shape.get();
  entry.id = id;
  entry.rotation = object.pose.linear();
  entry.rotation_t = entry.rotation.transpose();
  entry.center = object.pose.translation();
  entry.camera_in_model = -(entry.rotation_t * entry.center);
  const double radius = object.shape->getBoundingRadius();
  entry.radius_squared = std::isfinite (radius)
                             ? radius * radius
                             : std::numeric_limits<double>::infinity();
  prepared.push_back (entry);
  return true;
}

/** The nearest surface along the camera ray with the given direction (z = 1). */
bool
castRay (const std::vector<PreparedObject>& objects,
         const Eigen::Vector3d& direction,
         RayHit& hit)
{
  const double direction_squared = direction.squaredNorm();
  double best = std::numeric_limits<double>::infinity();
  SurfaceHit surface;
  hit.object = nullptr;
  for (const PreparedObject& object : objects) {
    if (std::isfinite (object.radius_squared)) {
      // Skip the object unless the ray meets its bounding sphere in front of the best hit.
      const double b = direction.dot (object.center);
      const double discriminant =
          b * b -
          direction_squared * (object.center.squaredNorm() - object.radius_squared);
      if (discriminant < 0.0)
        continue;
      const double root = std::sqrt (discriminant);
      if (b + root <= 0.0 || (b - root) / direction_squared >= best)
        continue;
    }
    const Eigen::Vector3d direction_model = object.rotation_t * direction;
    if (object.shape->intersect (
            object.camera_in_model, direction_model, best, surface)) {
      best = surface.t;
      hit.object = &object;
      hit.surface = surface;
    }
  }
  return hit.object != nullptr;
}

/** Shaded colour of a hit. */
cv::Vec3f
shade (const RayHit& hit, const Eigen::Vector3d& light, double ambient)
{
  const Eigen::Vector3d normal = hit.object->rotation * hit.surface.normal;
  const double intensity =
      ambient + (1.0 - ambient) * std::max (0.0, normal.dot (light));
  return hit.object->shape->getColor (hit.surface) * static_cast<float> (intensity);
}

} // namespace

bool
SceneRenderer::render (const Scene& scene, RenderedFrame& frame) const
{
  std::string problem;
  if (!validateCamera (camera_, problem))
    return fail (problem, frame);
  if (!light_direction_.allFinite() || light_direction_.norm() == 0.0)
    return fail ("the light direction must be finite and non-zero", frame);
  if (!(ambient_ >= 0.0 && ambient_ <= 1.0))
    return fail (
        "the ambient share must be in [0, 1], got " + std::to_string (ambient_), frame);
  if (supersampling_ < 1 || supersampling_ > kMaxSupersampling)
    return fail ("supersampling must be in [1, " + std::to_string (kMaxSupersampling) +
                     "], got " + std::to_string (supersampling_),
                 frame);

  std::vector<PreparedObject> objects;
  objects.reserve (scene.getObjects().size() + scene.getBackgroundObjects().size());
  for (std::size_t i = 0; i < scene.getObjects().size(); ++i)
    if (!prepareObject (scene.getObjects()[i],
                        static_cast<int> (i),
                        "object " + std::to_string (i),
                        objects,
                        problem))
      return fail (problem, frame);
  for (std::size_t i = 0; i < scene.getBackgroundObjects().size(); ++i)
    if (!prepareObject (scene.getBackgroundObjects()[i],
                        -1,
                        "background object " + std::to_string (i),
                        objects,
                        problem))
      return fail (problem, frame);

  const Eigen::Vector3d light = light_direction_.normalized();
  const cv::Vec3b& background = scene.getBackgroundColor();
  const cv::Vec3f background_color (background[0], background[1], background[2]);
  frame.camera = camera_;
  frame.color.create (camera_.height, camera_.width, CV_8UC3);
  frame.depth = cv::Mat::zeros (camera_.height, camera_.width, CV_32FC1);
  frame.instances = cv::Mat (camera_.height, camera_.width, CV_32SC1, cv::Scalar (-1));
  frame.normals = cv::Mat::zeros (camera_.height, camera_.width, CV_32FC3);
  frame.instance_stats.assign (scene.getObjects().size(), InstanceStats());
  std::vector<cv::Point> bbox_min (scene.getObjects().size(),
                                   cv::Point (camera_.width, camera_.height));
  std::vector<cv::Point> bbox_max (scene.getObjects().size(), cv::Point (-1, -1));

  const int samples = supersampling_;
  const float sample_weight = 1.0f / static_cast<float> (samples * samples);
  RayHit hit;
  for (int v = 0; v < camera_.height; ++v) {
    auto* color_row = frame.color.ptr<cv::Vec3b> (v);
    auto* depth_row = frame.depth.ptr<float> (v);
    auto* instance_row = frame.instances.ptr<int> (v);
    auto* normal_row = frame.normals.ptr<cv::Vec3f> (v);
    for (int u = 0; u < camera_.width; ++u) {
      const bool found = castRay (objects, pixelRay (camera_, u, v), hit);
      cv::Vec3f color = background_color;
      if (found) {
        depth_row[u] = static_cast<float> (hit.surface.t);
        const Eigen::Vector3d normal = hit.object->rotation * hit.surface.normal;
        normal_row[u] = cv::Vec3f (static_cast<float> (normal.x()),
                                   static_cast<float> (normal.y()),
                                   static_cast<float> (normal.z()));
        color = shade (hit, light, ambient_);
        const int id = hit.object->id;
        instance_row[u] = id;
        if (id >= 0) {
          ++frame.instance_stats[id].visible_pixels;
          bbox_min[id] =
              cv::Point (std::min (bbox_min[id].x, u), std::min (bbox_min[id].y, v));
          bbox_max[id] =
              cv::Point (std::max (bbox_max[id].x, u), std::max (bbox_max[id].y, v));
        }
      }
      if (samples > 1) {
        color = cv::Vec3f (0.0f, 0.0f, 0.0f);
        for (int j = 0; j < samples; ++j)
          for (int i = 0; i < samples; ++i) {
            const double du = (i + 0.5) / samples - 0.5;
            const double dv = (j + 0.5) / samples - 0.5;
            RayHit sample;
            color += (castRay (objects, pixelRay (camera_, u + du, v + dv), sample)
                          ? shade (sample, light, ambient_)
                          : background_color) *
                     sample_weight;
          }
      }
      color_row[u] = cv::Vec3b (cv::saturate_cast<uchar> (color[0]),
                                cv::saturate_cast<uchar> (color[1]),
                                cv::saturate_cast<uchar> (color[2]));
    }
  }
  for (std::size_t id = 0; id < frame.instance_stats.size(); ++id)
    if (frame.instance_stats[id].visible_pixels > 0)
      frame.instance_stats[id].bbox =
          cv::Rect (bbox_min[id], bbox_max[id] + cv::Point (1, 1));
  return true;
}

} // namespace simulation
} // namespace mid
