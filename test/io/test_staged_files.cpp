#include "temporary_folder.h"

#include <mid/io/staged_files.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

TEST (StagedFiles, FilesAppearOnlyOnCommit)
{
  const mid::test::TemporaryFolder folder;
  const std::string final_path = folder.file ("a.txt");
  {
    mid::io::StagedFiles files;
    const std::string temporary = files.stage (final_path);
    EXPECT_EQ (fs::path (temporary).extension(), ".txt");
    std::ofstream (temporary) << "first";
    EXPECT_FALSE (fs::exists (final_path));
  } // not committed: removed
  EXPECT_EQ (folder.entries(), 0u);

  mid::io::StagedFiles files;
  std::ofstream (files.stage (final_path)) << "second";
  const std::string missing = files.stage (folder.file ("b.txt"));
  (void)missing; // never written: commit refuses and cleans up
  EXPECT_FALSE (files.commit());
  EXPECT_EQ (folder.entries(), 0u);

  std::ofstream (files.stage (final_path)) << "third";
  ASSERT_TRUE (files.commit());
  std::ifstream file (final_path);
  std::string text;
  file >> text;
  EXPECT_EQ (text, "third");
  EXPECT_EQ (folder.entries(), 1u);
}

TEST (StagedFiles, RefusesADestinationInAMissingFolder)
{
  mid::io::StagedFiles files;
  EXPECT_TRUE (files.stage ("/nonexistent_mid_folder/result.json").empty());
  EXPECT_TRUE (files.commit()); // nothing staged
}
