#pragma once

#include <cstddef>

namespace mid {
namespace bench {

/** \brief Bytes currently allocated through operator new in this process. */
std::size_t
currentAllocatedBytes ();

/** \brief Restart peak tracking at the current allocation level. */
void
resetPeakAllocatedBytes ();

/** \brief Largest allocation level since the last reset. */
std::size_t
peakAllocatedBytes ();

} // namespace bench
} // namespace mid
