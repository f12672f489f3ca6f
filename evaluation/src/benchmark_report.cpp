#include <mid/evaluation/benchmark_report.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>

namespace mid {
namespace evaluation {

namespace {

template <typename T>
void
append (std::vector<T>& to, const std::vector<T>& from)
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

/** One row per scenario (`row (name, summary)`), in name order, then the "total" row of
  * them all summed.
  */
template <typename Row>
std::string
rowsWithTotal (const std::map<std::string, ScoreSummary>& scenarios, const Row& row)
{
  std::string rows;
  ScoreSummary total;
  for (const auto& [name, summary] : scenarios) {
    rows += row (name, summary);
    total.add (summary);
  }
  return rows + row ("total", total);
}

/** The scenarios of a method plus its "total" (all scenarios summed), by name. */
std::map<std::string, ScoreSummary>
withTotal (const std::map<std::string, ScoreSummary>& scenarios)
{
  std::map<std::string, ScoreSummary> all = scenarios;
  ScoreSummary total;
  for (const auto& [name, summary] : scenarios)
    total.add (summary);
  all["total"] = total;
  return all;
}

std::string
comparisonRow (const std::string& scenario,
               const std::string& method,
               const ScoreSummary& s,
               double reference_ms)
{
  const double ip = ScoreSummary::precision (s.instance_tp, s.instance_fp);
  const double ir = ScoreSummary::recall (s.instance_tp, s.instance_fn);
  const double pp = ScoreSummary::precision (s.pair_tp, s.pair_fp);
  const double pr = ScoreSummary::recall (s.pair_tp, s.pair_fn);
  const double grouping = median (s.grouping_times_ms);
  char line[360];
  std::snprintf (
      line,
      sizeof (line),
      "| %-10s | %-10s | %5.3f | %5.3f | %5.3f | %5.3f | %5.3f | %5.3f | %6.2f "
      "| %6.2f | %7.2f | %5.2f |\n",
      scenario.c_str(),
      method.c_str(),
      ip,
      ir,
      ScoreSummary::f1 (ip, ir),
      pp,
      pr,
      ScoreSummary::f1 (pp, pr),
      median (s.rotation_errors_deg),
      median (s.translation_errors_mm),
      grouping,
      grouping > 0.0 ? reference_ms / grouping
                     : std::numeric_limits<double>::quiet_NaN());
  return line;
}

/** The bins of formatSharedSurfaceReport(): the lower bound of each bin's shared cubes. */
constexpr int kSharedBins[] = {0, 1, 10, 30, 100};

std::string
sharedSurfaceRow (const std::string& name, const ScoreSummary& s, int min_shared_cells)
{
  const auto count = [] (const std::vector<int>& cells, int from, int to) {
    return static_cast<int> (std::count_if (
        cells.begin(), cells.end(), [&] (int c) { return c >= from && c < to; }));
  };
  std::string line =
      "| " + name + std::string (name.size() < 10 ? 10 - name.size() : 0, ' ');
  constexpr std::size_t bins = sizeof (kSharedBins) / sizeof (kSharedBins[0]);
  for (std::size_t b = 0; b < bins; ++b) {
    const int from = kSharedBins[b];
    const int to = b + 1 < bins ? kSharedBins[b + 1] : std::numeric_limits<int>::max();
    const int found = count (s.found_shared_cells, from, to);
    char cell[48];
    std::snprintf (cell,
                   sizeof (cell),
                   " | %3d / %3d",
                   found,
                   found + count (s.missed_shared_cells, from, to));
    line += cell;
  }
  const int max = std::numeric_limits<int>::max();
  const double precision = ScoreSummary::precision (s.instance_tp, s.instance_fp);
  const double recall =
      ScoreSummary::recall (count (s.found_shared_cells, min_shared_cells, max),
                            count (s.missed_shared_cells, min_shared_cells, max));
  char tail[64];
  std::snprintf (tail,
                 sizeof (tail),
                 " | %5.3f | %5.3f | %5.3f |\n",
                 precision,
                 recall,
                 ScoreSummary::f1 (precision, recall));
  return line + tail;
}

/** "| count | median | share <= 5 mm | share <= 10 mm" of box size errors (millimetres). */
std::string
boxErrorColumns (const std::vector<double>& errors)
{
  const auto within = [&errors] (double limit) {
    const auto count = std::count_if (
        errors.begin(), errors.end(), [limit] (double e) { return e <= limit; });
    return errors.empty()
               ? 0.0
               : static_cast<double> (count) / static_cast<double> (errors.size());
  };
  char text[96];
  std::snprintf (text,
                 sizeof (text),
                 " | %5zu | %6.1f | %5.3f | %5.3f",
                 errors.size(),
                 median (errors),
                 within (5.0),
                 within (10.0));
  return text;
}

std::string
boxSizeRow (const std::string& name,
            const ScoreSummary& s,
            const ObjectSizeTable& sizes)
{
  std::size_t objects = 0;
  std::vector<double> errors, agreed_errors;
  for (const ObjectBox& box : s.object_boxes) {
    const auto truth = sizes.find (box.type);
    if (truth == sizes.end())
      continue;
    ++objects;
    if (box.copies < 1)
      continue;
    const double error = boxSizeErrorMm (box.size.cast<double>(), truth->second);
    errors.push_back (error);
    if (box.copies >= 2)
      agreed_errors.push_back (error);
  }
  char line[64];
  std::snprintf (line, sizeof (line), "| %-10s | %5zu", name.c_str(), objects);
  return line + boxErrorColumns (errors) + boxErrorColumns (agreed_errors) + " |\n";
}

/** " | count above (share)": how many of the errors exceed the threshold. */
std::string
aboveColumn (const std::vector<double>& errors, double threshold_deg)
{
  const auto above =
      std::count_if (errors.begin(), errors.end(), [threshold_deg] (double e) {
        return e > threshold_deg;
      });
  char text[48];
  std::snprintf (text,
                 sizeof (text),
                 " | %4td (%5.3f)",
                 above,
                 errors.empty() ? 0.0
                                : static_cast<double> (above) /
                                      static_cast<double> (errors.size()));
  return text;
}

/** " | median": the median of the errors. */
std::string
medianColumn (const std::vector<double>& errors)
{
  char text[32];
  std::snprintf (text, sizeof (text), " | %6.2f", median (errors));
  return text;
}

/** " | count": how many values there are. */
std::string
countColumn (std::size_t count)
{
  char text[32];
  std::snprintf (text, sizeof (text), " | %5zu", count);
  return text;
}

/** "| name" padded to the first column's width. */
std::string
nameColumn (const std::string& name)
{
  char text[96];
  std::snprintf (text, sizeof (text), "| %-10s", name.c_str());
  return text;
}

std::string
poseErrorRow (const std::string& name,
              const ScoreSummary& s,
              const std::vector<double>& thresholds_deg)
{
  const std::vector<double>& errors = s.rotation_errors_deg;
  std::string text = nameColumn (name) + countColumn (errors.size()) +
                     medianColumn (errors) + medianColumn (s.translation_errors_mm);
  for (const auto* values : {&errors, &s.symmetric_rotation_errors_deg})
    for (const double threshold : thresholds_deg)
      text += aboveColumn (*values, threshold);
  return text + " |\n";
}

/** One row of formatGroupPoseReport(): the pairs within one group, those across groups (also
  * modulo the shape's symmetries), and how many pairs have no groups.
  */
std::string
groupPoseRow (const std::string& name, const ScoreSummary& s, double threshold_deg)
{
  std::vector<double> within, across, across_symmetric;
  std::size_t without = 0;
  // The three vectors are appended together; at() makes a misalignment loud.
  for (std::size_t p = 0; p < s.pair_groups.size(); ++p) {
    if (s.pair_groups[p] == 1)
      within.push_back (s.rotation_errors_deg.at (p));
    else if (s.pair_groups[p] == 0) {
      across.push_back (s.rotation_errors_deg.at (p));
      across_symmetric.push_back (s.symmetric_rotation_errors_deg.at (p));
    }
    else
      ++without;
  }
  return nameColumn (name) + countColumn (within.size()) + medianColumn (within) +
         aboveColumn (within, threshold_deg) + countColumn (across.size()) +
         medianColumn (across) + aboveColumn (across, threshold_deg) +
         medianColumn (across_symmetric) +
         aboveColumn (across_symmetric, threshold_deg) + countColumn (without) + " |\n";
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
  append (symmetric_rotation_errors_deg, score.symmetric_rotation_errors_deg);
  append (pair_groups, score.pair_groups);
  append (found_shared_cells, score.found_shared_cells);
  append (missed_shared_cells, score.missed_shared_cells);
  append (translation_errors_mm, score.translation_errors_mm);
  append (object_boxes, score.object_boxes);
  if (result.total_ms >= 0.0)
    times_ms.push_back (result.total_ms);
  if (result.features_ms >= 0.0)
    feature_times_ms.push_back (result.features_ms);
  if (result.grouping_ms >= 0.0)
    grouping_times_ms.push_back (result.grouping_ms);
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
  append (symmetric_rotation_errors_deg, other.symmetric_rotation_errors_deg);
  append (pair_groups, other.pair_groups);
  append (found_shared_cells, other.found_shared_cells);
  append (missed_shared_cells, other.missed_shared_cells);
  append (translation_errors_mm, other.translation_errors_mm);
  append (times_ms, other.times_ms);
  append (feature_times_ms, other.feature_times_ms);
  append (grouping_times_ms, other.grouping_times_ms);
  append (object_boxes, other.object_boxes);
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
  return report + rowsWithTotal (scenarios, row);
}

std::string
formatSharedSurfaceReport (const std::map<std::string, ScoreSummary>& scenarios,
                           int min_shared_cells)
{
  std::string report =
      "| scenario   | found / annotated, sharing 0 cubes | 1-9 | 10-29 | "
      "30-99 | >= 100 | instances P | R (sharing >= " +
      std::to_string (min_shared_cells) +
      ") | F1 |\n|---|---|---|---|---|---|---|---|---|\n";
  return report +
         rowsWithTotal (
             scenarios,
             [min_shared_cells] (const std::string& name, const ScoreSummary& summary) {
               return sharedSurfaceRow (name, summary, min_shared_cells);
             });
}

std::string
formatPoseErrorReport (const std::map<std::string, ScoreSummary>& scenarios,
                       const std::vector<double>& thresholds_deg)
{
  std::string report =
      "| scenario   | instance pairs | rot. err. deg (median) | transl. "
      "err. mm (median)";
  std::string rule = "|---|---|---|---";
  for (const char* modulo : {"", " mod. symmetry"})
    for (const double threshold : thresholds_deg) {
      char column[64];
      std::snprintf (
          column, sizeof (column), " | rot. err. > %g deg%s", threshold, modulo);
      report += column;
      rule += "|---";
    }
  report += " |\n" + rule + "|\n";
  return report + rowsWithTotal (scenarios,
                                 [&thresholds_deg] (const std::string& name,
                                                    const ScoreSummary& summary) {
                                   return poseErrorRow (name, summary, thresholds_deg);
                                 });
}

std::string
formatGroupPoseReport (const std::map<std::string, ScoreSummary>& scenarios,
                       double threshold_deg)
{
  char header[512];
  std::snprintf (
      header,
      sizeof (header),
      "| scenario   | pairs in one group | rot. err. deg (median) | rot. err. > %g "
      "deg | pairs across groups | rot. err. deg (median) | rot. err. > %g deg | "
      "rot. err. deg mod. symmetry (median) | rot. err. > %g deg mod. symmetry | "
      "pairs without groups |\n|---|---|---|---|---|---|---|---|---|---|\n",
      threshold_deg,
      threshold_deg,
      threshold_deg);
  return header + rowsWithTotal (scenarios,
                                 [threshold_deg] (const std::string& name,
                                                  const ScoreSummary& summary) {
                                   return groupPoseRow (name, summary, threshold_deg);
                                 });
}

std::string
formatBoxSizeReport (const std::map<std::string, ScoreSummary>& scenarios,
                     const ObjectSizeTable& sizes)
{
  std::string report =
      "| scenario   | objects | with a box | edge err. mm (median) | <= 5 mm | "
      "<= 10 mm | box of 2+ copies | edge err. mm (median) | <= 5 mm | "
      "<= 10 mm |\n|---|---|---|---|---|---|---|---|---|---|\n";
  return report + rowsWithTotal (
                      scenarios,
                      [&sizes] (const std::string& name, const ScoreSummary& summary) {
                        return boxSizeRow (name, summary, sizes);
                      });
}

std::string
formatComparison (const std::vector<MethodScores>& methods)
{
  std::string report =
      "| scenario   | method     | instances P | R | F1 | pairs P | R | F1 | rot. err. "
      "deg "
      "(median) | transl. err. mm (median) | grouping ms (median) | time ratio |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  if (methods.empty())
    return report;
  std::vector<std::map<std::string, ScoreSummary>> all;
  all.reserve (methods.size());
  std::set<std::string> names;
  for (const auto& method : methods) {
    all.push_back (withTotal (method.scenarios));
    for (const auto& [name, summary] : method.scenarios)
      names.insert (name);
  }
  names.erase ("total");
  std::vector<std::string> scenarios (names.begin(), names.end());
  scenarios.emplace_back ("total");
  for (const auto& scenario : scenarios) {
    const auto reference = all.front().find (scenario);
    const double reference_ms = reference != all.front().end()
                                    ? median (reference->second.grouping_times_ms)
                                    : std::numeric_limits<double>::quiet_NaN();
    for (std::size_t m = 0; m < methods.size(); ++m) {
      const auto found = all[m].find (scenario);
      if (found != all[m].end())
        report +=
            comparisonRow (scenario, methods[m].name, found->second, reference_ms);
    }
  }
  return report;
}

} // namespace evaluation
} // namespace mid
