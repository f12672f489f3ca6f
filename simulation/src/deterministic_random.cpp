#include <mid/simulation/deterministic_random.h>

#include <algorithm>
#include <cmath>

namespace mid {
namespace simulation {

namespace {

/** Mixed into every seed sequence so that streams of small seeds do not look alike. */
constexpr std::uint32_t kSeedSalt = 0x6d696473u; // "mids"

constexpr double kTwoPi = 6.283185307179586476925286766559;

} // namespace

DeterministicRandom::DeterministicRandom (std::uint32_t seed, std::uint32_t stream)
{
  std::seed_seq sequence{seed, stream, kSeedSalt};
  engine_.seed (sequence);
}

std::uint32_t
DeterministicRandom::next()
{
  return static_cast<std::uint32_t> (engine_());
}

double
DeterministicRandom::uniform()
{
  const std::uint32_t high = next() >> 5; // 27 bits
  const std::uint32_t low = next() >> 6;  // 26 bits
  return (high * 67108864.0 + low) / 9007199254740992.0;
}

double
DeterministicRandom::uniform (double low, double high)
{
  return low + (high - low) * uniform();
}

int
DeterministicRandom::uniformInt (int count)
{
  if (count <= 0)
    return 0;
  return std::min (count - 1, static_cast<int> (uniform() * count));
}

double
DeterministicRandom::normal()
{
  if (has_spare_) {
    has_spare_ = false;
    return spare_;
  }
  const double u1 = 1.0 - uniform(); // (0, 1]: the logarithm stays finite
  const double u2 = uniform();
  const double radius = std::sqrt (-2.0 * std::log (u1));
  spare_ = radius * std::sin (kTwoPi * u2);
  has_spare_ = true;
  return radius * std::cos (kTwoPi * u2);
}

} // namespace simulation
} // namespace mid
