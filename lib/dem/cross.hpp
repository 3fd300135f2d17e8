// The cross product of the contact loops. Eigen's a.cross(b) writes its three components one by
// one into memory, and the vector sums that take it read two of them back as one packet: the
// store cannot be forwarded to that load, and each contact waited for it (perf put about a
// quarter of the wall loop's samples on those loads, docs/performance.md). Here the first two
// components are made as one packet. The same products and differences as Eigen's: the same bits.
#pragma once

#include "dem/particles.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace demscale::dem {

inline Vec3 cross(const Vec3& a, const Vec3& b) {
#if defined(__SSE2__)
    // Read as Eigen writes a vector: components 0 and 1 as a packet, 2 alone (a load across
    // two stores cannot be forwarded either).
    const __m128d a01 = _mm_loadu_pd(a.data()), a2 = _mm_load_sd(a.data() + 2);
    const __m128d b01 = _mm_loadu_pd(b.data()), b2 = _mm_load_sd(b.data() + 2);
    const __m128d a12 = _mm_shuffle_pd(a01, a2, 1), a20 = _mm_unpacklo_pd(a2, a01);  // (a1, a2), (a2, a0)
    const __m128d b12 = _mm_shuffle_pd(b01, b2, 1), b20 = _mm_unpacklo_pd(b2, b01);  // (b1, b2), (b2, b0)
    Vec3 out;
    _mm_storeu_pd(out.data(), _mm_sub_pd(_mm_mul_pd(a12, b20), _mm_mul_pd(a20, b12)));  // a1 b2 − a2 b1, a2 b0 − a0 b2
    out[2] = a[0] * b[1] - a[1] * b[0];
    return out;
#else
    return a.cross(b);
#endif
}

}  // namespace demscale::dem
