// The fuzz corpus as unit tests: every seed is a valid frame, and every input a fuzzer ever
// crashed on (kept in test/fuzz/regressions/) is now refused cleanly: false, cloud cleared.
#include "fuzz_inputs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <vector>

namespace {

namespace fs = std::filesystem;

/** The files of one corpus folder, sorted; READMEs are skipped. */
std::vector<fs::path>
inputs (const std::string& folder)
{
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator (fs::path (MID_FUZZ_DIR) / folder))
    if (entry.is_regular_file() && entry.path().extension() != ".md")
      files.push_back (entry.path());
  std::sort (files.begin(), files.end());
  return files;
}

using Loader = bool (*) (const std::uint8_t*, std::size_t, mid::fuzz::Cloud&);

bool
load (Loader loader, const fs::path& path, mid::fuzz::Cloud& cloud)
{
  const mid::fuzz::Bytes bytes = mid::fuzz::readFile (path.string());
  return loader (bytes.data(), bytes.size(), cloud);
}

} // namespace

TEST (FuzzSeedCorpus, EveryPcdSeedIsAValidFrame)
{
  const auto files = inputs ("corpus/pcd");
  ASSERT_FALSE (files.empty());
  for (const auto& path : files) {
    mid::fuzz::Cloud cloud;
    EXPECT_TRUE (load (&mid::fuzz::loadPCDBytes, path, cloud)) << path;
    EXPECT_EQ (cloud.width, 4u) << path;
    EXPECT_EQ (cloud.height, 3u) << path;
  }
}

TEST (FuzzSeedCorpus, EveryRgbdSeedIsAValidFrame)
{
  const auto files = inputs ("corpus/rgbd");
  ASSERT_FALSE (files.empty());
  for (const auto& path : files) {
    mid::fuzz::Cloud cloud;
    EXPECT_TRUE (load (&mid::fuzz::loadRGBDBytes, path, cloud)) << path;
    EXPECT_EQ (cloud.width, 4u) << path;
    EXPECT_EQ (cloud.height, 3u) << path;
  }
}

TEST (FuzzRegressions, EveryPcdCrashIsRefusedCleanly)
{
  for (const auto& path : inputs ("regressions/pcd")) {
    mid::fuzz::Cloud cloud;
    cloud.resize (1);
    EXPECT_FALSE (load (&mid::fuzz::loadPCDBytes, path, cloud)) << path;
    EXPECT_TRUE (mid::fuzz::keepsTheContract (false, cloud)) << path;
  }
}

TEST (FuzzRegressions, EveryRgbdCrashIsRefusedCleanly)
{
  for (const auto& path : inputs ("regressions/rgbd")) {
    mid::fuzz::Cloud cloud;
    cloud.resize (1);
    EXPECT_FALSE (load (&mid::fuzz::loadRGBDBytes, path, cloud)) << path;
    EXPECT_TRUE (mid::fuzz::keepsTheContract (false, cloud)) << path;
  }
}
