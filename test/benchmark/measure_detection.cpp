// Detection of a saved model in new frames, against the truth. A model is discovered in one
// frame, then found with ModelInstanceDetector in other frames (other poses, one or several
// instances). Pose errors are absolute: the model frame is tied to the object's own frame
// through the discovery frame's truth.
//  (A) cookie boxes (printed face up, seen from various angles; test/common's box scenes);
//  (B) the tabletop juice cartons of the sample scene's recipe (seed 2), in frames of other seeds.
//
//   build/test/benchmark/measure_detection [TEXTURE_DIR]

#include "rendered_objects_scene.h"

#include <mid/discovery/multi_instance_discovery.h>
#include <mid/features/sift_keypoint_extractor.h>
#include <mid/registration/model_instance_detector.h>
#include <mid/simulation/frame_io.h>
#include <mid/simulation/scene_renderer.h>
#include <mid/simulation/sensor_model.h>
#include <mid/simulation/tabletop_scene.h>

#include <Eigen/Geometry>
#include <pcl/point_types.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZRGBA>;

/** A rendered tabletop frame (Kinect-like noise) and its truth. */
struct Frame
{
  mid::simulation::Scene scene;
  mid::simulation::RenderedFrame rendered;
  Cloud::Ptr cloud = pcl::make_shared<Cloud>();
};

bool
render (int instances, std::uint32_t seed, const std::string& textures, Frame& frame)
{
  mid::simulation::TabletopSceneOptions options;
  options.instances = instances;
  options.seed = seed;
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

/** The scene object most of an instance's keypoints lie on (-1: background). */
int
objectUnder (const Frame& frame,
             const mid::ImageKeypoints& image,
             const pcl::Indices& keypoints)
{
  std::map<int, int> votes;
  for (const auto k : keypoints) {
    const auto& kp = image[static_cast<std::size_t> (k)];
    ++votes[frame.rendered.instances.at<int> (static_cast<int> (std::lround (kp.v)),
                                              static_cast<int> (std::lround (kp.u)))];
  }
  return std::max_element (
             votes.begin(),
             votes.end(),
             [] (const auto& a, const auto& b) { return a.second < b.second; })
      ->first;
}

Eigen::Matrix4f
truePose (const Frame& frame, int object)
{
  return frame.scene.getObjects()[static_cast<std::size_t> (object)]
      .pose.matrix()
      .cast<float>();
}

double
median (std::vector<double> values)
{
  if (values.empty())
    return -1.0;
  std::sort (values.begin(), values.end());
  return values[values.size() / 2];
}

} // namespace

/** Part (A): boxes with the cookie print, discovered in a 3-box frame, detected in others. */
void
measureBoxes ()
{
  using mid::test::boxPose;
  const Eigen::Vector3d size (0.16, 0.11, 0.04);
  const char* cookies = "bastoncini_cookie_box.png";
  const auto reference = mid::test::renderBoxes (
      {{cookies, size, boxPose (-0.17, -0.06, 0.85, 10.0, 15.0)},
       {cookies, size, boxPose (0.12, -0.08, 0.90, 70.0, -10.0)},
       {cookies, size, boxPose (0.0, 0.14, 0.80, -40.0, 25.0)}});
  mid::MultiInstanceDiscovery<pcl::PointXYZRGBA> discovery;
  discovery.setInputCloud (reference.cloud);
  mid::DiscoveryResult discovered;
  if (!discovery.discover (discovered) || discovered.models.empty())
    return;
  auto model = std::make_shared<mid::ObjectModel> (discovered.models.front());
  const auto& anchor = model->instances.front();
  std::vector<Eigen::Vector2f> pixels;
  for (const auto k : anchor.keypoints)
    pixels.emplace_back (discovered.image_keypoints[static_cast<std::size_t> (k)].u,
                         discovered.image_keypoints[static_cast<std::size_t> (k)].v);
  const int anchor_box = mid::test::boxUnderKeypoints (reference, pixels);
  const Eigen::Matrix4f model_in_box =
      reference.boxes[static_cast<std::size_t> (anchor_box)]
          .pose.matrix()
          .cast<float>()
          .inverse() *
      anchor.pose;
  std::printf ("(A) cookie boxes: model of %zu landmarks from %zu instances\n\n",
               model->landmarks.size(),
               model->instances.size());
  std::printf ("| frame | boxes | detected | on a box | rotation error deg (median) | "
               "translation error mm (median) |\n|---|---|---|---|---|---|\n");
  const std::vector<std::vector<mid::test::BoxSpec>> frames{
      {{cookies, size, boxPose (0.05, 0.02, 0.95, 120.0, 20.0)}},
      {{cookies, size, boxPose (-0.1, 0.05, 0.75, -75.0, -25.0)}},
      {{cookies, size, boxPose (-0.18, 0.0, 0.9, 30.0, 0.0)},
       {cookies, size, boxPose (0.15, -0.1, 0.85, -20.0, 20.0)},
       {cookies, size, boxPose (0.05, 0.15, 1.0, 160.0, -15.0)}}};
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const auto scene = mid::test::renderBoxes (frames[f]);
    mid::SIFTKeypointExtractor<pcl::PointXYZRGBA> extractor;
    extractor.setInputCloud (scene.cloud);
    auto keypoints = pcl::make_shared<mid::KeypointCloud>();
    auto descriptors = pcl::make_shared<mid::SIFTDescriptorCloud>();
    extractor.compute (*keypoints, *descriptors);
    mid::ModelInstanceDetector detector;
    detector.setModel (model);
    detector.setInputKeypoints (keypoints);
    detector.setInputDescriptors (descriptors);
    mid::ModelInstances found;
    detector.detect (found);
    int correct = 0;
    std::vector<double> rotation, translation;
    for (const auto& instance : found) {
      std::vector<Eigen::Vector2f> at;
      for (const auto k : instance.keypoints)
        at.emplace_back (extractor.getImageKeypoints()[static_cast<std::size_t> (k)].u,
                         extractor.getImageKeypoints()[static_cast<std::size_t> (k)].v);
      const int box = mid::test::boxUnderKeypoints (scene, at);
      if (box < 0)
        continue;
      ++correct;
      const Eigen::Matrix4f expected =
          scene.boxes[static_cast<std::size_t> (box)].pose.matrix().cast<float>() *
          model_in_box;
      const Eigen::Matrix3f relative = instance.pose.topLeftCorner<3, 3>().transpose() *
                                       expected.topLeftCorner<3, 3>();
      rotation.push_back (Eigen::AngleAxisf (relative).angle() * 180.0 / M_PI);
      translation.push_back (
          (instance.pose.topRightCorner<3, 1>() - expected.topRightCorner<3, 1>())
              .norm() *
          1000.0);
    }
    std::printf ("| %zu | %zu | %zu | %d | %.2f | %.1f |\n",
                 f,
                 frames[f].size(),
                 found.size(),
                 correct,
                 median (rotation),
                 median (translation));
  }
  std::printf ("\n");
}

int
main (int argc, char** argv)
{
  const std::string textures = argc > 1 ? argv[1] : "data/textures";
  measureBoxes();
  std::printf ("(B) juice cartons of the tabletop recipe\n\n");
  Frame reference;
  if (!render (5, 2, textures, reference))
    return 1;
  mid::MultiInstanceDiscovery<pcl::PointXYZRGBA> discovery;
  discovery.setInputCloud (reference.cloud);
  mid::DiscoveryResult discovered;
  if (!discovery.discover (discovered) || discovered.models.empty())
    return 1;
  auto model = std::make_shared<mid::ObjectModel> (discovered.models.front());
  // Tie the model frame to the carton frame with the best-observed instance: P = G X.
  const auto& anchor =
      *std::max_element (model->instances.begin(),
                         model->instances.end(),
                         [] (const auto& a, const auto& b) {
                           return a.keypoints.size() < b.keypoints.size();
                         });
  const Eigen::Matrix4f model_in_carton =
      truePose (reference,
                objectUnder (reference, discovered.image_keypoints, anchor.keypoints))
          .inverse() *
      anchor.pose;
  std::printf ("model: %zu landmarks, %zu descriptors, from %zu instances of the "
               "seed-2 frame\n\n",
               model->landmarks.size(),
               model->descriptors.size(),
               model->instances.size());
  std::printf ("| seed | cartons | detected | on a carton | rotation error deg "
               "(median) | translation error mm (median) |\n");
  std::printf ("|---|---|---|---|---|---|\n");
  std::vector<double> all_rotation, all_translation;
  for (const int instances : {1, 3, 5})
    for (std::uint32_t seed = 11; seed <= 14; ++seed) {
      Frame frame;
      if (!render (instances, seed, textures, frame))
        continue;
      mid::SIFTKeypointExtractor<pcl::PointXYZRGBA> extractor;
      extractor.setInputCloud (frame.cloud);
      auto keypoints = pcl::make_shared<mid::KeypointCloud>();
      auto descriptors = pcl::make_shared<mid::SIFTDescriptorCloud>();
      extractor.compute (*keypoints, *descriptors);
      mid::ModelInstanceDetector detector;
      detector.setModel (model);
      detector.setInputKeypoints (keypoints);
      detector.setInputDescriptors (descriptors);
      mid::ModelInstances found;
      detector.detect (found);
      int correct = 0;
      std::vector<double> rotation, translation;
      for (const auto& instance : found) {
        const int object =
            objectUnder (frame, extractor.getImageKeypoints(), instance.keypoints);
        if (object < 0 || object >= instances)
          continue;
        ++correct;
        const Eigen::Matrix4f expected = truePose (frame, object) * model_in_carton;
        const Eigen::Matrix3f relative =
            instance.pose.topLeftCorner<3, 3>().transpose() *
            expected.topLeftCorner<3, 3>();
        rotation.push_back (Eigen::AngleAxisf (relative).angle() * 180.0 / M_PI);
        translation.push_back (
            (instance.pose.topRightCorner<3, 1>() - expected.topRightCorner<3, 1>())
                .norm() *
            1000.0);
      }
      all_rotation.insert (all_rotation.end(), rotation.begin(), rotation.end());
      all_translation.insert (
          all_translation.end(), translation.begin(), translation.end());
      std::printf ("| %u | %d | %zu | %d | %.2f | %.1f |\n",
                   seed,
                   instances,
                   found.size(),
                   correct,
                   median (rotation),
                   median (translation));
    }
  std::printf ("\nall detections on a carton: rotation error median %.2f deg, "
               "translation error median %.1f mm (%zu detections)\n",
               median (all_rotation),
               median (all_translation),
               all_rotation.size());
  return 0;
}
