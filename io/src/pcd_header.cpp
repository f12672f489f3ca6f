#include "pcd_header.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <limits>
#include <locale>
#include <sstream>
#include <vector>

namespace mid {
namespace io {
namespace detail {

namespace {

/** The header lines in the order the PCD format requires them. */
enum class Keyword {
  kVersion,
  kFields,
  kSize,
  kType,
  kCount,
  kWidth,
  kHeight,
  kViewpoint,
  kPoints,
  kData
};

constexpr std::array<const char*, 10> kSpelling = {"VERSION",
                                                   "FIELDS",
                                                   "SIZE",
                                                   "TYPE",
                                                   "COUNT",
                                                   "WIDTH",
                                                   "HEIGHT",
                                                   "VIEWPOINT",
                                                   "POINTS",
                                                   "DATA"};

/** PCL's int: every count it reads, and every sum it forms, must stay below this. */
constexpr std::uint64_t kMaxInt = std::numeric_limits<std::int32_t>::max();
/** Bytes of one point, far above any descriptor PCL has (a SHOT color point has 1,352 floats). */
constexpr std::uint64_t kMaxPointStep = std::uint64_t{1} << 24U;
/** LZF, the compression of binary_compressed PCD files, turns 3 bytes into at most 264. */
constexpr std::uint64_t kMaxCompressionRatio = 100;

/** The keyword PCL's reader takes a line's first token for (it compares prefixes, and reads
  * COLUMNS as FIELDS); false if it ends the header there.
  */
bool
pclKeyword (const std::string& token, Keyword& keyword)
{
  const auto starts_with = [&token] (const char* prefix) {
    return token.compare (0, std::char_traits<char>::length (prefix), prefix) == 0;
  };
  if (starts_with ("COLUMNS")) {
    keyword = Keyword::kFields;
    return true;
  }
  for (std::size_t k = 0; k < kSpelling.size(); ++k)
    if (starts_with (kSpelling[k])) {
      keyword = static_cast<Keyword> (k);
      return true;
    }
  return false;
}

const char*
spelling (Keyword keyword)
{
  return kSpelling[static_cast<std::size_t> (keyword)];
}

/** Printable ASCII, spaces, tabs and carriage returns only: on such a line PCL's token split
  * (on space, tab and carriage return) and its stream extraction see the same tokens.
  */
bool
isPlainText (const std::string& line)
{
  return std::all_of (line.begin(), line.end(), [] (char c) {
    return (c >= 0x20 && c < 0x7F) || c == '\t' || c == '\r';
  });
}

/** A plain decimal number (digits only) of at most max. */
bool
parseCount (const std::string& token, std::uint64_t max, std::uint64_t& value)
{
  const char* end = token.data() + token.size();
  const auto [stop, error] = std::from_chars (token.data(), end, value);
  return !token.empty() && token[0] != '-' && error == std::errc() && stop == end &&
         value <= max;
}

/** A number PCL's float extraction reads without failing (a finite float, not out of its
  * range: a failed extraction would leave the next VIEWPOINT values uninitialized).
  */
bool
isFiniteFloat (const std::string& token)
{
  float value = 0.0f;
  const char* end = token.data() + token.size();
  const auto [stop, error] = std::from_chars (token.data(), end, value);
  return error == std::errc() && stop == end && std::isfinite (value);
}

/** The values of the header, as far as they have been read. */
struct Header
{
  std::size_t fields = 0;
  std::vector<std::uint64_t> sizes, counts;
  std::uint64_t width = 0, height = 0, points = 0;
  bool has_type = false, has_points = false, has_width = false, has_height = false,
       has_data = false;
};

/** Reads the values of one header line into header; false (with problem set) if they are not
  * what the format allows.
  */
bool
readValues (Keyword keyword,
            const std::vector<std::string>& values,
            Header& header,
            std::string& problem)
{
  const std::string line = std::string ("its ") + spelling (keyword) + " line";
  const auto one_per_field = [&] {
    if (values.size() == header.fields)
      return true;
    problem = line + " has " + std::to_string (values.size()) + " values for " +
              std::to_string (header.fields) + " fields";
    return false;
  };
  const auto counts_per_field = [&] (std::uint64_t max,
                                     std::vector<std::uint64_t>& out) {
    out.assign (values.size(), 0);
    for (std::size_t i = 0; i < values.size(); ++i)
      if (!parseCount (values[i], max, out[i]) || out[i] == 0) {
        problem = line + " value '" + values[i] + "' is not a whole number from 1 to " +
                  std::to_string (max);
        return false;
      }
    return true;
  };
  const auto single_count = [&] (std::uint64_t& out) {
    if (values.size() == 1 && parseCount (values[0], kMaxInt, out))
      return true;
    problem =
        line + " must hold one whole number from 0 to " + std::to_string (kMaxInt);
    return false;
  };
  switch (keyword) {
  case Keyword::kVersion:
    return true;
  case Keyword::kFields:
    header.fields = values.size();
    if (values.empty())
      problem = "its FIELDS line names no field";
    return !values.empty();
  case Keyword::kSize:
    if (header.fields == 0) {
      problem = "its SIZE line comes before FIELDS";
      return false;
    }
    if (!one_per_field() || !counts_per_field (8, header.sizes))
      return false;
    if (std::all_of (header.sizes.begin(), header.sizes.end(), [] (std::uint64_t s) {
          return s == 1 || s == 2 || s == 4 || s == 8;
        }))
      return true;
    problem = "its SIZE values must be 1, 2, 4 or 8 bytes";
    return false;
  case Keyword::kType:
    if (header.sizes.empty()) {
      problem = "its TYPE line comes before SIZE";
      return false;
    }
    header.has_type = true;
    if (!one_per_field())
      return false;
    for (std::size_t i = 0; i < values.size(); ++i) {
      const bool known =
          values[i] == "I" || values[i] == "U" || values[i] == "F" || values[i] == "B";
      if (!known ||
          (values[i] == "F" && header.sizes[i] != 4 && header.sizes[i] != 8) ||
          (values[i] == "B" && header.sizes[i] != 1)) {
        problem = "its TYPE '" + values[i] + "' does not fit a field of " +
                  std::to_string (header.sizes[i]) + " bytes";
        return false;
      }
    }
    return true;
  case Keyword::kCount:
    return one_per_field() && counts_per_field (kMaxPointStep, header.counts);
  case Keyword::kWidth:
    header.has_width = true;
    return single_count (header.width);
  case Keyword::kHeight:
    header.has_height = true;
    return single_count (header.height);
  case Keyword::kViewpoint:
    if (values.size() == 7 && std::all_of (values.begin(), values.end(), isFiniteFloat))
      return true;
    problem = "its VIEWPOINT line must hold seven numbers (tx ty tz qw qx qy qz)";
    return false;
  case Keyword::kPoints:
    header.has_points = true;
    return single_count (header.points);
  case Keyword::kData:
    header.has_data = true;
    if (values.size() == 1 && (values[0] == "ascii" || values[0] == "binary" ||
                               values[0] == "binary_compressed"))
      return true;
    problem = "its DATA line must say ascii, binary or binary_compressed";
    return false;
  }
  return false;
}

/** The checks that need the whole header: required lines, sizes that agree, plausible size. */
bool
checkWhole (const Header& header, std::uint64_t file_size, std::string& problem)
{
  if (!header.has_type || !header.has_points || !header.has_data) {
    problem = "the header lacks one of FIELDS, SIZE, TYPE, POINTS and DATA";
    return false;
  }
  if (header.has_height && !header.has_width) {
    problem = "it has a HEIGHT line but no WIDTH line";
    return false;
  }
  const std::uint64_t width = header.has_width ? header.width : header.points;
  const std::uint64_t height = header.has_height ? header.height : 1;
  if (width * height != header.points) {
    problem = "its WIDTH " + std::to_string (width) + " x HEIGHT " +
              std::to_string (height) + " is not POINTS " +
              std::to_string (header.points);
    return false;
  }
  std::uint64_t point_step = 0;
  for (std::size_t i = 0; i < header.sizes.size(); ++i)
    point_step += header.sizes[i] * (header.counts.empty() ? 1 : header.counts[i]);
  if (point_step > kMaxPointStep) {
    problem =
        "a point of " + std::to_string (point_step) + " bytes is implausibly large";
    return false;
  }
  if (header.points * point_step > kMaxCompressionRatio * file_size) {
    problem = "its header announces " + std::to_string (header.points) + " points of " +
              std::to_string (point_step) + " bytes, far more than its " +
              std::to_string (file_size) + " bytes can hold";
    return false;
  }
  return true;
}

} // namespace

bool
checkPCDHeader (std::istream& stream, std::uint64_t file_size, std::string& problem)
{
  problem.clear();
  Header header;
  bool seen[kSpelling.size()] = {};
  int last = -1;
  std::string line;
  // The lines PCL reads as header: while a line starts with a keyword or a comment, also after
  // DATA (where the point data begins).
  while (std::getline (stream, line)) {
    if (line.empty())
      continue;
    std::istringstream tokens (line);
    tokens.imbue (std::locale::classic());
    std::string first;
    if (!(tokens >> first))
      break;
    if (first[0] == '#')
      continue;
    Keyword keyword{};
    if (!pclKeyword (first, keyword))
      break;
    const int rank = static_cast<int> (keyword);
    if (header.has_data)
      problem = "a header line ('" + first + "') follows the DATA line";
    else if (first != spelling (keyword))
      problem = "'" + first + "' is not a PCD v0.7 header keyword";
    else if (!isPlainText (line))
      problem = "the " + first + " line holds control characters";
    else if (seen[rank])
      problem = "it has two " + first + " lines";
    else if (rank < last)
      problem = "its " + first + " line comes after " +
                spelling (static_cast<Keyword> (last));
    if (!problem.empty())
      return false;
    seen[rank] = true;
    last = rank;
    std::vector<std::string> values;
    for (std::string value; tokens >> value;)
      values.push_back (value);
    if (!readValues (keyword, values, header, problem))
      return false;
  }
  return checkWhole (header, file_size, problem);
}

} // namespace detail
} // namespace io
} // namespace mid
