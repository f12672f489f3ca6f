#include <mid/registration/triplet_cluster.h>
#include <mid/segmentation/appearance_model_splitter.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <numeric>
#include <vector>

namespace mid {

namespace {

/** The representative of `i`'s group (path halving). */
std::size_t
findGroup (std::vector<std::size_t>& parent, std::size_t i)
{
  while (parent[i] != i) {
    parent[i] = parent[parent[i]];
    i = parent[i];
  }
  return i;
}

/** The correlations of every pair of instances, and whether the frame could tell
  * (PhotometricVerification::correlation()).
  */
struct PairLooks
{
  std::size_t n;
  std::vector<double> correlation; ///< row-major, n x n
  std::vector<bool> tested;

  PairLooks (const ObjectModel& model, const PhotometricVerification& verification)
  : n (model.instances.size()), correlation (n * n, 0.0), tested (n * n, false)
  {
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j) {
        const ModelInstance &a = model.instances[i], &b = model.instances[j];
        TripletCluster link;
        link.source_indices = a.keypoints;
        link.target_indices = b.keypoints;
        std::sort (link.source_indices.begin(), link.source_indices.end());
        std::sort (link.target_indices.begin(), link.target_indices.end());
        link.transformation = b.pose * a.pose.inverse();
        bool told = false;
        const double c = verification.correlation (link, told);
        correlation[i * n + j] = correlation[j * n + i] = c;
        tested[i * n + j] = tested[j * n + i] = told;
      }
  }

  bool
  alike (std::size_t i, std::size_t j, double min) const
  {
    return tested[i * n + j] && correlation[i * n + j] >= min;
  }
};

} // namespace

std::string
AppearanceModelSplitter::inputProblem (const ObjectModel& model) const
{
  std::string problem = verification_.inputProblem();
  if (!problem.empty())
    return "the verification cannot compare surfaces: " + problem;
  const std::size_t pixels = verification_.getKeypointSurface().keypoint_pixels.size();
  for (const auto& instance : model.instances) {
    if (instance.keypoints.size() != instance.landmarks.size() ||
        !std::all_of (instance.keypoints.begin(),
                      instance.keypoints.end(),
                      [pixels] (pcl::index_t k) {
                        return k >= 0 && static_cast<std::size_t> (k) < pixels;
                      }) ||
        !std::all_of (
            instance.landmarks.begin(), instance.landmarks.end(), [&model] (int l) {
              return l >= 0 && static_cast<std::size_t> (l) < model.landmarks.size();
            }))
      return "an instance observes a keypoint without a pixel or a landmark the model "
             "does not have";
  }
  return descriptorProblem (model);
}

bool
AppearanceModelSplitter::split (const ObjectModel& model, ObjectModels& parts) const
{
  parts.clear();
  const std::string problem = inputProblem (model);
  if (!problem.empty()) {
    PCL_ERROR ("[mid::AppearanceModelSplitter::split] %s.\n", problem.c_str());
    return false;
  }
  const std::size_t n = model.instances.size();
  if (n < 4) { // two groups of two at least
    parts.push_back (model);
    return true;
  }
  const PairLooks looks (model, verification_);
  const auto min = static_cast<double> (verification_.getMinCorrelation());

  // Groups of instances linked by a look alike.
  std::vector<std::size_t> parent (n);
  std::iota (parent.begin(), parent.end(), std::size_t{0});
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      if (looks.alike (i, j, min))
        parent[findGroup (parent, j)] = findGroup (parent, i);
  std::vector<std::vector<std::size_t>> members (n);
  for (std::size_t i = 0; i < n; ++i)
    members[findGroup (parent, i)].push_back (i);
  std::vector<std::size_t> groups, loners; // groups: representatives of two or more
  for (std::size_t i = 0; i < n; ++i)
    if (members[i].size() >= 2)
      groups.push_back (i);
    else if (members[i].size() == 1)
      loners.push_back (i);

  // Split only groups that were compared: some pair across every two of them was tested.
  const auto compared = [&] (std::size_t g, std::size_t h) {
    for (const auto i : members[g])
      for (const auto j : members[h])
        if (looks.tested[i * n + j])
          return true;
    return false;
  };
  bool apart = groups.size() >= 2;
  for (std::size_t a = 0; apart && a < groups.size(); ++a)
    for (std::size_t b = a + 1; apart && b < groups.size(); ++b)
      apart = compared (groups[a], groups[b]);
  if (!apart) {
    parts.push_back (model);
    return true;
  }

  // A loner joins the group it looks most alike, else (compared with none) the largest.
  for (const auto i : loners) {
    std::size_t to = n;
    double best = 0.0;
    for (const auto g : groups)
      for (const auto j : members[g])
        if (looks.tested[i * n + j] &&
            (to == n || looks.correlation[i * n + j] > best)) {
          best = looks.correlation[i * n + j];
          to = g;
        }
    if (to == n)
      to = *std::max_element (
          groups.begin(), groups.end(), [&members] (std::size_t g, std::size_t h) {
            return members[g].size() < members[h].size();
          });
    members[to].push_back (i);
  }
  for (const auto g : groups)
    std::sort (members[g].begin(), members[g].end());
  std::sort (groups.begin(), groups.end(), [&members] (std::size_t g, std::size_t h) {
    return members[g].front() < members[h].front();
  });
  for (const auto g : groups) {
    parts.emplace_back();
    extractModelPart (model, members[g], parts.back());
  }
  return true;
}

} // namespace mid
