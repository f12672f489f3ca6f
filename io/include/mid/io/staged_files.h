#pragma once

#include <string>
#include <vector>

namespace mid {
namespace io {

/** \brief Writes a set of output files all-or-nothing (as far as the file system allows):
  * each file is first written under a temporary name next to its destination, and only
  * commit() renames them into place. Temporary files of a set that was not committed are
  * removed when it is destroyed, so an error never leaves a half-written output file.
  *
  * \code
  * mid::io::StagedFiles files;
  * const std::string json_tmp = files.stage ("out/ground_truth.json");
  * if (!writeMyJson (json_tmp) || !files.commit ()) return (-1); // nothing left behind
  * \endcode
  */
class StagedFiles
{
public:
  StagedFiles() = default;
  StagedFiles (const StagedFiles&) = delete;
  StagedFiles&
  operator= (const StagedFiles&) = delete;

  /** \brief Removes the temporary files unless commit() succeeded. */
  ~StagedFiles();

  /** \brief Register a destination and get the temporary path to write it to: same folder,
    * same extension (so that writers choosing the format by extension still work), e.g.
    * "out/rgb.png" -> "out/rgb.partial.png".
    * \param[in] path the destination
    * \return the temporary path; empty (with a PCL_ERROR) if the destination's folder is
    * missing or not writable
    */
  std::string
  stage (const std::string& path);

  /** \brief Rename every temporary file to its destination, replacing existing files.
    * \return false (with a PCL_ERROR) if a temporary file is missing or a rename fails; the
    * remaining temporary files are then removed
    */
  bool
  commit ();

  /** \brief Remove the temporary files written so far and forget the set. */
  void
  discard ();

private:
  struct Entry
  {
    std::string temporary;
    std::string destination;
  };
  std::vector<Entry> entries_;
};

} // namespace io
} // namespace mid
