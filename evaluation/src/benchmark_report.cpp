#include <mid/evaluation/benchmark_report.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace mid {
namespace evaluation {

namespace {

void
append (std::vector<double>& to, const std::vector<double>& from)
{
  to.insert (to.end(), from.begin(), from.end());
}

std::string
row (const std::string& name, const ScoreSummary& s)
{
  const double ip = ScoreSummary::precision (s.instance_tp, s.instance_fp);
  const double ir = ScoreSummary::recall (s.instance_tp, s.instance_fn);
  const double pp = ScoreSummary::precision (s.pair_tp, s.pair_fp);
  const double pr = ScoreSummary::recall (s.pair_tp, s.pair_fn);
  char line[320];
  std::snprintf (line,
                 sizeof (line),
                 "| %-10s | %4d | %5.3f | %5.3f | %5.3f | %4d | %5.3f | %5.3f | %5.3f "
                 "| %6.2f | %6.2f | %7.1f | %7.1f |\n",
                 name.c_str(),
                 s.frames,
                 ip,
                 ir,
                 ScoreSummary::f1 (ip, ir),
                 s.pair_frames,
                 pp,
                 pr,
                 ScoreSummary::f1 (pp, pr),
                 median (s.rotation_errors_deg),
                 median (s.translation_errors_mm),
                 median (s.times_ms),
                 median (s.feature_times_ms));
  return line;
}

} // namespace

void
ScoreSummary::add (const FrameScore& score, const DetectionResult& result)
{
  ++frames;
  instance_tp += score.instance_tp;
  instance_fp += score.instance_fp;
  instance_fn += score.instance_fn;
  if (score.pairs_only) {
    ++pair_frames;
    pair_tp += score.pair_tp;
    pair_fp += score.pair_fp;
    pair_fn += score.pair_fn;
  }
  append (rotation_errors_deg, score.rotation_errors_deg);
  append (translation_errors_mm, score.translation_errors_mm);
  if (result.total_ms >= 0.0)
    times_ms.push_back (result.total_ms);
  if (result.features_ms >= 0.0)
    feature_times_ms.push_back (result.features_ms);
}

void
ScoreSummary::add (const ScoreSummary& other)
{
  frames += other.frames;
  pair_frames += other.pair_frames;
  instance_tp += other.instance_tp;
  instance_fp += other.instance_fp;
  instance_fn += other.instance_fn;
  pair_tp += other.pair_tp;
  pair_fp += other.pair_fp;
  pair_fn += other.pair_fn;
  append (rotation_errors_deg, other.rotation_errors_deg);
  append (translation_errors_mm, other.translation_errors_mm);
  append (times_ms, other.times_ms);
  append (feature_times_ms, other.feature_times_ms);
}

double
median (std::vector<double> values)
{
  if (values.empty())
    return std::numeric_limits<double>::quiet_NaN();
  const auto middle = values.begin() + static_cast<std::ptrdiff_t> (values.size() / 2);
  std::nth_element (values.begin(), middle, values.end());
  if (values.size() % 2 == 1)
    return *middle;
  return 0.5 * (*middle + *std::max_element (values.begin(), middle));
}

std::string
formatReport (const std::map<std::string, ScoreSummary>& scenarios)
{
  std::string report = "| scenario   | frames | instances P | R | F1 | pair frames | "
                       "pairs P | R | F1 | rot. err. deg (median) | transl. err. mm "
                       "(median) | time ms (median) | SIFT ms (median) |\n"
                       "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  ScoreSummary total;
  for (const auto& [name, summary] : scenarios) {
    report += row (name, summary);
    total.add (summary);
  }
  report += row ("total", total);
  return report;
}

} // namespace evaluation
} // namespace mid
