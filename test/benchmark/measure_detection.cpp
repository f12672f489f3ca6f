// Detection of a saved model in new frames, against the truth. A model is discovered in one
// frame, then found with ModelInstanceDetector in other frames (other poses, one or several
// instances). Pose errors are absolute: the model frame is tied to the object's own frame
// through the discovery frame's truth.
//  (A) cookie boxes (printed face up, seen from various angles; test/common's box scenes);
//  (B) the tabletop juice cartons of the sample scene's recipe (seed 2), in frames of other seeds;
//  (C) the same model extended frame by frame by what its detected cartons show inside the
//      object's box (pcl_multi_instance_detect -extend), then detected in the frames of (B).
//
//   build/test/benchmark/measure_detection [TEXTURE_DIR]   (default: the repository's data/textures)

#include "rendered_objects_scene.h"
#include "tabletop_frame.h"

#include <mid/discovery/multi_instance_discovery.h>
#include <mid/features/sift_keypoint_extractor.h>
#include <mid/registration/instance_overlap.h>
#include <mid/registration/model_instance_detector.h>
#include <mid/segmentation/model_box_extension.h>
#include <mid/simulation/box_shape.h>

#include <Eigen/Geometry>
#include <pcl/common/io.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace {

using Frame = mid::test::TabletopFrame;

/** The scene object most of an instance's keypoints lie on (-1: background). */
int
objectUnder (const Frame& frame,
             const mid::ImageKeypoints& image,
             const pcl::Indices& keypoints)
{
  std::vector<Eigen::Vector2f> pixels;
  for (const auto k : keypoints)
    pixels.emplace_back (image[static_cast<std::size_t> (k)].u,
                         image[static_cast<std::size_t> (k)].v);
  return mid::test::objectUnderPixels (frame, pixels);
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

/** One frame's keypoints and descriptors, and the surface the box extension reads. */
struct Features
{
  mid::KeypointCloud::Ptr keypoints = pcl::make_shared<mid::KeypointCloud>();
  mid::SIFTDescriptorCloud::Ptr descriptors =
      pcl::make_shared<mid::SIFTDescriptorCloud>();
  mid::ImageKeypoints image;
};

Features
featuresOf (const Frame& frame)
{
  Features features;
  mid::SIFTKeypointExtractor<pcl::PointXYZRGBA> extractor;
  extractor.setInputCloud (frame.cloud);
  extractor.compute (*features.keypoints, *features.descriptors);
  features.image = extractor.getImageKeypoints();
  return features;
}

mid::ModelInstances
detect (const mid::ObjectModel& model, const Features& features)
{
  mid::ModelInstanceDetector detector;
  detector.setModel (std::make_shared<mid::ObjectModel> (model));
  detector.setInputKeypoints (features.keypoints);
  detector.setInputDescriptors (features.descriptors);
  mid::ObjectModel found;
  detector.detect (found.instances);
  // One instance per physical copy, as pcl_multi_instance_detect keeps.
  mid::removeOverlappingInstances (*features.keypoints, found);
  return found.instances;
}

/** The rotations that map a box of the given edges (centred at its origin, edges along its
  * axes) onto itself: the signed axis permutations with determinant +1 that keep the edges.
  */
std::vector<Eigen::Matrix3f>
boxSymmetries (const Eigen::Vector3f& size)
{
  std::vector<Eigen::Matrix3f> symmetries;
  const int orders[6][3] = {
      {0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (const auto& order : orders)
    for (int signs = 0; signs < 8; ++signs) {
      Eigen::Matrix3f r = Eigen::Matrix3f::Zero();
      for (int row = 0; row < 3; ++row)
        r (row, order[row]) = (signs >> row & 1) != 0 ? -1.0f : 1.0f;
      if (r.determinant() > 0.0f &&
          ((r.cwiseAbs() * size) - size).cwiseAbs().maxCoeff() < 1e-6f)
        symmetries.push_back (r);
    }
  return symmetries;
}

/** A detection's error against a carton's truth, up to the carton box's symmetries. */
struct PoseError
{
  double rotation_deg = 0.0, translation_mm = 0.0;
  /** Whether the closest symmetry is the identity: the carton's own frame, not only its box. */
  bool own_frame = true;
};

PoseError
poseError (const Eigen::Matrix4f& found,
           const Eigen::Matrix4f& carton,
           const Eigen::Matrix4f& model_in_carton,
           const std::vector<Eigen::Matrix3f>& symmetries)
{
  PoseError best;
  best.rotation_deg = 1e9;
  for (const Eigen::Matrix3f& symmetry : symmetries) {
    Eigen::Matrix4f turn = Eigen::Matrix4f::Identity();
    turn.topLeftCorner<3, 3>() = symmetry;
    const Eigen::Matrix4f expected = carton * turn * model_in_carton;
    const Eigen::Matrix3f relative =
        found.topLeftCorner<3, 3>().transpose() * expected.topLeftCorner<3, 3>();
    const double angle = Eigen::AngleAxisf (relative).angle() * 180.0 / M_PI;
    if (angle < best.rotation_deg)
      best = {angle,
              (found.topRightCorner<3, 1>() - expected.topRightCorner<3, 1>()).norm() *
                  1000.0,
              symmetry.isIdentity()};
  }
  return best;
}

/** Part (B)/(C): the carton table of one model over the test frames (seeds 11-14 with 1, 3 and
  * 5 cartons); pose errors up to the carton box's symmetries (a model whose copies showed
  * different faces is joined by their boxes, which cannot tell a face from the opposite one).
  */
void
measureCartons (const mid::ObjectModel& model,
                const Eigen::Matrix4f& model_in_carton,
                const Eigen::Vector3f& carton_size,
                const std::string& textures)
{
  const auto symmetries = boxSymmetries (carton_size);
  std::printf (
      "| seed | cartons | detections | cartons found | in the carton's own frame | "
      "rotation error deg (median) | translation error mm (median) |\n");
  std::printf ("|---|---|---|---|---|---|---|\n");
  std::vector<double> all_rotation, all_translation;
  int all_found = 0, all_cartons = 0, all_present = 0, all_own = 0;
  for (const int instances : {1, 3, 5})
    for (std::uint32_t seed = 11; seed <= 14; ++seed) {
      Frame frame;
      if (!mid::test::renderTabletopFrame (instances, seed, frame, textures))
        continue;
      const Features features = featuresOf (frame);
      const mid::ModelInstances found = detect (model, features);
      std::set<int> cartons;
      int own = 0;
      std::vector<double> rotation, translation;
      for (const auto& instance : found) {
        const int object = objectUnder (frame, features.image, instance.keypoints);
        if (object < 0 || object >= instances)
          continue;
        cartons.insert (object);
        const PoseError error = poseError (
            instance.pose, truePose (frame, object), model_in_carton, symmetries);
        own += error.own_frame ? 1 : 0;
        rotation.push_back (error.rotation_deg);
        translation.push_back (error.translation_mm);
      }
      all_rotation.insert (all_rotation.end(), rotation.begin(), rotation.end());
      all_translation.insert (
          all_translation.end(), translation.begin(), translation.end());
      all_found += static_cast<int> (found.size());
      all_cartons += static_cast<int> (cartons.size());
      all_present += instances;
      all_own += own;
      std::printf ("| %u | %d | %zu | %zu | %d | %.2f | %.1f |\n",
                   seed,
                   instances,
                   found.size(),
                   cartons.size(),
                   own,
                   median (rotation),
                   median (translation));
    }
  std::printf (
      "\n%d of %d cartons found by %d detections (%zu on a carton, %d of them in "
      "the carton's own frame); rotation error median %.2f deg, translation error "
      "median %.1f mm\n\n",
      all_cartons,
      all_present,
      all_found,
      all_rotation.size(),
      all_own,
      median (all_rotation),
      median (all_translation));
}

/** Part (C): the model extended, frame after frame, by the keypoints its detected cartons show
  * inside the object's box (what pcl_multi_instance_detect -extend does), over frames of seeds
  * 21-28 with 5 cartons each; reports what each frame added and how many of the added
  * landmarks came from a carton's own keypoints.
  */
mid::ObjectModel
accumulate (mid::ObjectModel model,
            const mid::ModelSize& box,
            const std::string& textures)
{
  std::printf (
      "| seed | cartons detected | on a carton | landmarks added | of them on the "
      "detected carton | landmarks |\n");
  std::printf ("|---|---|---|---|---|---|\n");
  for (std::uint32_t seed = 21; seed <= 28; ++seed) {
    Frame frame;
    if (!mid::test::renderTabletopFrame (5, seed, frame, textures))
      continue;
    const Features features = featuresOf (frame);
    model.instances = detect (model, features);
    auto organized = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
    pcl::copyPointCloud (*frame.cloud, *organized);
    mid::ModelBoxExtender extender;
    extender.setInputKeypoints (features.keypoints);
    extender.setKeypointSurface ({organized, mid::pixelIndices (features.image)});
    extender.setInputDescriptors (features.descriptors);
    extender.setKnownSizes ({box});
    mid::ObjectModels models{model};
    mid::ModelExtension extension;
    if (!extender.extend (models, extension)) {
      std::printf ("| %u | could not extend the model |\n", seed);
      continue;
    }
    // The carton under each instance (-1: on the background or a distractor).
    int on_carton = 0, own = 0;
    std::vector<int> carton_of (model.instances.size(), -1);
    for (std::size_t i = 0; i < model.instances.size(); ++i) {
      const int object =
          objectUnder (frame, features.image, model.instances[i].keypoints);
      carton_of[i] = object >= 0 && object < 5 ? object : -1;
      on_carton += carton_of[i] >= 0 ? 1 : 0;
    }
    for (const auto& [i, k] : extension.observations[0]) {
      const auto& kp = features.image[static_cast<std::size_t> (k)];
      own += carton_of[i] >= 0 && mid::test::objectUnderPixels (
                                      frame, {{kp.u, kp.v}}) == carton_of[i]
                 ? 1
                 : 0;
    }
    std::printf ("| %u | %zu | %d | %zu | %d | %zu |\n",
                 seed,
                 model.instances.size(),
                 on_carton,
                 extension.observations[0].size(),
                 own,
                 models[0].landmarks.size());
    model = models[0];
  }
  model.instances.clear();
  std::printf ("\n");
  return model;
}

int
main (int argc, char** argv)
{
  const std::string textures = argc > 1 ? argv[1] : "";
  measureBoxes();
  std::printf ("(B) juice cartons of the tabletop recipe\n\n");
  Frame reference;
  if (!mid::test::renderTabletopFrame (5, 2, reference, textures))
    return 1;
  mid::MultiInstanceDiscovery<pcl::PointXYZRGBA> discovery;
  discovery.setInputCloud (reference.cloud);
  mid::DiscoveryResult discovered;
  if (!discovery.discover (discovered) || discovered.models.empty())
    return 1;
  const mid::ObjectModel& model = discovered.models.front();
  // Tie the model frame to the carton frame with the best-observed instance: P = G X.
  const auto& anchor =
      *std::max_element (model.instances.begin(),
                         model.instances.end(),
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
               model.landmarks.size(),
               model.descriptors.size(),
               model.instances.size());
  const auto carton = std::dynamic_pointer_cast<const mid::simulation::BoxShape> (
      reference.scene.getObjects().front().shape);
  if (!carton)
    return 1;
  const Eigen::Vector3f carton_size = carton->getSize().cast<float>();
  measureCartons (model, model_in_carton, carton_size, textures);

  const mid::ModelSize* box = mid::modelBox (discovered, 0);
  if (box == nullptr || !box->valid) {
    std::printf ("(C) skipped: the seed-2 frame measured no box of the carton\n");
    return 0;
  }
  std::printf (
      "(C) the same model accumulated over frames of seeds 21-28 (5 cartons each)\n\n");
  const mid::ObjectModel accumulated = accumulate (model, *box, textures);
  measureCartons (accumulated, model_in_carton, carton_size, textures);
  return 0;
}
