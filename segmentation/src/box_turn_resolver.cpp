#include <mid/segmentation/box_turn_resolver.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <array>
#include <vector>

namespace mid {

namespace {

using Turns = std::vector<Eigen::Matrix4f, Eigen::aligned_allocator<Eigen::Matrix4f>>;

/** The copies of each side compared for a turn: those with the most observations. */
constexpr std::size_t kComparedCopies = 4;

/** The proper rotations about a box's centre that map it onto itself, in the model frame
  * (box_in_model: box frame -> model frame, axes along the edges of `size`): the signed
  * permutations of the axes with determinant 1 that only exchange edges that agree. The
  * identity comes first.
  */
Turns
boxTurns (const Eigen::Vector3f& size,
          const Eigen::Matrix4f& box_in_model,
          const SizeAgreement& agree)
{
  Turns turns;
  std::array<int, 3> axes{0, 1, 2};
  do {
    bool same_box = true;
    for (int i = 0; i < 3; ++i)
      same_box = same_box && agree.edgesAgree (size[axes[i]], size[i]);
    if (!same_box)
      continue;
    for (int signs = 0; signs < 8; ++signs) {
      Eigen::Matrix3f turn = Eigen::Matrix3f::Zero();
      for (int i = 0; i < 3; ++i)
        turn (axes[i], i) = ((signs >> i) & 1) != 0 ? -1.0f : 1.0f;
      if (turn.determinant() < 0.0f)
        continue;
      Eigen::Matrix4f in_box = Eigen::Matrix4f::Identity();
      in_box.topLeftCorner<3, 3>() = turn;
      turns.push_back (box_in_model * in_box * box_in_model.inverse());
    }
  }
  while (std::next_permutation (axes.begin(), axes.end()));
  // std::next_permutation starts at the identity permutation and signs 0 is all +1.
  return turns;
}

/** The instances of `group` with the most observations, at most `count` of them, the one with
  * the most first (the first of equals).
  */
std::vector<std::size_t>
largestOf (const ObjectModel& model,
           const std::vector<int>& groups,
           int group,
           std::size_t count)
{
  std::vector<std::size_t> members;
  for (std::size_t i = 0; i < groups.size(); ++i)
    if (groups[i] == group)
      members.push_back (i);
  std::stable_sort (
      members.begin(), members.end(), [&model] (std::size_t a, std::size_t b) {
        return model.instances[a].keypoints.size() >
               model.instances[b].keypoints.size();
      });
  if (members.size() > count)
    members.resize (count);
  return members;
}

/** The cluster from instance a's keypoints to instance b's, b posed in `turn`. */
TripletCluster
copyLink (const ModelInstance& a, const ModelInstance& b, const Eigen::Matrix4f& turn)
{
  TripletCluster link;
  link.source_indices = a.keypoints;
  link.target_indices = b.keypoints;
  for (auto* indices : {&link.source_indices, &link.target_indices}) {
    std::sort (indices->begin(), indices->end());
    indices->erase (std::unique (indices->begin(), indices->end()), indices->end());
  }
  link.transformation = b.pose * turn * a.pose.inverse();
  return link;
}

/** Turn the instances of `group` and the landmarks they observe by `turn` (model frame). */
void
turnGroup (const KeypointCloud& keypoints,
           const std::vector<int>& groups,
           int group,
           const Eigen::Matrix4f& turn,
           ObjectModel& model,
           std::size_t& turned)
{
  const Eigen::Affine3f back (turn.inverse());
  std::vector<bool> moved (model.landmarks.size(), false);
  for (std::size_t i = 0; i < groups.size(); ++i) {
    if (groups[i] != group)
      continue;
    ModelInstance& instance = model.instances[i];
    instance.pose = instance.pose * turn;
    for (const int l : instance.landmarks) {
      const auto index = static_cast<std::size_t> (l);
      if (moved[index])
        continue;
      moved[index] = true;
      auto& landmark = model.landmarks[index];
      landmark.getVector3fMap() = back * landmark.getVector3fMap();
      landmark.getNormalVector3fMap() = back.linear() * landmark.getNormalVector3fMap();
    }
    ++turned;
  }
  for (std::size_t i = 0; i < groups.size(); ++i)
    if (groups[i] == group)
      updateInstanceError (model, keypoints, model.instances[i]);
}

} // namespace

std::string
BoxTurnResolver::inputProblem (const ObjectModels& models) const
{
  std::string problem = measurementProblem (models);
  if (problem.empty())
    problem = verification_.inputProblem();
  if (problem.empty() && !verification_.hasProjection())
    problem = "the verification's frame has no projection";
  if (problem.empty() && verification_.getKeypointSurface().keypoint_pixels.size() !=
                             surface_.keypoint_pixels.size())
    problem =
        "the verification holds " +
        std::to_string (verification_.getKeypointSurface().keypoint_pixels.size()) +
        " keypoint pixels, the keypoint surface " +
        std::to_string (surface_.keypoint_pixels.size());
  if (problem.empty() && !(min_gain_ >= 0.0f && min_gain_ <= 2.0f))
    problem =
        "the smallest gain must be in [0, 2] (got " + std::to_string (min_gain_) + ")";
  return problem;
}

bool
BoxTurnResolver::resolve (ObjectModels& models, std::size_t& turned) const
{
  turned = 0;
  if (const std::string why = inputProblem (models); !why.empty()) {
    PCL_ERROR ("[mid::BoxTurnResolver::resolve] %s.\n", why.c_str());
    return false;
  }
  std::vector<std::vector<int>> groups (models.size());
  bool any_split = false;
  for (std::size_t m = 0; m < models.size(); ++m) {
    groups[m] = sharedLandmarkGroups (models[m]);
    any_split =
        any_split ||
        std::any_of (groups[m].begin(), groups[m].end(), [] (int g) { return g > 0; });
  }
  Eigen::Vector4f plane;
  if (!any_split || !fitPlane (plane))
    return true;
  ModelSizes sizes;
  if (!measureSizes (models, plane, sizes))
    return false;
  const SizeAgreement agree = agreement();
  // A pair of copies confirms a turn by its correlation; 0 when the look does not confirm it.
  const auto confirmed = [this] (const PhotometricVerification::Agreement& look) {
    return look.correlation_tested && !verification_.rejects (look) ? look.correlation
                                                                    : 0.0;
  };
  for (std::size_t m = 0; m < models.size(); ++m) {
    ObjectModel& model = models[m];
    const std::vector<int>& group = groups[m];
    const int group_count =
        group.empty() ? 0 : *std::max_element (group.begin(), group.end()) + 1;
    if (group_count < 2 || !sizes[m].valid)
      continue;
    std::vector<std::size_t> observations (static_cast<std::size_t> (group_count), 0);
    for (std::size_t i = 0; i < group.size(); ++i)
      observations[static_cast<std::size_t> (group[i])] +=
          model.instances[i].keypoints.size();
    const int reference =
        static_cast<int> (std::max_element (observations.begin(), observations.end()) -
                          observations.begin());
    const std::vector<std::size_t> anchors =
        largestOf (model, group, reference, kComparedCopies);
    const Turns turns = boxTurns (sizes[m].size, sizes[m].box_in_model, agree);
    for (int g = 0; g < group_count; ++g) {
      if (g == reference)
        continue;
      const std::vector<std::size_t> copies =
          largestOf (model, group, g, kComparedCopies);
      // Each turn's evidence: the correlations of the pairs of copies whose look confirms it.
      std::vector<double> scores;
      scores.reserve (turns.size());
      for (const auto& turn : turns) {
        double score = 0.0;
        for (const auto a : anchors)
          for (const auto b : copies)
            score += confirmed (verification_.compare (
                copyLink (model.instances[a], model.instances[b], turn)));
        scores.push_back (score);
      }
      const auto best = static_cast<std::size_t> (
          std::max_element (scores.begin(), scores.end()) - scores.begin());
      if (best == 0 || scores[best] <= 0.0 ||
          scores[best] < scores[0] + static_cast<double> (min_gain_))
        continue;
      turnGroup (*keypoints_, group, g, turns[best], model, turned);
    }
  }
  return true;
}

} // namespace mid
