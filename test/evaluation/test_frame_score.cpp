// The evaluator scores hand-built results exactly as the paper's rules say.

#include <mid/evaluation/benchmark_report.h>
#include <mid/evaluation/frame_score.h>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

namespace {

using mid::evaluation::DetectedInstance;
using mid::evaluation::DetectedObject;
using mid::evaluation::DetectionResult;
using mid::evaluation::GroundTruthFrame;
using mid::evaluation::GroundTruthInstance;

/** Annotated instances: type and visible box (100 x 100 px at column x, row 100), a pose each. */
GroundTruthFrame
frame (const std::vector<std::pair<int, int>>& type_and_x)
{
  GroundTruthFrame f;
  for (std::size_t k = 0; k < type_and_x.size(); ++k) {
    GroundTruthInstance i;
    i.object_id = type_and_x[k].first;
    i.bbox_visible = cv::Rect (type_and_x[k].second, 100, 100, 100);
    i.pose.topLeftCorner<3, 3>() =
        Eigen::AngleAxisf (0.3f * static_cast<float> (k), Eigen::Vector3f::UnitY())
            .toRotationMatrix();
    i.pose.topRightCorner<3, 1>() =
        Eigen::Vector3f (0.2f * static_cast<float> (k), 0.0f, 1.0f);
    f.instances.push_back (i);
  }
  return f;
}

/** A detected instance with `inside` keypoints in the box at column x and `outside` far away,
  * and the given pose.
  */
DetectedInstance
instance (int x,
          int inside,
          int outside = 0,
          const Eigen::Matrix4f& pose = Eigen::Matrix4f::Identity())
{
  DetectedInstance d;
  d.pose = pose;
  for (int i = 0; i < inside; ++i)
    d.keypoints.emplace_back (static_cast<float> (x + 10 + i), 150.0f);
  for (int i = 0; i < outside; ++i)
    d.keypoints.emplace_back (5.0f, 5.0f + static_cast<float> (i));
  return d;
}

/** The truthful pose of annotated instance k, in a model frame offset by `model` (any). */
Eigen::Matrix4f
truePose (const GroundTruthFrame& f,
          std::size_t k,
          const Eigen::Matrix4f& model = Eigen::Matrix4f::Identity())
{
  return f.instances[k].pose * model;
}

} // namespace

TEST (FrameScore, APerfectResult)
{
  // Types 1 (three copies) and 2 (two copies) and a distractor of type 3.
  const auto f = frame ({{1, 0}, {1, 150}, {1, 300}, {2, 450}, {2, 600}, {3, 750}});
  Eigen::Matrix4f offset = Eigen::Matrix4f::Identity();
  offset.topRightCorner<3, 1>() =
      Eigen::Vector3f (0.01f, 0.02f, -0.03f); // model frame is arbitrary
  DetectionResult r;
  r.objects.push_back ({{instance (0, 20, 0, truePose (f, 0, offset)),
                         instance (150, 20, 0, truePose (f, 1, offset)),
                         instance (300, 20, 0, truePose (f, 2, offset))}});
  r.objects.push_back ({{instance (450, 20, 0, truePose (f, 3)),
                         instance (600, 20, 0, truePose (f, 4))}});
  const auto s = mid::evaluation::scoreFrame (f, r);
  EXPECT_EQ (s.instance_tp, 5);
  EXPECT_EQ (s.instance_fp, 0);
  EXPECT_EQ (s.instance_fn, 0); // the distractor is not expected
  EXPECT_EQ (s.pair_tp, 2);
  EXPECT_EQ (s.pair_fp, 0);
  EXPECT_EQ (s.pair_fn, 0);
  EXPECT_FALSE (s.pairs_only);
  ASSERT_EQ (s.rotation_errors_deg.size(), 3u + 1u);
  for (std::size_t i = 0; i < s.rotation_errors_deg.size(); ++i) {
    EXPECT_NEAR (s.rotation_errors_deg[i], 0.0, 1e-3);
    EXPECT_NEAR (s.translation_errors_mm[i], 0.0, 1e-3);
  }
}

TEST (FrameScore, AnEmptyResultMissesEveryRepeatedInstance)
{
  const auto f = frame ({{1, 0}, {1, 150}, {2, 300}});
  const auto s = mid::evaluation::scoreFrame (f, DetectionResult());
  EXPECT_EQ (s.instance_tp, 0);
  EXPECT_EQ (s.instance_fp, 0);
  EXPECT_EQ (s.instance_fn, 2);
  EXPECT_EQ (s.pair_fn, 1);
  EXPECT_TRUE (s.pairs_only);
}

TEST (FrameScore, TheNinetyPercentRuleDecidesWhereAnInstanceIs)
{
  const auto f = frame ({{1, 0}, {1, 150}});
  DetectionResult r;
  // 18 of 20 inside (90 %): correct; 17 of 20: not.
  r.objects.push_back ({{instance (0, 18, 2), instance (150, 17, 3)}});
  const auto s = mid::evaluation::scoreFrame (f, r);
  EXPECT_EQ (s.instance_tp, 1);
  EXPECT_EQ (s.instance_fp, 1);
  EXPECT_EQ (s.instance_fn, 1);
  EXPECT_EQ (s.pair_fp, 1); // only one true instance: no pair
  EXPECT_EQ (s.pair_fn, 1);
}

TEST (FrameScore, WrongModelsAndDuplicatesAreFalsePositives)
{
  const auto f = frame ({{1, 0}, {1, 150}, {3, 300}});
  DetectionResult r;
  r.objects.push_back ({{instance (0, 20), instance (150, 20)}}); // right
  r.objects.push_back (
      {{instance (0, 20), instance (150, 20)}}); // a second model of type 1
  r.objects.push_back (
      {{instance (300, 20), instance (300, 20)}}); // the distractor, twice
  r.objects.push_back ({{instance (900, 20), instance (950, 20)}}); // on nothing
  const auto s = mid::evaluation::scoreFrame (f, r);
  EXPECT_EQ (s.instance_tp, 2);
  EXPECT_EQ (s.instance_fp, 6);
  EXPECT_EQ (s.instance_fn, 0);
  EXPECT_EQ (s.pair_tp, 1);
  EXPECT_EQ (s.pair_fp, 3);
}

TEST (FrameScore, OneInstanceDetectedTwiceCountsOnce)
{
  const auto f = frame ({{1, 0}, {1, 150}, {1, 300}});
  DetectionResult r;
  r.objects.push_back ({{instance (0, 20), instance (0, 15), instance (150, 20)}});
  const auto s = mid::evaluation::scoreFrame (f, r);
  EXPECT_EQ (s.instance_tp, 2);
  EXPECT_EQ (s.instance_fp, 1);
  EXPECT_EQ (s.instance_fn, 1);
  EXPECT_EQ (s.pair_tp, 1);
}

TEST (FrameScore, RelativePoseErrorsAreMeasured)
{
  const auto f = frame ({{1, 0}, {1, 150}});
  Eigen::Matrix4f off = truePose (f, 1);
  // Second instance rotated by 2 degrees about its own origin and moved by 3 mm.
  Eigen::Matrix4f turn = Eigen::Matrix4f::Identity();
  turn.topLeftCorner<3, 3>() =
      Eigen::AngleAxisf (static_cast<float> (2.0 * M_PI / 180.0),
                         Eigen::Vector3f::UnitZ())
          .toRotationMatrix();
  off = off * turn;
  off.topRightCorner<3, 1>() += Eigen::Vector3f (0.003f, 0.0f, 0.0f);
  DetectionResult r;
  r.objects.push_back (
      {{instance (0, 20, 0, truePose (f, 0)), instance (150, 20, 0, off)}});
  const auto s = mid::evaluation::scoreFrame (f, r);
  ASSERT_EQ (s.rotation_errors_deg.size(), 1u);
  EXPECT_NEAR (s.rotation_errors_deg[0], 2.0, 1e-3);
  // At the first instance's origin, 0.2 m from the second's: 3 mm plus the turn's lever arm.
  EXPECT_GT (s.translation_errors_mm[0], 3.0);
}

TEST (ScoreSummary, SumsFramesAndPairsOnlyFromPairFrames)
{
  mid::evaluation::ScoreSummary summary;
  mid::evaluation::FrameScore pairs;
  pairs.pairs_only = true;
  pairs.instance_tp = 2;
  pairs.pair_tp = 1;
  mid::evaluation::FrameScore many;
  many.instance_tp = 3;
  many.instance_fn = 1;
  many.pair_tp = 1;
  DetectionResult timed;
  timed.total_ms = 100.0;
  summary.add (pairs, timed);
  summary.add (many, DetectionResult());
  EXPECT_EQ (summary.frames, 2);
  EXPECT_EQ (summary.pair_frames, 1);
  EXPECT_EQ (summary.instance_tp, 5);
  EXPECT_EQ (summary.pair_tp, 1);
  EXPECT_DOUBLE_EQ (
      mid::evaluation::ScoreSummary::recall (summary.instance_tp, summary.instance_fn),
      5.0 / 6.0);
  EXPECT_DOUBLE_EQ (mid::evaluation::median (summary.times_ms), 100.0);
  EXPECT_DOUBLE_EQ (mid::evaluation::median ({1.0, 3.0, 2.0, 10.0}), 2.5);
  const std::string report = mid::evaluation::formatReport ({{"S_ez", summary}});
  EXPECT_NE (report.find ("| S_ez"), std::string::npos);
  EXPECT_NE (report.find ("| total"), std::string::npos);
}

TEST (FrameScore, ListsMissedInstancesAndTheSharedSurfaceOfFoundAndMissedOnes)
{
  // Type 1: three copies, the first two sharing 120 cubes, the third none; type 2 has two copies
  // whose surface was not measured; type 3 appears once.
  auto f = frame ({{1, 0}, {1, 150}, {1, 300}, {2, 450}, {2, 600}, {3, 750}});
  const int shared[] = {120, 120, 0, -1, -1, 0};
  for (std::size_t k = 0; k < f.instances.size(); ++k)
    f.instances[k].shared_surface_cells = shared[k];
  DetectionResult r;
  r.objects.push_back ({{instance (0, 20), instance (150, 20)}});
  r.objects.push_back ({{instance (450, 20), instance (600, 20)}});
  auto s = mid::evaluation::scoreFrame (f, r);
  EXPECT_EQ (s.found_shared_cells, (std::vector<int>{120, 120}));
  EXPECT_EQ (s.missed_shared_cells, (std::vector<int>{0}));
  EXPECT_EQ (s.missed_instances, (std::vector<std::size_t>{2}));
  EXPECT_TRUE (s.missed_but_located.empty());

  // A second model of type 1 on copies 2 and 0: copy 2 is located, but still missed.
  r.objects.push_back ({{instance (300, 20), instance (0, 20)}});
  s = mid::evaluation::scoreFrame (f, r);
  EXPECT_EQ (s.instance_fn, 1);
  EXPECT_EQ (s.missed_instances, (std::vector<std::size_t>{2}));
  EXPECT_EQ (s.missed_but_located, (std::vector<std::size_t>{2}));
}

TEST (ScoreSummary, ReportsRecallAgainstTheSharedSurface)
{
  mid::evaluation::FrameScore score;
  score.instance_tp = 3;
  score.instance_fp = 1;
  score.instance_fn = 4;
  score.found_shared_cells = {0, 5, 150};
  score.missed_shared_cells = {0, 20, 200, 40};
  mid::evaluation::ScoreSummary summary;
  summary.add (score, DetectionResult());
  const std::string report =
      mid::evaluation::formatSharedSurfaceReport ({{"S_ez", summary}}, 10);
  // Bins 0 | 1-9 | 10-29 | 30-99 | >= 100; from 10 cubes on 1 of 4 instances were found:
  // recall 0.25, precision 3 / 4, F1 2 * 0.75 * 0.25 / 1.
  const std::string row =
      "| S_ez       |   1 /   2 |   1 /   1 |   0 /   1 |   0 /   1 |   1 "
      "/   2 | 0.750 | 0.250 | 0.375 |";
  EXPECT_NE (report.find (row), std::string::npos) << report;
  EXPECT_NE (report.find ("| total      |   1 /   2"), std::string::npos) << report;
  EXPECT_NE (report.find ("R (sharing >= 10)"), std::string::npos) << report;
}

TEST (ScoreSummary, CountsThePairsWhoseRotationIsWrongBeyondEachThreshold)
{
  // Three copies of one type; the second is found turned by 60 deg about its own origin, the
  // others at their true poses: pairs (0, 1) and (1, 2) are 60 deg off, (0, 2) exact.
  const auto f = frame ({{1, 0}, {1, 150}, {1, 300}});
  Eigen::Matrix4f turn = Eigen::Matrix4f::Identity();
  turn.topLeftCorner<3, 3>() =
      Eigen::AngleAxisf (static_cast<float> (M_PI / 3.0), Eigen::Vector3f::UnitX())
          .toRotationMatrix();
  DetectionResult r;
  r.objects.push_back ({{instance (0, 20, 0, truePose (f, 0)),
                         instance (150, 20, 0, truePose (f, 1) * turn),
                         instance (300, 20, 0, truePose (f, 2))}});
  mid::evaluation::ScoreSummary turned;
  turned.add (mid::evaluation::scoreFrame (f, r), r);
  ASSERT_EQ (turned.rotation_errors_deg.size(), 3u);
  // A second scenario with one exact pair.
  r.objects.front().instances.pop_back();
  r.objects.front().instances[1].pose = truePose (f, 1);
  mid::evaluation::ScoreSummary exact;
  exact.add (mid::evaluation::scoreFrame (f, r), r);

  const std::string report = mid::evaluation::formatPoseErrorReport (
      {{"S_ez", turned}, {"rows", exact}}, {10.0, 45.0, 90.0});
  EXPECT_NE (report.find ("rot. err. > 45 deg | rot. err. > 90 deg |"),
             std::string::npos)
      << report;
  // Median of {60, 0, 60} is 60 deg; two of three pairs beyond 10 and 45 deg, none beyond 90.
  EXPECT_NE (report.find ("| S_ez       |     3 |  60.00 |"), std::string::npos)
      << report;
  EXPECT_NE (report.find ("|    2 (0.667) |    2 (0.667) |    0 (0.000) |"),
             std::string::npos)
      << report;
  EXPECT_NE (report.find ("| rows       |     1 |   0.00 |   0.00 |    0 (0.000) |"),
             std::string::npos)
      << report;
  // The total: two of four pairs.
  EXPECT_NE (report.find ("| total      |     4 |"), std::string::npos) << report;
  EXPECT_NE (report.find ("|    2 (0.500) |    2 (0.500) |    0 (0.000) |"),
             std::string::npos)
      << report;
}

TEST (ScoreSummary, SplitsThePairsByTheGroupsOfTheResult)
{
  // Four copies of a type that is symmetric under a half turn about model z. Copies 0 and 1
  // are one group, found at their true poses; copies 2 and 3 another, both turned by the half
  // turn (right among themselves, wrong against 0 and 1 but for the symmetry).
  const auto f = frame ({{1, 0}, {1, 150}, {1, 300}, {1, 450}});
  mid::evaluation::ObjectSymmetryTable symmetries;
  symmetries[1].discrete.push_back (
      Eigen::AngleAxisd (M_PI, Eigen::Vector3d::UnitZ()).toRotationMatrix());
  Eigen::Matrix4f half = Eigen::Matrix4f::Identity();
  half.topLeftCorner<3, 3>() =
      Eigen::AngleAxisf (static_cast<float> (M_PI), Eigen::Vector3f::UnitZ())
          .toRotationMatrix();
  DetectionResult r;
  r.objects.push_back ({{instance (0, 20, 0, truePose (f, 0)),
                         instance (150, 20, 0, truePose (f, 1)),
                         instance (300, 20, 0, truePose (f, 2) * half),
                         instance (450, 20, 0, truePose (f, 3) * half)}});
  const std::vector<int> groups = {0, 0, 1, 1};
  for (std::size_t i = 0; i < groups.size(); ++i)
    r.objects.front().instances[i].group = groups[i];
  const auto s = mid::evaluation::scoreFrame (f, r, 0.9, symmetries);
  // Pairs in order (0,1) (0,2) (0,3) (1,2) (1,3) (2,3).
  EXPECT_EQ (s.pair_groups, (std::vector<int>{1, 0, 0, 0, 0, 1}));
  mid::evaluation::ScoreSummary summary;
  summary.add (s, r);
  const std::string report =
      mid::evaluation::formatGroupPoseReport ({{"S_ez", summary}}, 45.0);
  // Within: 2 pairs, both exact. Across: 4 pairs, all 180 deg off, none modulo the symmetry
  // (0.0x deg: float poses).
  EXPECT_NE (report.find (
                 "| S_ez       |     2 |   0.00 |    0 (0.000) |     4 | 180.00 |    4 "
                 "(1.000) |   0.0"),
             std::string::npos)
      << report;
  EXPECT_NE (
      report.find (" |    0 (0.000) |     0 |\n| total      |     2 |   0.00 |    0 "
                   "(0.000) |     4 | 180.00 |    4 (1.000) |   0.0"),
      std::string::npos)
      << report;

  // A result without groups (the detect app's, an older discovery's) puts every pair in the
  // last column.
  for (auto& instance : r.objects.front().instances)
    instance.group = -1;
  const auto plain = mid::evaluation::scoreFrame (f, r, 0.9, symmetries);
  EXPECT_EQ (plain.pair_groups, std::vector<int> (6, -1));
  mid::evaluation::ScoreSummary without;
  without.add (plain, r);
  EXPECT_NE (
      mid::evaluation::formatGroupPoseReport ({{"S_ez", without}}, 45.0)
          .find ("| S_ez       |     0 |    nan |    0 (0.000) |     0 |    nan |    0 "
                 "(0.000) |    nan |    0 (0.000) |     6 |"),
      std::string::npos);
}

TEST (FrameScore, RotationErrorsModuloTheShapeForgiveItsSymmetries)
{
  // Type 1 is a cylinder about model z; type 2 lists no symmetry. Of each, the second copy is
  // found turned by 60 deg about model z; of type 1 a third copy turned by 60 deg about x.
  const auto f = frame ({{1, 0}, {1, 150}, {1, 300}, {2, 450}, {2, 600}});
  mid::evaluation::ObjectSymmetryTable symmetries;
  symmetries[1].continuous_axes = {Eigen::Vector3d::UnitZ()};
  symmetries[1].discrete.push_back (
      Eigen::AngleAxisd (M_PI, Eigen::Vector3d::UnitX()).toRotationMatrix());
  const auto turned = [] (const Eigen::Vector3f& axis) {
    Eigen::Matrix4f turn = Eigen::Matrix4f::Identity();
    turn.topLeftCorner<3, 3>() =
        Eigen::AngleAxisf (static_cast<float> (M_PI / 3.0), axis).toRotationMatrix();
    return turn;
  };
  DetectionResult r;
  r.objects.push_back (
      {{instance (0, 20, 0, truePose (f, 0)),
        instance (150, 20, 0, truePose (f, 1, turned (Eigen::Vector3f::UnitZ()))),
        instance (300, 20, 0, truePose (f, 2, turned (Eigen::Vector3f::UnitX())))}});
  r.objects.push_back (
      {{instance (450, 20, 0, truePose (f, 3)),
        instance (600, 20, 0, truePose (f, 4, turned (Eigen::Vector3f::UnitZ())))}});
  const auto s = mid::evaluation::scoreFrame (f, r, 0.9, symmetries);
  // Pairs (0, 1), (0, 2), (1, 2) of type 1, then (3, 4) of type 2; copy 1 is right modulo
  // the cylinder, so (1, 2) is off by copy 2's turn across the axis alone.
  ASSERT_EQ (s.rotation_errors_deg.size(), 4u);
  ASSERT_EQ (s.symmetric_rotation_errors_deg.size(), 4u);
  const std::vector<double> plain = {60.0, 60.0, -1.0, 60.0},
                            modulo = {0.0, 60.0, 60.0, 60.0};
  for (std::size_t p = 0; p < 4; ++p) {
    if (plain[p] >= 0.0) {
      EXPECT_NEAR (s.rotation_errors_deg[p], plain[p], 1e-3) << p;
    }
    EXPECT_NEAR (s.symmetric_rotation_errors_deg[p], modulo[p], 1e-2) << p;
  }
  EXPECT_GT (s.rotation_errors_deg[2], 61.0); // two turns about different axes
  // Without the table, every error is the plain one.
  const auto without = mid::evaluation::scoreFrame (f, r);
  for (std::size_t p = 0; p < 4; ++p)
    EXPECT_NEAR (
        without.symmetric_rotation_errors_deg[p], without.rotation_errors_deg[p], 1e-3);
}

TEST (ScoreSummary, ComparesTheBoxOfEveryCorrectObjectWithItsTypesSize)
{
  // Type 1 (0.07 x 0.07 x 0.2 m) found with a box 3 mm long agreed on by two copies; type 2
  // (0.05 x 0.11 x 0.16 m) found with a box of two copies joined (0.10 m too wide) measured on
  // one copy; a second object of type 1 (a false positive) with a box, and type 3 found without
  // any: only the valid objects' boxes count, and type 3 counts as an object without a box.
  const auto f = frame ({{1, 0}, {1, 150}, {2, 300}, {2, 450}, {3, 600}, {3, 750}});
  DetectionResult r;
  DetectedObject first{{instance (0, 20), instance (150, 20)}};
  first.box_size = Eigen::Vector3f (0.07f, 0.07f, 0.203f);
  first.box_copies = 2;
  DetectedObject joined{{instance (300, 20), instance (450, 20)}};
  joined.box_size = Eigen::Vector3f (0.05f, 0.16f, 0.21f);
  joined.box_copies = 1;
  DetectedObject second = first;
  r.objects = {
      first, joined, second, DetectedObject{{instance (600, 20), instance (750, 20)}}};
  const auto score = mid::evaluation::scoreFrame (f, r);
  ASSERT_EQ (score.object_boxes.size(), 3u);
  EXPECT_EQ (score.object_boxes[0].type, 1);
  EXPECT_EQ (score.object_boxes[0].copies, 2);
  EXPECT_EQ (score.object_boxes[1].type, 2);
  EXPECT_EQ (score.object_boxes[2].type, 3);
  EXPECT_EQ (score.object_boxes[2].copies, 0);

  mid::evaluation::ScoreSummary summary;
  summary.add (score, r);
  const mid::evaluation::ObjectSizeTable sizes = {
      {1, {0.07, 0.07, 0.2}}, {2, {0.05, 0.11, 0.16}}, {3, {0.04, 0.09, 0.12}}};
  const std::string report =
      mid::evaluation::formatBoxSizeReport ({{"M_d", summary}}, sizes);
  // Three objects, two with a box: errors 3 and 50 mm (median 26.5), one of two within 5 mm;
  // the box of two copies alone: 3 mm.
  EXPECT_NE (
      report.find ("| M_d        |     3 |     2 |   26.5 | 0.500 | 0.500 |     1 |"
                   "    3.0 | 1.000 | 1.000 |"),
      std::string::npos)
      << report;
  EXPECT_NE (report.find ("| total      |     3 |     2 |"), std::string::npos)
      << report;
  // A type without a true size is left out.
  const std::string without = mid::evaluation::formatBoxSizeReport (
      {{"M_d", summary}}, {{1, {0.07, 0.07, 0.2}}});
  EXPECT_NE (without.find ("| M_d        |     1 |     1 |    3.0 |"),
             std::string::npos)
      << without;
}
