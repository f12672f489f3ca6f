#include <mid/simulation/scene.h>

namespace mid {
namespace simulation {

int
Scene::addObject (const Shape::ConstPtr& shape, const Eigen::Isometry3d& pose)
{
  objects_.push_back ({shape, pose});
  return static_cast<int> (objects_.size()) - 1;
}

void
Scene::addBackgroundObject (const Shape::ConstPtr& shape, const Eigen::Isometry3d& pose)
{
  background_.push_back ({shape, pose});
}

void
Scene::clear()
{
  objects_.clear();
  background_.clear();
}

} // namespace simulation
} // namespace mid
