#include <mid/io/staged_files.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace {

namespace fs = std::filesystem;

fs::path
makeEmptyFolder (const std::string& name)
{
  const fs::path folder = fs::temp_directory_path () / ("mid_test_" + name);
  fs::remove_all (folder);
  fs::create_directories (folder);
  return folder;
}

std::size_t
countEntries (const fs::path& folder)
{
  return static_cast<std::size_t> (std::distance (fs::directory_iterator (folder), fs::directory_iterator ()));
}

} // namespace

TEST (StagedFiles, FilesAppearOnlyOnCommit)
{
  const fs::path folder = makeEmptyFolder ("staged_files");
  const std::string final_path = (folder / "a.txt").string ();
  {
    mid::io::StagedFiles files;
    const std::string temporary = files.stage (final_path);
    EXPECT_EQ (fs::path (temporary).extension (), ".txt");
    std::ofstream (temporary) << "first";
    EXPECT_FALSE (fs::exists (final_path));
  } // not committed: removed
  EXPECT_EQ (countEntries (folder), 0u);

  mid::io::StagedFiles files;
  std::ofstream (files.stage (final_path)) << "second";
  const std::string missing = files.stage ((folder / "b.txt").string ());
  (void) missing; // never written: commit refuses and cleans up
  EXPECT_FALSE (files.commit ());
  EXPECT_EQ (countEntries (folder), 0u);

  std::ofstream (files.stage (final_path)) << "third";
  ASSERT_TRUE (files.commit ());
  std::ifstream file (final_path);
  std::string text;
  file >> text;
  EXPECT_EQ (text, "third");
  EXPECT_EQ (countEntries (folder), 1u);
  fs::remove_all (folder);
}

TEST (StagedFiles, RefusesADestinationInAMissingFolder)
{
  mid::io::StagedFiles files;
  EXPECT_TRUE (files.stage ("/nonexistent_mid_folder/result.json").empty ());
  EXPECT_TRUE (files.commit ()); // nothing staged
}
