#pragma once

#include <mid/evaluation/frame_score.h>
#include <mid/evaluation/object_size.h>

#include <map>
#include <string>
#include <vector>

namespace mid {
namespace evaluation {

/** \brief Scores summed over frames (one scenario, or all). */
struct ScoreSummary
{
  /** \brief Frames added. */
  int frames = 0;
  int pair_frames = 0; ///< frames counted for the pair scores (FrameScore::pairs_only)
  /** \brief Instances: true positives, false positives, false negatives, over all frames. */
  ///@{
  int instance_tp = 0, instance_fp = 0, instance_fn = 0;
  ///@}
  /** \brief Pairs: true positives, false positives, false negatives, over the pair frames. */
  ///@{
  int pair_tp = 0, pair_fp = 0, pair_fn = 0;
  ///@}
  /** \brief Every relative pose error of the frames (FrameScore): rotation in degrees,
    * translation in millimetres.
    */
  ///@{
  std::vector<double> rotation_errors_deg, translation_errors_mm;
  ///@}
  /** \brief The rotation errors modulo the shape's symmetries
    * (FrameScore::symmetric_rotation_errors_deg), in the same order.
    */
  std::vector<double> symmetric_rotation_errors_deg;
  /** \brief For each of those pairs, FrameScore::pair_groups (1 in one group, 0 in two, -1
    * without groups), in the same order.
    */
  std::vector<int> pair_groups;
  /** \brief Time per frame, and of SIFT extraction alone (milliseconds), of the frames whose
    * result gives them (DetectionResult::total_ms, DetectionResult::features_ms).
    */
  ///@{
  std::vector<double> times_ms, feature_times_ms, grouping_times_ms;
  ///@}
  /** \brief The shared surface of every found and every missed annotated instance of a
    * repeated type (FrameScore::found_shared_cells, FrameScore::missed_shared_cells).
    */
  ///@{
  std::vector<int> found_shared_cells, missed_shared_cells;
  ///@}
  /** \brief The box of every valid object (FrameScore::object_boxes). */
  std::vector<ObjectBox> object_boxes;

  /** \brief Add one frame; its pair counts only if it holds only pairs.
    * \param[in] score the frame's score (scoreFrame())
    * \param[in] result the frame's result, for its times (negative ones are left out)
    */
  void
  add (const FrameScore& score, const DetectionResult& result);

  /** \brief Add another summary.
    * \param[in] other the summary whose counts and values are added to this one
    */
  void
  add (const ScoreSummary& other);

  /** \brief Precision tp / (tp + fp), recall tp / (tp + fn) and F1 = 2 p r / (p + r) of the
    * counts (or of precision p and recall r), in [0, 1]; 0 where undefined (zero denominator).
    */
  ///@{
  static double
  precision (int tp, int fp)
  {
    return tp + fp > 0 ? static_cast<double> (tp) / (tp + fp) : 0.0;
  }
  static double
  recall (int tp, int fn)
  {
    return tp + fn > 0 ? static_cast<double> (tp) / (tp + fn) : 0.0;
  }
  static double
  f1 (double p, double r)
  {
    return p + r > 0.0 ? 2.0 * p * r / (p + r) : 0.0;
  }
  ///@}
};

/** \brief Median of values, NaN if empty.
  * \param[in] values the values (taken by copy, as they are partly sorted)
  * \return the middle value, or the mean of the two middle values for an even count
  */
double
median (std::vector<double> values);

/** \brief A Table-2-style report: per scenario and in total, precision and recall on instances
  * and on pairs (pair-only frames), F1, median relative pose error, and median time per frame
  * next to the time of SIFT extraction alone.
  * \param[in] scenarios the summary of each scenario, by name; the total row sums them all
  * \return a Markdown table, one line per scenario and one for the total
  */
std::string
formatReport (const std::map<std::string, ScoreSummary>& scenarios);

/** \brief Recall against the surface an instance shares with another copy of its type
  * (measureSharedSurface()): per scenario and in total, found / annotated instances of repeated
  * types for 0, 1 to 9, 10 to 29, 30 to 99 and 100 or more shared cubes, then recall and F1 when
  * only the instances sharing at least `min_shared_cells` count as annotated. Precision is the
  * full table's: every reported instance still counts. Instances whose surface was not measured
  * are left out of every column.
  * \param[in] scenarios the summary of each scenario, by name; the total row sums them all
  * \param[in] min_shared_cells the shared cubes from which an instance counts as findable
  * \return a Markdown table, one line per scenario and one for the total
  */
std::string
formatSharedSurfaceReport (const std::map<std::string, ScoreSummary>& scenarios,
                           int min_shared_cells);

/** \brief How many relative poses inside one object are wrong: per scenario and in total, the
  * number of pairs of correctly found instances of one object (FrameScore::rotation_errors_deg),
  * their median rotation and translation errors, and how many of them (count and share) have a
  * rotation error above each threshold, then above each threshold modulo the symmetries of the
  * object's shape (FrameScore::symmetric_rotation_errors_deg). The median alone hides an object
  * glued from groups of copies that are right among themselves but turned against each other:
  * every instance is correct by the paper's rules, yet the poses across the groups are wrong
  * for picking, unless they differ by a symmetry of the shape (a square carton turned a
  * quarter turn about its long axis fills the same space).
  * \param[in] scenarios the summary of each scenario, by name; the total row sums them all
  * \param[in] thresholds_deg the rotation errors (degrees) above which a pair is counted, one
  * column each, e.g. {10, 45}
  * \return a Markdown table, one line per scenario and one for the total
  */
std::string
formatPoseErrorReport (const std::map<std::string, ScoreSummary>& scenarios,
                       const std::vector<double>& thresholds_deg);

/** \brief The same pairs split by the result's groups (FrameScore::pair_groups): per scenario
  * and in total, the pairs whose instances are in one group (their relative pose rests on
  * their print) with their median rotation error and how many are wrong by more than
  * `threshold_deg`, then the same for the pairs across two groups (relative poses that rest on
  * a box), there also modulo the shape's symmetries, and last how many pairs have no groups
  * (results of the detect app or from before the groups), which neither count holds. Tells
  * whether the groups say which relative poses a picker can trust for the print side.
  * \param[in] scenarios the summary of each scenario, by name; the total row sums them all
  * \param[in] threshold_deg the rotation error (degrees) above which a pair is counted wrong
  * \return a Markdown table, one line per scenario and one for the total
  */
std::string
formatGroupPoseReport (const std::map<std::string, ScoreSummary>& scenarios,
                       double threshold_deg);

/** \brief How well the objects' boxes (the result JSON's "box") give the products' sizes: per
  * scenario and in total, the valid objects (FrameScore::object_boxes), how many have a box,
  * the median and the shares of 5 and 10 mm or less of the largest edge error
  * (boxSizeErrorMm()), then the same for the boxes that two or more measured copies agree on.
  * Objects of a type without a size in `sizes` are left out.
  * \param[in] scenarios the summary of each scenario, by name; the total row sums them all
  * \param[in] sizes the true size of each type (loadBopModelSizes())
  * \return a Markdown table, one line per scenario and one for the total
  */
std::string
formatBoxSizeReport (const std::map<std::string, ScoreSummary>& scenarios,
                     const ObjectSizeTable& sizes);

/** \brief One method's scores per scenario, with the method's name (see formatComparison()). */
struct MethodScores
{
  /** \brief The method's name in the table (e.g. "triplets", "gcg"). */
  std::string name;
  /** \brief The method's summary per scenario, by scenario name. */
  std::map<std::string, ScoreSummary> scenarios;
};

/** \brief Methods side by side on the same frames: per scenario (and in total) one line per
  * method with precision, recall and F1 on instances and pairs, the median relative pose
  * error, the median time of the grouping stage (triplets + clustering, or the peer's
  * correspondence grouping) and the ratio of the first method's median grouping time to this
  * method's (below 1: the first method is faster).
  * \param[in] methods the methods, the first one being the reference of the time ratio; a
  * scenario missing from a method is left out for that method
  * \return a Markdown table
  */
std::string
formatComparison (const std::vector<MethodScores>& methods);

} // namespace evaluation
} // namespace mid
