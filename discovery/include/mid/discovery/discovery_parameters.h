#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

namespace mid {

/** \brief Which method groups the self-matches into pairs of instances. */
enum class Grouping {
  /** \brief Ours: PPF triplet rejector + transformation-space DBSCAN (the paper). */
  triplets,
  /** \brief PCL's GeometricConsistencyGrouping on the same self-matches (a peer). */
  geometric_consistency,
  /** \brief PCL's Hough3DGrouping with BOARD reference frames (a peer). */
  hough3d
};

/** \brief Every parameter of the discovery pipeline, with the values of Abbeloos et al.
  * (3DV 2017, Sec. 4) as defaults where the paper gives one. Lengths in metres, angles in
  * radians. The range each value must lie in is given in brackets; validateDiscoveryParameters()
  * checks them, and MultiInstanceDiscovery::discover() and discoverFromKeypoints() refuse (with
  * a PCL_ERROR) parameters that fail it.
  */
struct DiscoveryParameters
{
  // --- Keypoints (SIFTKeypointExtractor) ---
  /** \brief Keep at most this many keypoints, strongest first; 0 keeps all (>= 0). */
  int max_keypoints = 0;
  /** \brief SIFT contrast threshold (OpenCV's default; > 0). */
  double contrast_threshold = 0.04;
  /** \brief Radius of the neighbourhood a keypoint normal is fitted to (> 0). */
  float normal_radius = 0.015f;

  // --- Self-matching (SelfMatcher) ---
  /** \brief Largest SIFT descriptor distance of a match (the paper thresholds it, no value;
    * > 0). 350 was chosen on the development frames of the benchmark (seed 2, not the scored
    * seed 1): instance F1 0.30, 0.40, 0.45, 0.44 at 250, 300, 350, 400 (doc/benchmark.md).
    */
  float max_descriptor_distance = 350.0f;
  /** \brief A keypoint cannot match another closer than this in 3D (>= 0). */
  float min_keypoint_distance = 0.01f;
  /** \brief Lowe's ratio test, 1 = off (it would drop matches when 3+ instances exist; in
    * (0, 1]).
    */
  float max_distance_ratio = 1.0f;
  /** \brief Keep only mutual best matches. */
  bool mutual_check = false;
  /** \brief Matches per keypoint: its k most similar other keypoints (>= 1; 1 is the paper's
    * choice; see SelfMatcher::setMaxMatchesPerKeypoint()).
    */
  int matches_per_keypoint = 1;

  // --- Triplets (CorrespondenceRejectorPPFTriplet) ---
  /** \brief Point pair feature thresholds: distance difference 5 mm (>= 0) and angle difference
    * 35 degrees (in [0, pi]).
    */
  ///@{
  float ppf_distance = 0.005f;
  float ppf_angle = static_cast<float> (35.0 * M_PI / 180.0);
  ///@}
  /** \brief Triangle edges between 10 mm (> 0) and 125 mm (>= min_edge_length), every angle
    * above 10 degrees (min_triangle_angle in [0, pi/3)).
    */
  ///@{
  float min_edge_length = 0.010f;
  float max_edge_length = 0.125f;
  float min_triangle_angle = static_cast<float> (10.0 * M_PI / 180.0);
  ///@}
  /** \brief Triangles closer than this overlap (one instance); negative disables the test (not
    * NaN).
    */
  float overlap_distance = 0.005f;
  /** \brief L: accepted triplets per keypoint (the paper's L, no value given; >= 1). */
  int triplets_per_keypoint = 10;
  /** \brief Hard cap on accepted triplets (memory bound; >= 1). */
  std::size_t max_triplets = 200000;

  // --- Clustering (TransformationSpaceClustering) ---
  /** \brief DBSCAN eps: 35 mm (> 0). */
  float cluster_distance = 0.035f;
  /** \brief DBSCAN min samples, the smallest cluster: 14 (>= 1). */
  std::size_t min_cluster_size = 14;
  /** \brief Split clusters that link a regular row of copies into neighbour pairs (not in the
    * paper, which lists rows as a limitation; see TransformationSpaceClustering::setSplitChains()).
    */
  bool split_chains = true;
  /** \brief Split clusters whose point sets span two touching copies: half turns and pairs of
    * pairs (not in the paper, which lists pairs sharing one relative pose as a limitation; see
    * TransformationSpaceClustering::setSplitCompounds()).
    */
  bool split_compounds = true;

  // --- Verification (PhotometricVerification; every grouping) ---
  /** \brief Keep only the clusters whose pose carries the look of the surface around one point
    * set onto the other (not in the paper: chance matches on shiny parts can agree on a pose
    * that moves one part onto another; see PhotometricVerification). Needs the organized
    * colour frame: without one (discoverFromKeypoints() given none), or when no pinhole camera
    * fits it (a frame moved out of its camera's coordinates: a PCL_WARN), nothing is checked.
    */
  bool verify_clusters = true;
  /** \brief How far around a keypoint the surface is compared (metres, > 0). */
  float verification_radius = 0.015f;
  /** \brief How far the frame's surface may lie from a moved point (metres, > 0). */
  float verification_depth_tolerance = 0.01f;
  /** \brief The smallest grey-level correlation of a kept cluster, each way (in [-1, 1];
    * stricter than PhotometricVerification's own 0.4: a cluster that moves one print onto a
    * look-alike part of another is better dropped, as the later stages then find the copies
    * at their right pose; doc/benchmark.md, session 30).
    */
  float min_photometric_correlation = 0.6f;
  /** \brief The largest difference of the mean chromaticities (|dr| + |dg| of the red and
    * green shares) of the two sides of the surface a pose compares, for the verified clusters, the guided search and
    * the patches (> 0; 2 or more: colours never reject; not in the paper: grey levels alone
    * confuse two products whose prints share small dark text on a light ground, see
    * PhotometricVerification::setMaxChromaticityDifference()).
    */
  float max_chromaticity_difference = 0.1f;
  /** \brief The same over the vivid colours alone (> 0; 2 or more: off; not in the paper;
    * PhotometricVerification::setMaxVividChromaticityDifference()): the inks, where two
    * products of one brand that share a layout, a font and a white ground differ. Seeds 1 / 3
    * / 4 and the pairs: instance F1 0.954 / 0.926 / 0.926 / 0.922 -> 0.956 / 0.931 / 0.926 /
    * 0.936, every real frame's count unchanged (doc/benchmark.md, session 42).
    */
  float max_vivid_chromaticity_difference = 0.15f;

  // --- Peers (used instead of triplets + clustering when grouping is not Grouping::triplets) ---
  /** \brief The grouping method. */
  Grouping grouping = Grouping::triplets;
  /** \brief GeometricConsistencyGrouping: consensus set resolution (metres, > 0) and smallest
    * group (>= 3).
    */
  ///@{
  double gc_size = 0.01;
  int gc_threshold = 8;
  ///@}
  /** \brief Hough3DGrouping: bin size (metres, > 0) and vote threshold (> 0); BOARD frames of
    * radius lrf_radius (metres, > 0) on the surface around each keypoint.
    */
  ///@{
  double hough_bin_size = 0.04;
  double hough_threshold = 3.0;
  float lrf_radius = 0.03f;
  ///@}

  // --- Models (MultiInstanceModelBuilder) ---
  /** \brief Alternations of the joint landmark / pose refinement (>= 0; 0 skips it). */
  int refinement_iterations = 20;
  /** \brief Instances whose poses differ by less than this rotation (radians, >= 0) and this
    * distance at the model centre (metres, >= 0) are one instance.
    */
  ///@{
  float duplicate_angle = static_cast<float> (10.0 * M_PI / 180.0);
  float duplicate_distance = 0.01f;
  ///@}
  /** \brief A link between two point sets that share a keypoint is dropped when the poses of
    * the other links put the sets this far apart (metres, > 0; not in the paper: a stray
    * keypoint otherwise ties two copies of a row into one instance). See
    * MultiInstanceModelBuilder::setLinkTolerance().
    */
  float link_tolerance = 0.04f;

  // --- Additional instances (ModelInstanceDetector) ---
  /** \brief Compare the models with each other and merge those that are one object. */
  bool merge_models = true;
  /** \brief Evidence for merging two models (not in the paper): the RANSAC of one model in the
    * other's landmarks must find the smaller of min_merge_inliers (>= 3) and merge_fraction (in
    * [0, 1]) of the smaller model's landmark count in inliers (descriptor matches), and never
    * fewer than min_inliers. The paper
    * compares models with the detection's 5 inliers; on the development frames five chance
    * matches then merged models of different products (a can row with a carton row), while
    * models of one product that share few landmarks are small. A fraction of 0 gives the
    * paper's rule.
    */
  ///@{
  std::size_t min_merge_inliers = 10;
  float merge_fraction = 0.3f;
  ///@}
  /** \brief Let copies join a model by descriptors and RANSAC only if they look like the
    * model's copies (not in the paper): a model merged into another (merge_models,
    * merge_through_regions) needs one of its copies and one of the other's that observe the
    * matched landmarks to show their common surface alike; an instance found by the
    * additional instance detection (detect_additional_instances) needs the same with the
    * model's copy that observes most of its landmarks. The test is the
    * PhotometricVerification of the matched keypoints' surroundings, with the verification's
    * radius, depth tolerance and largest chromaticity differences (all colours and the vivid
    * ones), and min_join_correlation (in
    * [-1, 1]) as the smallest grey-level correlation each way; where the frame cannot tell
    * (too few pairs, a uniform surface), the copy joins. Needs the organized colour frame, as
    * verify_clusters does. On the benchmark's frames, 5 to 7 descriptor matches between the
    * prints of two products, or at a wrong pose between two models of one product, merged
    * them: a relative pose wrong by more than 45 deg (modulo the shape's symmetries) in 17 of
    * 900 pairs of instances of one object on the scored frames, none with the check
    * (doc/benchmark.md, session 28).
    */
  ///@{
  bool verify_joins = true;
  float min_join_correlation = 0.4f;
  ///@}
  /** \brief Also merge models through the keypoints around their instances (not in the paper;
    * see RegionModelMerger): two models of one product built on different faces share no
    * landmark, but a copy of one often shows, next to its landmarks, surface that a copy of the
    * other shows too. The keypoints around an instance are those within region_margin (metres,
    * >= 0) of the box of its model's landmarks; a merge needs min_region_merge_inliers (>= 3)
    * RANSAC inliers (with the detection's inlier threshold and ratio).
    */
  ///@{
  bool merge_through_regions = true;
  float region_margin = 0.02f;
  std::size_t min_region_merge_inliers = 6;
  ///@}
  /** \brief Resolve instances that lie on one physical object (not in the paper; see
    * instancesOverlap() and instancesAdjoin()): models with such instances (overlapping, or
    * two faces of one copy) are merged, and of two overlapping instances of one model only
    * the one with more keypoints is kept. A model left with one
    * instance is dropped (one copy alone is no discovery).
    */
  bool resolve_overlaps = true;
  /** \brief Look for more instances among the keypoints no model uses. */
  bool detect_additional_instances = true;
  /** \brief A second discovery round on the keypoints left over (not in the paper): every stage
    * again, on the keypoints that no instance observes and that lie farther than leftover_margin
    * (metres, >= 0) from the box of every instance found (computeLandmarkBox() placed by the
    * instance's pose), self-matched among themselves up to
    * leftover_descriptor_distance (> 0). Their own best matches often lay on a product found
    * already, and between copies of one product many lie above max_descriptor_distance
    * (doc/benchmark.md). The new models are then merged with the first round's
    * (mergeMatchingModels() on the pairs with a new model) and overlaps resolved. Chosen on the
    * development frames: instance F1 0.768 -> 0.776 (seed 3), 0.766 -> 0.774 (seed 2).
    */
  ///@{
  bool discover_leftovers = true;
  float leftover_descriptor_distance = 450.0f;
  float leftover_margin = 0.01f;
  ///@}
  /** \brief After the additional instance detection, look for more instances of each model
    * from single keypoint matches (not in the paper; GuidedInstanceSearch): a pose from one
    * match (normals and SIFT orientations, its turn about the normal voted), checked by the
    * depth, by guided matches (at least guided_min_inliers, >= 3, within inlier_threshold) and
    * by the grey levels (guided_min_correlation each way, in [-1, 1]). Seed matches up to
    * guided_seed_distance (> 0), the most similar guided_hypotheses (>= 1) of them per model;
    * guided matches up to guided_descriptor_distance (> 0). Needs the organized colour frame
    * and the image keypoints (MultiInstanceDiscovery passes both). Chosen on the development
    * frames: instance F1 0.777 -> 0.786 (seed 3), 0.774 -> 0.780 (seed 2).
    *
    * A copy whose keypoint neighbourhoods disagree on their own (their grey-level correlation
    * below guided_neighbourhood_correlation, in [-1, 1]) in a share above
    * guided_max_disagreeing (in [0, 1]; 1: never) shows the layout of the model's print with
    * other words, another printed side: it joins the model with landmarks of its own
    * (GuidedInstanceSearch's unconfirmed copies), so that it shares no group with the copies
    * whose pose rests on the print (not in the paper; doc/benchmark.md, session 59). The
    * guided search of the patches keeps such copies as found.
    */
  ///@{
  bool guided_search = true;
  float guided_seed_distance = 450.0f;
  float guided_descriptor_distance = 500.0f;
  std::size_t guided_min_inliers = 6;
  float guided_min_correlation = 0.6f;
  float guided_neighbourhood_correlation = 0.3f;
  float guided_max_disagreeing = 0.3f;
  std::size_t guided_hypotheses = 500;
  ///@}
  /** \brief After the models from patches, the guided search once more (with the most similar
    * box_search_hypotheses, >= 1, seed matches per model), each model extended for it by the
    * keypoints that no instance observes and that lie in the box its copies occupy on the
    * support plane, placed at each instance and grown by box_search_margin (metres, >= 0;
    * not in the paper; ModelBoxExtender): a copy showing a face that a found copy shows but
    * the model's landmarks lack. Only keypoints off the table are candidates, and the
    * overlaps are resolved after the search (resolve_overlaps). After the search the
    * extension goes again, but for the landmarks that new copies observe. Needs guided_search,
    * the organized colour frame and the image keypoints. Chosen on the development frames:
    * instance F1 0.885 -> 0.889 (seed 3), 0.871 -> 0.881 (seed 4) (doc/benchmark.md, session
    * 32).
    */
  ///@{
  bool box_search = true;
  float box_search_margin = 0.005f;
  std::size_t box_search_hypotheses = 100;
  ///@}
  /** \brief After the second round, models from patches of the keypoints no instance
    * explains (not in the paper): where copies share too little surface for the triplets (a
    * few right matches, not 14 poses), the densest patch of keypoints farther than
    * patch_margin (metres, >= 0) from every instance's box (densestKeypointPatch(): at least
    * patch_min_keypoints, >= 1, within patch_radius, > 0) becomes a model with one instance,
    * and the guided search looks for more copies of it (with patch_min_inliers, >= 3, and
    * patch_min_correlation, in [-1, 1]: stricter than the guided search's, since a patch has
    * no second copy to vouch for it; the most similar patch_hypotheses, >= 1, seed matches). A patch model that matches another model on
    * patch_drop_inliers (>= 3) or more RANSAC inliers but does not merge with it is dropped;
    * the others merge as the second round's do. Up to max_patches patches per frame. Needs
    * the organized colour frame and the image keypoints. Chosen on the development frames:
    * instance F1 0.804 -> 0.815 (seed 3), 0.807 -> 0.825 (seed 2); doc/benchmark.md, session
    * 27.
    */
  ///@{
  bool patch_discovery = true;
  float patch_radius = 0.05f;
  std::size_t patch_min_keypoints = 8;
  float patch_margin = 0.04f;
  std::size_t patch_min_inliers = 7;
  float patch_min_correlation = 0.7f;
  std::size_t patch_drop_inliers = 3;
  std::size_t patch_hypotheses = 100;
  std::size_t max_patches = 10;
  ///@}
  /** \brief After the detection, in each round, split a model whose instances fall into
    * groups that do not look alike (not in the paper; AppearanceModelSplitter): two instances
    * are alike when the grey levels around their keypoints, moved by their relative pose,
    * correlate at split_min_correlation (in [-1, 1]) or more each way (over
    * verification_radius, with verification_depth_tolerance). Needs the organized colour
    * frame and the image keypoints (MultiInstanceDiscovery passes both). Off by default: on
    * the development frames it halves the pairs of one object whose relative pose is off by
    * more than 45 deg (111 -> 51 of about 800, seed 3), but the parts it makes of one product
    * are second models, which the paper's rules count as false positives (instance F1 0.786
    * -> 0.766; doc/benchmark.md, session 19).
    */
  ///@{
  bool split_by_appearance = false;
  float split_min_correlation = 0.4f;
  ///@}
  /** \brief After both rounds, refine every model's instance poses on the frame's depth (not
    * in the paper; SurfacePoseRefinement): each instance's surface samples (every
    * surface_sample_step pixels, >= 1, inside the landmarks' box grown by 5 mm) are aligned
    * point-to-plane with what the other instances show of the object, partners within
    * surface_max_distance (> 0), each weighted by surface_weight (>= 0) against one landmark
    * residual, for surface_iterations rounds (>= 1). Needs the organized frame
    * (MultiInstanceDiscovery passes it); changes poses and landmarks only, never which
    * instances are found.
    */
  ///@{
  bool surface_refinement = true;
  int surface_sample_step = 3;
  float surface_max_distance = 0.01f;
  float surface_weight = 1.0f;
  int surface_iterations = 4;
  ///@}
  /** \brief After the refinement on the depth, split a model whose copies occupy boxes of two
    * sizes on the support plane that differ on every edge (not in the paper;
    * ModelSizeSplitter): two products of one print layout joined into one model. Each size
    * needs at least two copies that agree on it (within the size tolerances below). Needs the
    * organized frame.
    */
  bool split_by_size = true;
  /** \brief Then merge models whose copies occupy boxes of one size on the support plane (not
    * in the paper; ModelSizeMerger): the second models of one product, made of copies that
    * show other faces than the first model's, which no descriptor links. Sizes agree when
    * each edge differs by at most the larger of size_tolerance (metres, >= 0) and
    * relative_size_tolerance (>= 0) times the edge. Two products of one size are merged too.
    * The merged model's instances are posed by their boxes, so their poses are right only up
    * to the box's symmetries (a half turn about an edge, a quarter turn of a square box).
    * Needs the organized frame (MultiInstanceDiscovery passes it). Seed-3 development frames:
    * F1 0.786 -> 0.793 (session 25) -> 0.804 (session 26: surfaces stopped at creases and
    * split between touching copies, a refitted plane), seed 2 0.780 -> 0.793 -> 0.807
    * (doc/benchmark.md).
    */
  ///@{
  bool merge_by_size = true;
  float size_tolerance = 0.006f;
  float relative_size_tolerance = 0.03f;
  ///@}
  /** \brief The size merge also joins two models when one's size is that of a consensus box
    * of the other's copies (ModelSizeMerger::setConsensusRadius()): the box of the pixels of a
    * copy's surface that lie within this distance (metres, >= 0; 0: no consensus boxes) of
    * another copy's surface in the model frame, without the neighbour the copy lies flush
    * with. Seed 3: instance F1 0.931 -> 0.937 (session 48, doc/benchmark.md).
    */
  float size_merge_consensus_radius = 0.02f;
  /** \brief After the size merge, drop the observations outside the box a model's copies
    * occupy on the support plane (not in the paper; ModelBoxPruning): when at least two of
    * its measured copies agree on its size, a keypoint farther than observation_box_margin
    * outside that box, placed by its instance's pose, is not the instance's; an instance left
    * with none goes (unless fewer than two would stay), and so do landmarks no instance
    * observes any longer. In a row of copies standing apart a model may take each copy's print
    * with its neighbour's (its landmark box then spans both, and bounds nothing): each instance
    * then holds its copy alone, and a copy freed may be found by the size search. Needs the
    * organized frame. Seeds 3 / 4: `rows` 0.967 -> 1.000 / 0.946 -> 0.959, seed 1 unchanged
    * (doc/benchmark.md, session 41).
    */
  bool prune_outside_box = true;
  /** \brief After the size merge, remove the instances that lie on one object with another
    * instance of their model, shifted along a print that repeats on it (not in the paper;
    * RepeatedPrintFilter): the other instance's object box (grown from its keypoints alone)
    * holds at least repeated_print_min_inside (in [0, 1]) of the instance's keypoints, the
    * two poses differ by less than repeated_print_max_rotation (radians, in [0, pi]) and move
    * the landmarks by less than repeated_print_max_shift (>= 0) times the box's shortest edge
    * and repeated_print_max_shift_along (>= 0) times its width along the shift.
    * A model left with one instance goes. Needs the organized frame. Scored frames: F1 0.877
    * -> 0.889, development 0.873 -> 0.879 and 0.863 -> 0.868 (doc/benchmark.md, session 30).
    */
  ///@{
  bool remove_repeated_prints = true;
  float repeated_print_max_rotation = 0.2617994f; // 15 deg
  float repeated_print_max_shift = 0.75f;
  float repeated_print_max_shift_along = 0.25f;
  float repeated_print_min_inside = 0.8f;
  ///@}
  /** \brief After the size merge, find the copies that show none of a model's landmarks by
    * the size of the box they occupy on the support plane (not in the paper;
    * SizeInstanceSearch): an object on the table that holds no instance's keypoint, at least
    * size_search_min_keypoints keypoints (>= 1) and the size of a model (size_tolerance,
    * relative_size_tolerance) becomes its instance, when at least size_search_min_agreeing
    * (>= 1) of the model's measured copies agree on that size. Its pose is right only up to
    * the box's symmetries. Needs the organized frame.
    */
  ///@{
  bool size_search = true;
  int size_search_min_keypoints = 2;
  int size_search_min_agreeing = 1;
  ///@}
  /** \brief With the size search, also make models of the objects that repeat with no two
    * copies showing the same surface, by size alone (not in the paper;
    * SizeInstanceSearch::setDiscoverModels()): two or more objects of no model's size, each
    * with a shortest edge of at least size_discovery_min_edge (metres, >= 0) and, when
    * size_discovery_max_surrounded (in [0, 1]) is below 1, standing alone on the support
    * plane (at most that share of the pixels around it hold something else than the plane
    * and its own box), with sizes that agree, become a model. Two different products of one
    * size standing apart become one model.
    */
  ///@{
  bool size_discovery = true;
  float size_discovery_max_surrounded = 1.0f;
  float size_discovery_min_edge = 0.03f;
  ///@}
  /** \brief After the size search, remove the instances of a model whose box would
    * interpenetrate another of its instances' box: box centres closer than
    * interpenetration_max_centre_distance (in [0, 1]) times the box's shortest edge (not in the
    * paper; InterpenetrationFilter). Needs the organized frame and a model size.
    */
  ///@{
  bool remove_interpenetrating = true;
  float interpenetration_max_centre_distance = 0.8f;
  ///@}
  /** \brief Then remove the models whose copies, at least size_disagreement_min_copies (>= 2)
    * of them, each standing alone on the table (at most size_disagreement_max_surrounded, in
    * [0, 1], of the pixels around its surface hold something else) and so measured whole,
    * agree on no size, two of them differing on every edge: the same print on different
    * products (not in the paper; SizeDisagreementFilter). Needs the organized frame.
    */
  ///@{
  bool remove_disagreeing_sizes = true;
  float size_disagreement_max_surrounded = 0.05f;
  int size_disagreement_min_copies = 3;
  ///@}
  /** \brief Then turn the groups of a model's copies that share no landmark with its other
    * copies (posed by their box alone, up to its symmetries) to the turn of the box whose
    * look the photometric verification confirms, when its correlation beats that of the
    * present turn by box_turn_min_gain (in [0, 2]) (not in the paper; BoxTurnResolver).
    * Needs the organized frame, its grey levels and projection, and a model size.
    */
  ///@{
  bool resolve_box_turns = true;
  float box_turn_min_gain = 0.1f;
  ///@}
  /** \brief Then remove the instances that lie flat in the support plane: at least
    * support_print_min_share (in (0, 1]) of their keypoints within 1 cm of it, and the surface
    * around them on it too; prints on the table such as sheets of paper with one layout, not
    * copies resting on it (not in the paper; SupportPrintFilter). Only where the plane is seen
    * to support what was found (an instance stands off it, none lies behind it). A model left
    * with one instance goes. Objects thinner than 1 cm lying flat on the table count as
    * prints. Needs the organized frame. On the IC-BIN frames it removes the objects made of
    * marker sheets (doc/benchmark.md, session 50).
    */
  ///@{
  bool remove_support_prints = true;
  float support_print_min_share = 0.8f;
  ///@}
  /** \brief Last, drop the observations that an instance's pose does not explain (not in the
    * paper; pruneUnexplainedObservations()): a keypoint farther than
    * observation_max_residual (metres, > 0; the paper's inlier threshold) from where the pose
    * puts its landmark, or farther than observation_box_margin (metres, >= 0; also the margin
    * of prune_outside_box) outside the
    * model's landmark box (unless the instance alone observes its landmark), is not the
    * instance's (a keypoint of a touching copy that a cluster spanning two copies brought in).
    * Landmarks that lose every observation go. The instances' keypoints and image boxes, what
    * the result reports, then hold only their copy. Scored frames: F1 0.889 -> 0.897 (`rows`
    * 0.964 -> 1.000), development 0.879 -> 0.880 and 0.868 -> 0.871 (doc/benchmark.md,
    * session 31). Before that, the same switch drops an instance's keypoints that lie amid
    * another instance's keypoints of its model (pruneObservationsOnOtherCopies(); since
    * session 51: seed 3 0.937 -> 0.940).
    */
  ///@{
  bool prune_observations = true;
  float observation_max_residual = 0.005f;
  float observation_box_margin = 0.02f;
  ///@}
  /** \brief RANSAC inlier threshold 5 mm (> 0), at least 5 inliers (>= 3), inlier ratio above
    * 12.5 % (min_inlier_ratio in [0, 1)); not in the paper: inliers spread at least
    * min_inlier_spread (metres, >= 0; 0: no test) off the line that fits them best, 3.5 mm
    * (the inlier threshold over sqrt(2), so that no quarter turn about the line keeps them
    * all), as keypoints along one line leave the turn about it free
    * (ModelInstanceDetector::setMinInlierSpread()); for instances among the frame's keypoints
    * only: models matched against models (merge_models, merge_through_regions, the leftover
    * round) share landmarks along a line, a row of print, and the test undid as many right
    * merges as wrong ones on the benchmark (doc/benchmark.md, session 55).
    */
  ///@{
  float inlier_threshold = 0.005f;
  std::size_t min_inliers = 5;
  float min_inlier_ratio = 0.125f;
  float min_inlier_spread = 0.0035f;
  ///@}
  /** \brief RANSAC hypotheses per detection (>= 1). */
  int ransac_iterations = 1000;
  /** \brief Seed of every random choice. */
  std::uint32_t seed = 0;
};

/** \brief Check every parameter's range (the ranges are given with DiscoveryParameters'
  * fields).
  * \param[in] parameters the parameters
  * \param[out] problem which parameter is wrong and what it must be; empty if all are valid
  * \return true if all are valid
  */
bool
validateDiscoveryParameters (const DiscoveryParameters& parameters,
                             std::string& problem);

} // namespace mid
