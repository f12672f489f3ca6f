#pragma once

#include <mid/evaluation/frame_score.h>

#include <map>
#include <string>
#include <vector>

namespace mid {
namespace evaluation {

/** \brief Scores summed over frames (one scenario, or all). */
struct ScoreSummary
{
  int frames = 0;
  int pair_frames = 0; ///< frames counted for the pair scores (FrameScore::pairs_only)
  int instance_tp = 0, instance_fp = 0, instance_fn = 0;
  int pair_tp = 0, pair_fp = 0, pair_fn = 0;
  std::vector<double> rotation_errors_deg, translation_errors_mm;
  std::vector<double> times_ms, feature_times_ms;

  /** \brief Add one frame; its pair counts only if it holds only pairs. */
  void
  add (const FrameScore& score, const DetectionResult& result);

  /** \brief Add another summary. */
  void
  add (const ScoreSummary& other);

  /** \brief Precision, recall and F1 (0 where undefined). */
  static double
  precision (int tp, int fp) { return tp + fp > 0 ? static_cast<double> (tp) / (tp + fp) : 0.0; }
  static double
  recall (int tp, int fn) { return tp + fn > 0 ? static_cast<double> (tp) / (tp + fn) : 0.0; }
  static double
  f1 (double p, double r) { return p + r > 0.0 ? 2.0 * p * r / (p + r) : 0.0; }
};

/** \brief Median of values, NaN if empty. */
double
median (std::vector<double> values);

/** \brief A Table-2-style report: per scenario and in total, precision and recall on instances
  * and on pairs (pair-only frames), F1, median relative pose error, and median time per frame
  * next to the time of SIFT extraction alone.
  */
std::string
formatReport (const std::map<std::string, ScoreSummary>& scenarios);

} // namespace evaluation
} // namespace mid
