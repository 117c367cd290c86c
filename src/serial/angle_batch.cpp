// SLEEF's atan2 over a batch of (cos, sin) pairs (angle_batch.hpp).
#include "angle_batch.hpp"

#if defined(__x86_64__) || defined(_M_X64)
#include <emmintrin.h>
#include <sleef.h>
#endif

namespace dispkin {
namespace serial {
namespace detail {

void angles_of(const CosSin* pairs, std::size_t n, double* angles) noexcept {
#if defined(__x86_64__) || defined(_M_X64)
  static_assert(sizeof(CosSin) == 2 * sizeof(double), "CosSin is the pair (c, s) in memory");
  std::size_t i = 0;
  for (; i + 2 <= n; i += 2) {
    // (c₀, s₀), (c₁, s₁) → x = (c₀, c₁), y = (s₀, s₁).
    const __m128d first = _mm_loadu_pd(&pairs[i].c);
    const __m128d second = _mm_loadu_pd(&pairs[i + 1].c);
    _mm_storeu_pd(angles + i, Sleef_atan2d2_u35(_mm_unpackhi_pd(first, second), _mm_unpacklo_pd(first, second)));
  }
  if (i < n) angles[i] = pairs[i].angle();
#else
  for (std::size_t i = 0; i < n; ++i) angles[i] = pairs[i].angle();
#endif
}

}  // namespace detail
}  // namespace serial
}  // namespace dispkin
