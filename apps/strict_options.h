#pragma once

// Strict command-line checking for the apps that do not link mid_app_support (the synthesizers):
// unknown arguments, options without a value, and integers with trailing junk are refused with
// a one-line message instead of being ignored or read as 0 (pcl::console::parse_argument alone
// does either). Header-only, used by one translation unit per app.

#include <pcl/console/parse.h>
#include <pcl/console/print.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstddef>
#include <cstdlib>
#include <iterator>
#include <string>

namespace mid {
namespace apps {

/** \brief True if `argument` is one of `options`. */
template <std::size_t N>
bool
isOneOf (const std::string& argument, const char* const (&options)[N])
{
  return std::any_of (std::begin (options),
                      std::end (options),
                      [&argument] (const char* option) { return argument == option; });
}

/** \brief True if every argument is one of `switches`, or one of `value_options` followed by a
  * value; otherwise prints which argument is wrong and returns false.
  */
template <std::size_t S, std::size_t V>
bool
onlyKnownArguments (int argc,
                    char** argv,
                    const char* const (&switches)[S],
                    const char* const (&value_options)[V])
{
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    if (isOneOf (argument, switches))
      continue;
    if (!isOneOf (argument, value_options)) {
      pcl::console::print_error ("Unknown argument '%s' (see -h).\n", argv[i]);
      return false;
    }
    if (i + 1 >= argc) {
      pcl::console::print_error ("Option %s needs a value.\n", argv[i]);
      return false;
    }
    ++i; // the value
  }
  return true;
}

/** \brief Strict conversion of a whole decimal string to an integer in [low, high]. */
inline bool
toInteger (const std::string& text, long low, long high, long& value)
{
  if (text.empty() ||
      (text[0] != '-' && !std::isdigit (static_cast<unsigned char> (text[0]))))
    return false;
  errno = 0;
  char* end = nullptr;
  value = std::strtol (text.c_str(), &end, 10);
  return errno == 0 && *end == '\0' && value >= low && value <= high;
}

/** \brief Read integer option `name` into `value` if given; false (after a message naming the
  * option and its range) if its value is no integer in [low, high].
  */
inline bool
parseIntegerOption (
    int argc, char** argv, const char* name, long low, long high, long& value)
{
  std::string text;
  if (pcl::console::parse_argument (argc, argv, name, text) < 0)
    return true;
  if (toInteger (text, low, high, value))
    return true;
  pcl::console::print_error ("%s must be an integer in [%ld, %ld], got '%s'.\n",
                             name,
                             low,
                             high,
                             text.c_str());
  return false;
}

} // namespace apps
} // namespace mid
