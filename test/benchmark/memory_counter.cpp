// Replaces the global operator new/delete of the benchmark binary to count the bytes it holds,
// so that a benchmark can report the peak memory of one call, not of the whole process.
#include "memory_counter.h"

#include <atomic>
#include <cstdlib>
#include <new>

namespace {

std::atomic<std::size_t> current{0};
std::atomic<std::size_t> peak{0};

/** Room in front of each block to remember its size. */
constexpr std::size_t kHeader = alignof (std::max_align_t);

void*
allocate (std::size_t size)
{
  auto* block = static_cast<unsigned char*> (std::malloc (size + kHeader));
  if (block == nullptr)
    throw std::bad_alloc();
  *reinterpret_cast<std::size_t*> (block) = size;
  const std::size_t now = current.fetch_add (size) + size;
  std::size_t seen = peak.load();
  while (now > seen && !peak.compare_exchange_weak (seen, now)) {
  }
  return block + kHeader;
}

void
release (void* pointer)
{
  if (pointer == nullptr)
    return;
  auto* block = static_cast<unsigned char*> (pointer) - kHeader;
  current.fetch_sub (*reinterpret_cast<std::size_t*> (block));
  std::free (block);
}

} // namespace

void*
operator new (std::size_t size)
{
  return allocate (size);
}

void*
operator new[] (std::size_t size)
{
  return allocate (size);
}

void
operator delete (void* pointer) noexcept
{
  release (pointer);
}

void
operator delete[] (void* pointer) noexcept
{
  release (pointer);
}

void
operator delete (void* pointer, std::size_t /*size*/) noexcept
{
  release (pointer);
}

void
operator delete[] (void* pointer, std::size_t /*size*/) noexcept
{
  release (pointer);
}

namespace mid {
namespace bench {

std::size_t
currentAllocatedBytes ()
{
  return current.load();
}

void
resetPeakAllocatedBytes ()
{
  peak.store (current.load());
}

std::size_t
peakAllocatedBytes ()
{
  return peak.load();
}

} // namespace bench
} // namespace mid
