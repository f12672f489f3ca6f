#include <mid/discovery/discovery_parameters.h>

#include <cmath>

namespace mid {

namespace {

/** Records the first failed requirement. */
class Checker
{
public:
  explicit Checker (std::string& problem) : problem_ (problem) { problem_.clear(); }

  void
  require (bool ok, const char* name, double value, const char* requirement)
  {
    if (!ok && problem_.empty())
      problem_ = std::string (name) + " is " + std::to_string (value) + ", must be " +
                 requirement;
  }

  bool
  ok () const
  {
    return problem_.empty();
  }

private:
  std::string& problem_;
};

} // namespace

bool
validateDiscoveryParameters (const DiscoveryParameters& p, std::string& problem)
{
  constexpr double pi = M_PI;
  Checker c (problem);
  c.require (p.max_keypoints >= 0, "max_keypoints", p.max_keypoints, ">= 0");
  c.require (
      p.contrast_threshold > 0.0, "contrast_threshold", p.contrast_threshold, "> 0");
  c.require (p.normal_radius > 0.0f,
             "normal_radius",
             static_cast<double> (p.normal_radius),
             "> 0");
  c.require (p.max_descriptor_distance > 0.0f,
             "max_descriptor_distance",
             static_cast<double> (p.max_descriptor_distance),
             "> 0");
  c.require (p.min_keypoint_distance >= 0.0f,
             "min_keypoint_distance",
             static_cast<double> (p.min_keypoint_distance),
             ">= 0");
  c.require (p.max_distance_ratio > 0.0f && p.max_distance_ratio <= 1.0f,
             "max_distance_ratio",
             static_cast<double> (p.max_distance_ratio),
             "in (0, 1]");
  c.require (p.matches_per_keypoint >= 1,
             "matches_per_keypoint",
             static_cast<double> (p.matches_per_keypoint),
             ">= 1");
  c.require (p.ppf_distance >= 0.0f,
             "ppf_distance",
             static_cast<double> (p.ppf_distance),
             ">= 0");
  c.require (p.ppf_angle >= 0.0f && p.ppf_angle <= pi,
             "ppf_angle",
             static_cast<double> (p.ppf_angle),
             "in [0, pi]");
  c.require (p.min_edge_length > 0.0f,
             "min_edge_length",
             static_cast<double> (p.min_edge_length),
             "> 0");
  c.require (p.max_edge_length >= p.min_edge_length,
             "max_edge_length",
             static_cast<double> (p.max_edge_length),
             ">= min_edge_length");
  c.require (p.min_triangle_angle >= 0.0f && p.min_triangle_angle < pi / 3.0,
             "min_triangle_angle",
             static_cast<double> (p.min_triangle_angle),
             "in [0, pi/3)");
  c.require (!std::isnan (p.overlap_distance),
             "overlap_distance",
             static_cast<double> (p.overlap_distance),
             "a number");
  c.require (p.triplets_per_keypoint >= 1,
             "triplets_per_keypoint",
             p.triplets_per_keypoint,
             ">= 1");
  c.require (p.max_triplets >= 1,
             "max_triplets",
             static_cast<double> (p.max_triplets),
             ">= 1");
  c.require (p.cluster_distance > 0.0f,
             "cluster_distance",
             static_cast<double> (p.cluster_distance),
             "> 0");
  c.require (p.min_cluster_size >= 1,
             "min_cluster_size",
             static_cast<double> (p.min_cluster_size),
             ">= 1");
  c.require (p.verification_radius > 0.0f,
             "verification_radius",
             static_cast<double> (p.verification_radius),
             "> 0");
  c.require (p.verification_depth_tolerance > 0.0f,
             "verification_depth_tolerance",
             static_cast<double> (p.verification_depth_tolerance),
             "> 0");
  c.require (p.max_chromaticity_difference > 0.0f,
             "max_chromaticity_difference",
             static_cast<double> (p.max_chromaticity_difference),
             "> 0");
  c.require (p.max_vivid_chromaticity_difference > 0.0f,
             "max_vivid_chromaticity_difference",
             static_cast<double> (p.max_vivid_chromaticity_difference),
             "> 0");
  c.require (p.min_photometric_correlation >= -1.0f &&
                 p.min_photometric_correlation <= 1.0f,
             "min_photometric_correlation",
             static_cast<double> (p.min_photometric_correlation),
             "in [-1, 1]");
  c.require (p.gc_size > 0.0, "gc_size", p.gc_size, "> 0");
  c.require (p.gc_threshold >= 3, "gc_threshold", p.gc_threshold, ">= 3");
  c.require (p.hough_bin_size > 0.0, "hough_bin_size", p.hough_bin_size, "> 0");
  c.require (p.hough_threshold > 0.0, "hough_threshold", p.hough_threshold, "> 0");
  c.require (
      p.lrf_radius > 0.0f, "lrf_radius", static_cast<double> (p.lrf_radius), "> 0");
  c.require (p.refinement_iterations >= 0,
             "refinement_iterations",
             p.refinement_iterations,
             ">= 0");
  c.require (p.duplicate_angle >= 0.0f,
             "duplicate_angle",
             static_cast<double> (p.duplicate_angle),
             ">= 0");
  c.require (p.duplicate_distance >= 0.0f,
             "duplicate_distance",
             static_cast<double> (p.duplicate_distance),
             ">= 0");
  c.require (p.link_tolerance > 0.0f,
             "link_tolerance",
             static_cast<double> (p.link_tolerance),
             "> 0");
  c.require (p.inlier_threshold > 0.0f,
             "inlier_threshold",
             static_cast<double> (p.inlier_threshold),
             "> 0");
  c.require (
      p.min_inliers >= 3, "min_inliers", static_cast<double> (p.min_inliers), ">= 3");
  c.require (p.min_merge_inliers >= 3,
             "min_merge_inliers",
             static_cast<double> (p.min_merge_inliers),
             ">= 3");
  c.require (p.merge_fraction >= 0.0f && p.merge_fraction <= 1.0f,
             "merge_fraction",
             static_cast<double> (p.merge_fraction),
             "in [0, 1]");
  c.require (p.region_margin >= 0.0f && std::isfinite (p.region_margin),
             "region_margin",
             static_cast<double> (p.region_margin),
             "finite and >= 0");
  c.require (p.leftover_descriptor_distance > 0.0f,
             "leftover_descriptor_distance",
             static_cast<double> (p.leftover_descriptor_distance),
             "> 0");
  c.require (p.leftover_margin >= 0.0f && std::isfinite (p.leftover_margin),
             "leftover_margin",
             static_cast<double> (p.leftover_margin),
             "finite and >= 0");
  c.require (p.box_search_margin >= 0.0f && std::isfinite (p.box_search_margin),
             "box_search_margin",
             static_cast<double> (p.box_search_margin),
             "finite and >= 0");
  c.require (p.box_search_hypotheses >= 1,
             "box_search_hypotheses",
             static_cast<double> (p.box_search_hypotheses),
             ">= 1");
  c.require (p.guided_seed_distance > 0.0f,
             "guided_seed_distance",
             static_cast<double> (p.guided_seed_distance),
             "> 0");
  c.require (p.guided_descriptor_distance > 0.0f,
             "guided_descriptor_distance",
             static_cast<double> (p.guided_descriptor_distance),
             "> 0");
  c.require (p.guided_min_inliers >= 3,
             "guided_min_inliers",
             static_cast<double> (p.guided_min_inliers),
             ">= 3");
  c.require (p.guided_min_correlation >= -1.0f && p.guided_min_correlation <= 1.0f,
             "guided_min_correlation",
             static_cast<double> (p.guided_min_correlation),
             "in [-1, 1]");
  c.require (p.guided_neighbourhood_correlation >= -1.0f &&
                 p.guided_neighbourhood_correlation <= 1.0f,
             "guided_neighbourhood_correlation",
             static_cast<double> (p.guided_neighbourhood_correlation),
             "in [-1, 1]");
  c.require (p.guided_max_disagreeing >= 0.0f && p.guided_max_disagreeing <= 1.0f,
             "guided_max_disagreeing",
             static_cast<double> (p.guided_max_disagreeing),
             "in [0, 1]");
  c.require (p.guided_hypotheses >= 1,
             "guided_hypotheses",
             static_cast<double> (p.guided_hypotheses),
             ">= 1");
  c.require (p.patch_radius > 0.0f && std::isfinite (p.patch_radius),
             "patch_radius",
             static_cast<double> (p.patch_radius),
             "finite and > 0");
  c.require (p.patch_min_keypoints >= 1,
             "patch_min_keypoints",
             static_cast<double> (p.patch_min_keypoints),
             ">= 1");
  c.require (p.patch_margin >= 0.0f && std::isfinite (p.patch_margin),
             "patch_margin",
             static_cast<double> (p.patch_margin),
             "finite and >= 0");
  c.require (p.patch_min_inliers >= 3,
             "patch_min_inliers",
             static_cast<double> (p.patch_min_inliers),
             ">= 3");
  c.require (p.patch_min_correlation >= -1.0f && p.patch_min_correlation <= 1.0f,
             "patch_min_correlation",
             static_cast<double> (p.patch_min_correlation),
             "in [-1, 1]");
  c.require (p.patch_drop_inliers >= 3,
             "patch_drop_inliers",
             static_cast<double> (p.patch_drop_inliers),
             ">= 3");
  c.require (p.patch_hypotheses >= 1,
             "patch_hypotheses",
             static_cast<double> (p.patch_hypotheses),
             ">= 1");
  c.require (p.split_min_correlation >= -1.0f && p.split_min_correlation <= 1.0f,
             "split_min_correlation",
             static_cast<double> (p.split_min_correlation),
             "in [-1, 1]");
  c.require (
      p.surface_sample_step >= 1, "surface_sample_step", p.surface_sample_step, ">= 1");
  c.require (p.surface_max_distance > 0.0f && std::isfinite (p.surface_max_distance),
             "surface_max_distance",
             static_cast<double> (p.surface_max_distance),
             "finite and > 0");
  c.require (p.surface_weight >= 0.0f && std::isfinite (p.surface_weight),
             "surface_weight",
             static_cast<double> (p.surface_weight),
             "finite and >= 0");
  c.require (
      p.surface_iterations >= 1, "surface_iterations", p.surface_iterations, ">= 1");
  c.require (p.size_tolerance >= 0.0f && std::isfinite (p.size_tolerance),
             "size_tolerance",
             static_cast<double> (p.size_tolerance),
             "finite and >= 0");
  c.require (p.relative_size_tolerance >= 0.0f &&
                 std::isfinite (p.relative_size_tolerance),
             "relative_size_tolerance",
             static_cast<double> (p.relative_size_tolerance),
             "finite and >= 0");
  c.require (p.size_merge_consensus_radius >= 0.0f &&
                 std::isfinite (p.size_merge_consensus_radius),
             "size_merge_consensus_radius",
             static_cast<double> (p.size_merge_consensus_radius),
             "finite and >= 0");
  c.require (p.repeated_print_max_rotation >= 0.0f &&
                 p.repeated_print_max_rotation <= static_cast<float> (M_PI),
             "repeated_print_max_rotation",
             static_cast<double> (p.repeated_print_max_rotation),
             "in [0, pi]");
  c.require (p.repeated_print_max_shift >= 0.0f &&
                 std::isfinite (p.repeated_print_max_shift),
             "repeated_print_max_shift",
             static_cast<double> (p.repeated_print_max_shift),
             "finite and >= 0");
  c.require (p.repeated_print_max_shift_along >= 0.0f &&
                 std::isfinite (p.repeated_print_max_shift_along),
             "repeated_print_max_shift_along",
             static_cast<double> (p.repeated_print_max_shift_along),
             "finite and >= 0");
  c.require (p.repeated_print_min_inside >= 0.0f && p.repeated_print_min_inside <= 1.0f,
             "repeated_print_min_inside",
             static_cast<double> (p.repeated_print_min_inside),
             "in [0, 1]");
  c.require (p.size_search_min_keypoints >= 1,
             "size_search_min_keypoints",
             p.size_search_min_keypoints,
             ">= 1");
  c.require (p.size_search_min_agreeing >= 1,
             "size_search_min_agreeing",
             p.size_search_min_agreeing,
             ">= 1");
  c.require (p.size_discovery_max_surrounded >= 0.0f &&
                 p.size_discovery_max_surrounded <= 1.0f,
             "size_discovery_max_surrounded",
             static_cast<double> (p.size_discovery_max_surrounded),
             "in [0, 1]");
  c.require (p.size_discovery_min_edge >= 0.0f &&
                 std::isfinite (p.size_discovery_min_edge),
             "size_discovery_min_edge",
             static_cast<double> (p.size_discovery_min_edge),
             "finite and >= 0");
  c.require (p.interpenetration_max_centre_distance >= 0.0f &&
                 p.interpenetration_max_centre_distance <= 1.0f,
             "interpenetration_max_centre_distance",
             static_cast<double> (p.interpenetration_max_centre_distance),
             "in [0, 1]");
  c.require (p.size_disagreement_max_surrounded >= 0.0f &&
                 p.size_disagreement_max_surrounded <= 1.0f,
             "size_disagreement_max_surrounded",
             static_cast<double> (p.size_disagreement_max_surrounded),
             "in [0, 1]");
  c.require (p.size_disagreement_min_copies >= 2,
             "size_disagreement_min_copies",
             static_cast<double> (p.size_disagreement_min_copies),
             ">= 2");
  c.require (p.box_turn_min_gain >= 0.0f && p.box_turn_min_gain <= 2.0f,
             "box_turn_min_gain",
             static_cast<double> (p.box_turn_min_gain),
             "in [0, 2]");
  c.require (p.support_print_min_share > 0.0f && p.support_print_min_share <= 1.0f,
             "support_print_min_share",
             static_cast<double> (p.support_print_min_share),
             "in (0, 1]");
  c.require (p.observation_max_residual > 0.0f &&
                 std::isfinite (p.observation_max_residual),
             "observation_max_residual",
             static_cast<double> (p.observation_max_residual),
             "finite and > 0");
  c.require (p.observation_box_margin >= 0.0f &&
                 std::isfinite (p.observation_box_margin),
             "observation_box_margin",
             static_cast<double> (p.observation_box_margin),
             "finite and >= 0");
  c.require (p.min_region_merge_inliers >= 3,
             "min_region_merge_inliers",
             static_cast<double> (p.min_region_merge_inliers),
             ">= 3");
  c.require (p.min_join_correlation >= -1.0f && p.min_join_correlation <= 1.0f,
             "min_join_correlation",
             static_cast<double> (p.min_join_correlation),
             "in [-1, 1]");
  c.require (p.min_inlier_ratio >= 0.0f && p.min_inlier_ratio < 1.0f,
             "min_inlier_ratio",
             static_cast<double> (p.min_inlier_ratio),
             "in [0, 1)");
  c.require (p.min_inlier_spread >= 0.0f,
             "min_inlier_spread",
             static_cast<double> (p.min_inlier_spread),
             ">= 0");
  c.require (
      p.ransac_iterations >= 1, "ransac_iterations", p.ransac_iterations, ">= 1");
  return c.ok();
}

} // namespace mid
