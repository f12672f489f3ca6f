#pragma once

#include <cstdint>
#include <istream>
#include <string>

namespace mid {
namespace io {
namespace detail {

/** \brief Check that a PCD header is written exactly as the PCD format specifies, before PCL's
  * reader sees it.
  *
  * PCL's pcl::PCDReader::readHeader parses numbers with unchecked stream extraction into int
  * (a failed extraction leaves a value it then uses uninitialized, an overflow wraps), matches
  * keywords by prefix, splits tokens on other characters than its stream extraction does, and
  * allocates the point data (points x point step bytes) as soon as it reads the POINTS line.
  * Fuzzing found several headers on which this allocated tens of gigabytes or wrote past its
  * buffer (see doc/quality_gates.md). Instead of predicting what PCL makes of a damaged header,
  * this check accepts only headers on which it cannot go wrong: the keywords spelled exactly, in
  * the order the format gives (VERSION, FIELDS, SIZE, TYPE, COUNT, WIDTH, HEIGHT, VIEWPOINT,
  * POINTS, DATA; VERSION, COUNT, WIDTH, HEIGHT and VIEWPOINT may be missing), each at most once,
  * printable ASCII only, one SIZE, TYPE and COUNT value per field, sizes 1, 2, 4 or 8 bytes (I, U,
  * F of 4 or 8, B of 1), plain decimal numbers within PCL's int, no HEIGHT without WIDTH,
  * WIDTH x HEIGHT equal to POINTS, seven VIEWPOINT numbers that are finite floats, a
  * known DATA kind, no header line after DATA, and no more point data than the file could hold
  * (its size times the largest LZF expansion). Every file PCL's writer produces passes, unless
  * its viewpoint is not finite.
  * \param[in] stream the file, positioned at its start
  * \param[in] file_size the file's size in bytes
  * \param[out] problem what is wrong with the header; empty on success
  * \return true if the header passes
  */
bool
checkPCDHeader (std::istream& stream, std::uint64_t file_size, std::string& problem);

} // namespace detail
} // namespace io
} // namespace mid
