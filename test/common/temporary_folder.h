#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <unistd.h>

namespace mid {
namespace test {

/** \brief A fresh, empty folder for the running test, removed with the object. Named after the
  * test and the process, so tests that CTest runs in parallel never share one.
  */
class TemporaryFolder
{
public:
  TemporaryFolder()
  {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::string name =
        info != nullptr ? std::string (info->test_suite_name()) + "_" + info->name()
                        : std::string ("no_test");
    path_ = std::filesystem::temp_directory_path() /
            ("mid_test_" + name + "_" + std::to_string (::getpid()));
    std::filesystem::remove_all (path_);
    std::filesystem::create_directories (path_);
  }
  ~TemporaryFolder() { std::filesystem::remove_all (path_); }
  TemporaryFolder (const TemporaryFolder&) = delete;
  TemporaryFolder&
  operator= (const TemporaryFolder&) = delete;

  /** \brief The folder. */
  const std::filesystem::path&
  path () const
  {
    return path_;
  }

  /** \brief A file in the folder, as a string. */
  std::string
  file (const std::string& name) const
  {
    return (path_ / name).string();
  }

  /** \brief How many entries the folder holds. */
  std::size_t
  entries () const
  {
    return static_cast<std::size_t> (
        std::distance (std::filesystem::directory_iterator (path_),
                       std::filesystem::directory_iterator()));
  }

private:
  std::filesystem::path path_;
};

} // namespace test
} // namespace mid
