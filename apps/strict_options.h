#pragma once

// Strict command-line checking for every app: unknown arguments, options without their values,
// and numbers with trailing junk or out of range are refused with a one-line message instead of
// being ignored or read as 0 (pcl::console::parse_argument alone does either). Header-only.

#include <pcl/console/parse.h>
#include <pcl/console/print.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

namespace mid {
namespace apps {

/** \brief One command-line option: its name and how many values follow it (0: a switch). */
struct OptionSpec
{
  const char* name;
  int values;
};

using OptionSpecs = std::vector<OptionSpec>;

/** \brief True if `text` ends in `ending` (and is longer), ignoring case, as
  * pcl::console::parse_file_extension_argument does (SCENE.PCD is a scene).
  */
inline bool
endsWithIgnoringCase (const std::string& text, const std::string& ending)
{
  return text.size() > ending.size() &&
         std::equal (ending.begin(),
                     ending.end(),
                     text.end() - static_cast<std::ptrdiff_t> (ending.size()),
                     [] (char a, char b) {
                       return std::tolower (static_cast<unsigned char> (a)) ==
                              std::tolower (static_cast<unsigned char> (b));
                     });
}

/** \brief True if every argument is one of `options` followed by its values, or a file argument
  * (not starting with '-') whose name ends in one of `file_endings`; otherwise prints which
  * argument is wrong and returns false. Which files an app needs is for the app to check.
  */
inline bool
onlyKnownArguments (int argc,
                    char** argv,
                    const OptionSpecs& options,
                    const std::vector<std::string>& file_endings = {})
{
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    const auto option =
        std::find_if (options.begin(),
                      options.end(),
                      [&argument] (const OptionSpec& o) { return argument == o.name; });
    if (option == options.end()) {
      const bool file = argument[0] != '-' &&
                        std::any_of (file_endings.begin(),
                                     file_endings.end(),
                                     [&] (const std::string& ending) {
                                       return endsWithIgnoringCase (argument, ending);
                                     });
      if (!file) {
        pcl::console::print_error ("Unknown argument '%s' (see -h).\n", argv[i]);
        return false;
      }
      continue;
    }
    const bool values_given =
        i + option->values < argc &&
        std::none_of (
            argv + i + 1, argv + i + 1 + option->values, [&options] (const char* v) {
              return std::any_of (
                  options.begin(), options.end(), [v] (const OptionSpec& o) {
                    return std::string (v) == o.name;
                  });
            });
    if (!values_given) {
      pcl::console::print_error ("Option %s needs %d value%s.\n",
                                 argv[i],
                                 option->values,
                                 option->values > 1 ? "s" : "");
      return false;
    }
    i += option->values;
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

/** \brief The range of an integral T that toInteger can read. */
template <typename T>
constexpr long
lowestInteger ()
{
  return static_cast<long> (std::numeric_limits<T>::lowest());
}

template <typename T>
constexpr long
highestInteger ()
{
  return std::numeric_limits<T>::max() >
                 static_cast<unsigned long> (std::numeric_limits<long>::max())
             ? std::numeric_limits<long>::max()
             : static_cast<long> (std::numeric_limits<T>::max());
}

/** \brief True if `text` is a plain decimal number: an optional '-', digits with an optional
  * fraction (at least one digit in all), and an optional exponent ('e' or 'E', an optional
  * sign, digits). strtod alone also takes a '+', hexadecimal, "inf" and "nan".
  */
inline bool
isPlainDecimal (const std::string& text)
{
  const auto digit = [&text] (std::size_t i) {
    return i < text.size() && std::isdigit (static_cast<unsigned char> (text[i]));
  };
  std::size_t i = text.empty() || text[0] != '-' ? 0 : 1, digits = 0;
  for (; digit (i); ++i)
    ++digits;
  if (i < text.size() && text[i] == '.')
    for (++i; digit (i); ++i)
      ++digits;
  if (digits == 0)
    return false;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    if (i < text.size() && (text[i] == '+' || text[i] == '-'))
      ++i;
    if (!digit (i))
      return false;
    while (digit (i))
      ++i;
  }
  return i == text.size();
}

/** \brief Strict conversion of a whole string to a number of type T: an integer in T's range
  * for an integral T; for a floating-point T, a plain decimal (isPlainDecimal()) that T holds
  * without overflowing, or underflowing to 0.
  */
template <typename T>
bool
toNumber (const std::string& text, T& value)
{
  if constexpr (std::is_integral_v<T>) {
    long integer = 0;
    if (!toInteger (text, lowestInteger<T>(), highestInteger<T>(), integer))
      return false;
    value = static_cast<T> (integer);
    return true;
  }
  else {
    if (!isPlainDecimal (text))
      return false;
    errno = 0;
    char* end = nullptr;
    const double number = std::strtod (text.c_str(), &end);
    if (errno != 0 || *end != '\0' || !std::isfinite (number) ||
        std::abs (number) > static_cast<double> (std::numeric_limits<T>::max()) ||
        (number != 0.0 && static_cast<T> (number) == T (0)))
      return false;
    value = static_cast<T> (number);
    return true;
  }
}

/** \brief Read number option `name` into `value` if given (pcl::console::parse_argument, but
  * strict); false after a message naming the option if its value is not a number of type T.
  */
template <typename T>
bool
parseNumber (int argc, char** argv, const char* name, T& value)
{
  std::string text;
  if (pcl::console::parse_argument (argc, argv, name, text) < 0)
    return true;
  if (toNumber (text, value))
    return true;
  if constexpr (std::is_integral_v<T>)
    pcl::console::print_error ("%s must be an integer in [%ld, %ld], got '%s'.\n",
                               name,
                               lowestInteger<T>(),
                               highestInteger<T>(),
                               text.c_str());
  else
    pcl::console::print_error ("%s must be a number, got '%s'.\n", name, text.c_str());
  return false;
}

} // namespace apps
} // namespace mid
