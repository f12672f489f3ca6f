#include "tabletop_frame.h"

#include <mid/simulation/frame_io.h>
#include <mid/simulation/scene_renderer.h>
#include <mid/simulation/sensor_model.h>
#include <mid/simulation/tabletop_scene.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace mid {
namespace test {

bool
renderTabletopFrame (int cartons,
                     std::uint32_t seed,
                     TabletopFrame& frame,
                     const std::string& texture_dir)
{
  mid::simulation::TabletopSceneOptions options;
  options.instances = cartons;
  options.seed = seed;
  const std::string textures =
      texture_dir.empty() ? std::string (MID_TEST_DATA_DIR) + "/textures" : texture_dir;
  if (!mid::simulation::makeTabletopScene (options, textures, frame.scene))
    return false;
  mid::simulation::SceneRenderer renderer;
  renderer.setCamera (options.camera);
  renderer.setSupersampling (3);
  mid::simulation::RenderedFrame exact;
  return renderer.render (frame.scene, exact) &&
         mid::simulation::applySensorModel (
             exact, mid::simulation::kinectSensorModel(), seed, frame.rendered) &&
         mid::simulation::frameToCloud (
             frame.rendered, mid::simulation::MILLIMETRE_DEPTH_SCALE, *frame.cloud);
}

int
objectUnderPixels (const TabletopFrame& frame,
                   const std::vector<Eigen::Vector2f>& pixels)
{
  std::map<int, int> votes;
  const cv::Mat& objects = frame.rendered.instances;
  for (const auto& p : pixels) {
    const int u = static_cast<int> (std::lround (p.x())),
              v = static_cast<int> (std::lround (p.y()));
    if (u >= 0 && v >= 0 && u < objects.cols && v < objects.rows)
      ++votes[objects.at<int> (v, u)];
  }
  if (votes.empty())
    return -1;
  return std::max_element (
             votes.begin(),
             votes.end(),
             [] (const auto& a, const auto& b) { return a.second < b.second; })
      ->first;
}

} // namespace test
} // namespace mid
