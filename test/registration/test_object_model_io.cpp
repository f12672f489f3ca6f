#include "temporary_folder.h"

#include <mid/registration/object_model_io.h>

#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <random>
#include <regex>
#include <sstream>
#include <utility>
#include <vector>

namespace {

namespace fs = std::filesystem;

mid::ObjectModel
randomModel ()
{
  std::mt19937 rng (8);
  std::uniform_real_distribution<float> unit (-0.05f, 0.05f), value (0.0f, 100.0f);
  mid::ObjectModel model;
  for (int l = 0; l < 12; ++l) {
    pcl::PointNormal p;
    p.getVector3fMap() = Eigen::Vector3f (unit (rng), unit (rng), unit (rng));
    p.getNormalVector3fMap() =
        Eigen::Vector3f (unit (rng), unit (rng), 1.0f).normalized();
    p.curvature = 0.0f;
    model.landmarks.push_back (p);
    for (int copy = 0; copy < 1 + l % 3; ++copy) {
      mid::SIFTDescriptor d;
      for (float& v : d.histogram)
        v = value (rng);
      model.descriptors.push_back (d);
      model.descriptor_landmarks.push_back (l);
    }
  }
  mid::updateModelDiameter (model);
  return model;
}

/** A box as ModelSizeMeasurement gives one: edges ascending (metres), a rigid pose. */
mid::ModelSize
someBox ()
{
  mid::ModelSize box;
  box.valid = true;
  box.agreeing = 3;
  box.size = Eigen::Vector3f (0.041f, 0.0893f, 0.1207f);
  Eigen::Affine3f pose (
      Eigen::AngleAxisf (0.7f, Eigen::Vector3f (1.0f, -2.0f, 0.5f).normalized()));
  pose.translation() = Eigen::Vector3f (0.012f, -0.003f, 0.021f);
  box.box_in_model = pose.matrix();
  return box;
}

class ObjectModelIO : public ::testing::Test
{
protected:
  void
  SetUp () override
  {
    path_ = folder_.file ("model.json");
    ASSERT_TRUE (mid::saveObjectModel (path_, randomModel()));
  }

  void
  rewriteJson (const std::string& from, const std::string& to)
  {
    std::ifstream in (path_);
    std::stringstream text;
    text << in.rdbuf();
    in.close();
    std::ofstream (path_) << std::regex_replace (text.str(), std::regex (from), to);
  }

  void
  expectRefused ()
  {
    mid::ObjectModel model = randomModel();
    EXPECT_FALSE (mid::loadObjectModel (path_, model));
    EXPECT_TRUE (model.landmarks.empty());
    EXPECT_TRUE (model.descriptors.empty());
    mid::ModelSize box = someBox();
    model = randomModel();
    EXPECT_FALSE (mid::loadObjectModel (path_, model, box));
    EXPECT_TRUE (model.landmarks.empty());
    EXPECT_FALSE (box.valid);
    EXPECT_EQ (box.agreeing, 0);
  }

  /** Save a model with `saved_box`, apply each (pattern, replacement) rewrite to its header in
    * turn and expect the loader to refuse the result.
    */
  void
  expectEachRewriteRefused (
      const std::vector<std::pair<std::string, std::string>>& rewrites,
      const mid::ModelSize& saved_box)
  {
    for (const auto& [from, to] : rewrites) {
      ASSERT_TRUE (mid::saveObjectModel (path_, randomModel(), saved_box));
      rewriteJson (from, to);
      SCOPED_TRACE (to);
      expectRefused();
    }
  }

  mid::test::TemporaryFolder folder_;
  const fs::path& dir_ = folder_.path();
  std::string path_;
};

} // namespace

TEST_F (ObjectModelIO, ReloadsIdentically)
{
  const mid::ObjectModel original = randomModel();
  mid::ObjectModel loaded;
  ASSERT_TRUE (mid::loadObjectModel (path_, loaded));
  ASSERT_EQ (loaded.landmarks.size(), original.landmarks.size());
  ASSERT_EQ (loaded.descriptors.size(), original.descriptors.size());
  EXPECT_EQ (loaded.descriptor_landmarks, original.descriptor_landmarks);
  for (std::size_t l = 0; l < original.landmarks.size(); ++l) {
    EXPECT_EQ (loaded.landmarks[l].getVector3fMap(),
               original.landmarks[l].getVector3fMap());
    EXPECT_EQ (loaded.landmarks[l].getNormalVector3fMap(),
               original.landmarks[l].getNormalVector3fMap());
  }
  for (std::size_t d = 0; d < original.descriptors.size(); ++d)
    EXPECT_TRUE (std::equal (original.descriptors[d].histogram,
                             original.descriptors[d].histogram + 128,
                             loaded.descriptors[d].histogram));
  EXPECT_NEAR (loaded.diameter, original.diameter, 1e-5f);
  EXPECT_TRUE (fs::exists (dir_ / "model.pcd"));
  EXPECT_EQ (folder_.entries(), 2u);
}

TEST_F (ObjectModelIO, ReloadsTheBoxIdentically)
{
  // Saved without a box: none comes back.
  mid::ObjectModel model;
  mid::ModelSize box = someBox();
  ASSERT_TRUE (mid::loadObjectModel (path_, model, box));
  EXPECT_FALSE (box.valid);
  // With one: the same edges, copies and pose, bit for bit, and the same model.
  const mid::ModelSize original = someBox();
  ASSERT_TRUE (mid::saveObjectModel (path_, randomModel(), original));
  ASSERT_TRUE (mid::loadObjectModel (path_, model, box));
  EXPECT_TRUE (box.valid);
  EXPECT_EQ (box.agreeing, original.agreeing);
  EXPECT_EQ (box.size, original.size);
  EXPECT_EQ (box.box_in_model, original.box_in_model);
  EXPECT_EQ (model.descriptor_landmarks, randomModel().descriptor_landmarks);
  // A box that is not valid (too few copies agree) is not stored.
  mid::ModelSize unsure = original;
  unsure.valid = false;
  ASSERT_TRUE (mid::saveObjectModel (path_, randomModel(), unsure));
  ASSERT_TRUE (mid::loadObjectModel (path_, model, box));
  EXPECT_FALSE (box.valid);
}

TEST_F (ObjectModelIO, ReadsAFileWrittenBeforeBoxesWereStored)
{
  rewriteJson (R"(,\s*"box": null)", "");
  std::ifstream in (path_);
  const std::string text ((std::istreambuf_iterator<char> (in)),
                          std::istreambuf_iterator<char>());
  ASSERT_EQ (text.find ("box"), std::string::npos) << text;
  mid::ObjectModel model;
  mid::ModelSize box = someBox();
  ASSERT_TRUE (mid::loadObjectModel (path_, model, box));
  EXPECT_FALSE (box.valid);
  EXPECT_EQ (model.descriptor_landmarks, randomModel().descriptor_landmarks);
}

TEST_F (ObjectModelIO, RefusesAMalformedBox)
{
  const std::vector<std::pair<std::string, std::string>> rewrites = {
      {R"("copies": 3)", R"("copies": 0)"},
      {R"("size": \[[^\]]*\])", R"("size": [0.05, 0.04, 0.12])"},
      {R"("size": \[[^\]]*\])", R"("size": [0.04, 0.09])"},
      {R"("size": \[[^\]]*\])", R"("size": [0, 0.09, 0.12])"},
      {R"("pose": \[\[.*\]\])",
       R"("pose": [[2, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])"},
      {R"("pose": \[\[.*\]\])",
       R"("pose": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 1, 1]])"},
      {R"("pose": \[\[.*\]\])",
       R"("pose": [[-1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])"},
      {R"("pose": \[\[.*\]\])", R"("pose": [1, 2, 3, 4])"},
      {R"("size": \[[^\]]*\])", R"("size": [1e300, 2e300, 3e300])"},
      {R"("size": \[[^\]]*\])", R"("size": ["0.04", 0.09, 0.12])"},
      {R"("copies": 3)", R"("copies": 3.0)"},
      {R"("box": \{)", R"("box": "large", "old": {)"}};
  expectEachRewriteRefused (rewrites, someBox());
}

TEST_F (ObjectModelIO, RefusesCountsThatAreNoCounts)
{
  // Counts that would make the reader allocate without bound, or cast out of range.
  const std::vector<std::pair<std::string, std::string>> rewrites = {
      {R"("landmarks": [0-9]+)", R"("landmarks": 1000000000000000000)"},
      {R"("landmarks": [0-9]+)", R"("landmarks": 1e30)"},
      {R"("landmarks": [0-9]+)", R"("landmarks": 0)"},
      {R"("descriptors": [0-9]+)", R"("descriptors": -20)"},
      {R"("version": 1)", R"("version": 1.9)"},
      {R"("version": 1)", R"("version": 1e300)"},
      {R"("diameter": [0-9.e-]+)", R"("diameter": -0.1)"},
      {R"("diameter": [0-9.e-]+)", R"("diameter": 1e300)"}};
  expectEachRewriteRefused (rewrites, mid::ModelSize{});
}

TEST (ObjectModelIOWrite, RefusesABoxItsReaderWouldRefuse)
{
  const mid::test::TemporaryFolder folder;
  mid::ModelSize mirrored = someBox(), unsorted = someBox(), no_copy = someBox(),
                 not_finite = someBox();
  mirrored.box_in_model.col (0) *= -1.0f;
  unsorted.size = Eigen::Vector3f (0.1f, 0.05f, 0.2f);
  no_copy.agreeing = 0;
  not_finite.size.z() = std::numeric_limits<float>::quiet_NaN();
  for (const auto& box : {mirrored, unsorted, no_copy, not_finite}) {
    EXPECT_FALSE (
        mid::saveObjectModel (folder.file ("model.json"), randomModel(), box));
    EXPECT_EQ (folder.entries(), 0u);
  }
  // The same boxes not valid are written as none.
  mid::ModelSize unsure = mirrored;
  unsure.valid = false;
  EXPECT_TRUE (
      mid::saveObjectModel (folder.file ("model.json"), randomModel(), unsure));
}

TEST_F (ObjectModelIO, RefusesMissingFiles)
{
  fs::remove (dir_ / "model.pcd");
  expectRefused();
  fs::remove (path_);
  expectRefused();
}

TEST_F (ObjectModelIO, RefusesATruncatedDataFile)
{
  // Every cut: inside the header (a cut after "POINTS" and before "DATA" once made PCL's
  // conversion bind a reference into an empty cloud, found by the sanitized CI run) and
  // inside the body.
  const fs::path data = dir_ / "model.pcd";
  std::ifstream in (data, std::ios::binary);
  const std::string full ((std::istreambuf_iterator<char> (in)),
                          std::istreambuf_iterator<char>());
  in.close();
  const std::size_t body = full.find ("DATA");
  ASSERT_NE (body, std::string::npos);
  std::vector<std::size_t> cuts;
  for (std::size_t cut = 0; cut < body + 20; ++cut)
    cuts.push_back (cut);
  for (std::size_t cut = body + 20; cut < full.size(); cut += full.size() / 17)
    cuts.push_back (cut);
  cuts.push_back (full.size() - 1);
  for (const std::size_t cut : cuts) {
    std::ofstream (data, std::ios::binary | std::ios::trunc) << full.substr (0, cut);
    SCOPED_TRACE ("data file cut at byte " + std::to_string (cut));
    expectRefused();
  }
}

TEST_F (ObjectModelIO, RefusesDataOfAnotherKind)
{
  pcl::PointCloud<pcl::PointXYZ> points;
  points.push_back (pcl::PointXYZ (0.0f, 0.0f, 0.5f));
  ASSERT_EQ (pcl::io::savePCDFileBinary ((dir_ / "model.pcd").string(), points), 0);
  expectRefused();
}

TEST_F (ObjectModelIO, RefusesAnotherVersionOrFormat)
{
  rewriteJson ("\"version\": 1", "\"version\": 2");
  expectRefused();
  rewriteJson ("\"version\": 2", "\"version\": 1");
  rewriteJson ("mid-object-model", "something-else");
  expectRefused();
}

TEST_F (ObjectModelIO, RefusesATruncatedHeader)
{
  rewriteJson (R"("descriptors": [0-9]+,\s*"diameter": [0-9.e-]+)", "");
  expectRefused();
}

TEST (ObjectModelIOWrite, RefusesBadPaths)
{
  EXPECT_FALSE (
      mid::saveObjectModel ("/nonexistent_mid_folder/model.json", randomModel()));
  const mid::test::TemporaryFolder folder;
  EXPECT_FALSE (mid::saveObjectModel (folder.file ("model.txt"), randomModel()));
  EXPECT_EQ (folder.entries(), 0u);
}
