#include <mid/evaluation/frame_score.h>

#include <Eigen/Geometry>

#include <map>
#include <set>

namespace mid {
namespace evaluation {

namespace {

/** The annotated instance at least min_inside of the keypoints lie on, or -1. */
int
annotatedInstanceOf (const GroundTruthFrame& truth,
                     const DetectedInstance& instance,
                     double min_inside)
{
  if (instance.keypoints.empty())
    return -1;
  for (std::size_t k = 0; k < truth.instances.size(); ++k) {
    std::size_t inside = 0;
    for (const auto& uv : instance.keypoints)
      inside += truth.contains (k, uv.x(), uv.y()) ? 1 : 0;
    if (static_cast<double> (inside) >=
        min_inside * static_cast<double> (instance.keypoints.size()))
      return static_cast<int> (k);
  }
  return -1;
}

void
addPoseErrors (const GroundTruthFrame& truth,
               const DetectedObject& object,
               const std::vector<std::pair<std::size_t, int>>& hits,
               const ObjectSymmetries& symmetries,
               FrameScore& score)
{
  for (std::size_t a = 0; a < hits.size(); ++a)
    for (std::size_t b = a + 1; b < hits.size(); ++b) {
      const Eigen::Matrix4f& pa = object.instances[hits[a].first].pose;
      const Eigen::Matrix4f& pb = object.instances[hits[b].first].pose;
      const Eigen::Matrix4f& ga =
          truth.instances[static_cast<std::size_t> (hits[a].second)].pose;
      const Eigen::Matrix4f& gb =
          truth.instances[static_cast<std::size_t> (hits[b].second)].pose;
      const Eigen::Matrix4d estimated = (pb * pa.inverse()).cast<double>();
      const Eigen::Matrix4d expected = (gb * ga.inverse()).cast<double>();
      const Eigen::Matrix3d relative =
          estimated.topLeftCorner<3, 3>().transpose() * expected.topLeftCorner<3, 3>();
      score.rotation_errors_deg.push_back (
          Eigen::AngleAxisd (Eigen::Quaterniond (relative).normalized()).angle() *
          180.0 / M_PI);
      // Modulo the shape: b's pose estimated from a's true one, against b's true one.
      const Eigen::Matrix3d b_estimated =
          estimated.topLeftCorner<3, 3>() * ga.topLeftCorner<3, 3>().cast<double>();
      score.symmetric_rotation_errors_deg.push_back (symmetricRotationError (
          b_estimated, gb.topLeftCorner<3, 3>().cast<double>(), symmetries));
      const int group_a = object.instances[hits[a].first].group;
      const int group_b = object.instances[hits[b].first].group;
      score.pair_groups.push_back (group_a < 0 || group_b < 0 ? -1
                                   : group_a == group_b       ? 1
                                                              : 0);
      const Eigen::Vector4d origin = ga.col (3).cast<double>();
      score.translation_errors_mm.push_back (
          ((estimated - expected) * origin).head<3>().norm() * 1000.0);
    }
}

} // namespace

FrameScore
scoreFrame (const GroundTruthFrame& truth,
            const DetectionResult& result,
            double min_inside,
            const ObjectSymmetryTable& symmetries)
{
  const ObjectSymmetries none;
  FrameScore score;
  std::map<int, int> annotated_of_type;
  for (const auto& instance : truth.instances)
    ++annotated_of_type[instance.object_id];
  score.pairs_only = true;
  bool any_repeated = false;
  for (const auto& [type, count] : annotated_of_type)
    if (count >= 2) {
      any_repeated = true;
      score.pairs_only = score.pairs_only && count == 2;
    }
  score.pairs_only = score.pairs_only && any_repeated;

  std::set<int> found_types, found_pairs;
  std::set<int> found_instances, located_by_false_objects;
  for (const auto& object : result.objects) {
    std::vector<int> hit (object.instances.size());
    std::map<int, int> votes;
    for (std::size_t i = 0; i < object.instances.size(); ++i) {
      hit[i] = annotatedInstanceOf (truth, object.instances[i], min_inside);
      if (hit[i] >= 0)
        ++votes[truth.instances[static_cast<std::size_t> (hit[i])].object_id];
    }
    int type = -1, best = 0;
    for (const auto& [candidate, count] : votes)
      if (count > best) {
        type = candidate;
        best = count;
      }
    const bool valid =
        type >= 0 && annotated_of_type[type] >= 2 && found_types.count (type) == 0;
    if (!valid) {
      for (const int h : hit)
        if (h >= 0)
          located_by_false_objects.insert (h);
      score.instance_fp += static_cast<int> (object.instances.size());
      ++score.pair_fp;
      continue;
    }
    found_types.insert (type);
    score.object_boxes.push_back ({type, object.box_size, object.box_copies});
    std::vector<std::pair<std::size_t, int>> true_hits;
    for (std::size_t i = 0; i < object.instances.size(); ++i) {
      const bool good =
          hit[i] >= 0 &&
          truth.instances[static_cast<std::size_t> (hit[i])].object_id == type &&
          found_instances.insert (hit[i]).second;
      if (good) {
        ++score.instance_tp;
        true_hits.emplace_back (i, hit[i]);
      }
      else
        ++score.instance_fp;
    }
    if (true_hits.size() >= 2) {
      ++score.pair_tp;
      found_pairs.insert (type);
    }
    else
      ++score.pair_fp;
    const auto symmetric = symmetries.find (type);
    addPoseErrors (truth,
                   object,
                   true_hits,
                   symmetric != symmetries.end() ? symmetric->second : none,
                   score);
  }
  for (std::size_t k = 0; k < truth.instances.size(); ++k) {
    const GroundTruthInstance& annotated = truth.instances[k];
    if (annotated_of_type[annotated.object_id] < 2)
      continue;
    const bool found = found_instances.count (static_cast<int> (k)) > 0;
    if (!found) {
      ++score.instance_fn;
      score.missed_instances.push_back (k);
      if (located_by_false_objects.count (static_cast<int> (k)) > 0)
        score.missed_but_located.push_back (k);
    }
    if (annotated.shared_surface_cells >= 0)
      (found ? score.found_shared_cells : score.missed_shared_cells)
          .push_back (annotated.shared_surface_cells);
  }
  for (const auto& [type, count] : annotated_of_type)
    if (count >= 2 && found_pairs.count (type) == 0)
      ++score.pair_fn;
  return score;
}

} // namespace evaluation
} // namespace mid
