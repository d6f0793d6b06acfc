#pragma once
// Eight float lanes on AVX2: the operations of simd.h's F4 for F8, one for
// one, so the contact solver's template runs at either width with the same
// arithmetic per lane. Include only after `#pragma GCC target("avx2")` in a
// file whose functions run after a CPU check (contact_solver_wide_avx2.cpp).

#include <immintrin.h>

#include "simd.h"

namespace impulse::simd {

// Never name this type outside AVX2-compiled code: without AVX, GCC lays
// __m256 out with 16-byte alignment (here too, when a header declared it
// before the pragma), so the alignment is spelled out and the type kept to
// one file.
struct alignas(32) F8 {
  static constexpr int kLanes = 8;
  __m256 v;
};

template <>
inline F8 broadcast<F8>(float x) {
  return {_mm256_set1_ps(x)};
}
template <>
inline F8 load<F8>(const float* p) {
  return {_mm256_loadu_ps(p)};
}
template <>
inline F8 loadInts<F8>(const std::int32_t* p) {
  return {_mm256_castsi256_ps(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(p)))};
}
inline void storeInts(std::int32_t* p, F8 a) {
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(p), _mm256_castps_si256(a.v));
}
template <>
inline F8 maskOfBits<F8>(std::uint8_t bits) {
  const __m256i laneBit = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
  return {_mm256_castsi256_ps(_mm256_cmpeq_epi32(_mm256_and_si256(_mm256_set1_epi32(bits), laneBit), laneBit))};
}
inline F8 operator+(F8 a, F8 b) { return {_mm256_add_ps(a.v, b.v)}; }
inline F8 operator-(F8 a, F8 b) { return {_mm256_sub_ps(a.v, b.v)}; }
inline F8 operator*(F8 a, F8 b) { return {_mm256_mul_ps(a.v, b.v)}; }
inline F8 operator/(F8 a, F8 b) { return {_mm256_div_ps(a.v, b.v)}; }
inline F8 operator-(F8 a) { return {_mm256_sub_ps(_mm256_setzero_ps(), a.v)}; }
inline F8 sqrt(F8 a) { return {_mm256_sqrt_ps(a.v)}; }
inline F8& operator+=(F8& a, F8 b) { return a = a + b; }
inline F8& operator-=(F8& a, F8 b) { return a = a - b; }
inline F8 abs(F8 a) { return {_mm256_andnot_ps(_mm256_set1_ps(-0.0f), a.v)}; }
/// -a exactly as a scalar negation: the sign flipped, also of a zero.
inline F8 negated(F8 a) { return {_mm256_xor_ps(_mm256_set1_ps(-0.0f), a.v)}; }
inline F8 max(F8 a, F8 b) { return {_mm256_max_ps(a.v, b.v)}; }
inline F8 min(F8 a, F8 b) { return {_mm256_min_ps(a.v, b.v)}; }
inline F8 clamp(F8 x, F8 lo, F8 hi) { return min(max(x, lo), hi); }
// Predicates as SSE2's: ordered greater/less, unordered not-equal.
inline F8 greater(F8 a, F8 b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_GT_OS)}; }
inline F8 less(F8 a, F8 b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_LT_OS)}; }
inline F8 atLeast(F8 a, F8 b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_GE_OS)}; }
inline F8 notEqual(F8 a, F8 b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_NEQ_UQ)}; }
inline F8 both(F8 a, F8 b) { return {_mm256_and_ps(a.v, b.v)}; }
inline F8 either(F8 a, F8 b) { return {_mm256_or_ps(a.v, b.v)}; }
// One blend instead of SSE2's and, andnot, or: the same lanes, since every
// mask's lanes are all ones or all zeros (blend reads their sign bits).
inline F8 select(F8 mask, F8 a, F8 b) { return {_mm256_blendv_ps(b.v, a.v, mask.v)}; }
inline F8 intGreater(F8 a, std::int32_t b) {
  return {_mm256_castsi256_ps(_mm256_cmpgt_epi32(_mm256_castps_si256(a.v), _mm256_set1_epi32(b)))};
}
inline bool any(F8 mask) { return _mm256_movemask_ps(mask.v) != 0; }
inline std::uint8_t bitsOf(F8 mask) { return std::uint8_t(_mm256_movemask_ps(mask.v)); }
inline void store(float* p, F8 a) { _mm256_storeu_ps(p, a.v); }

/// Reads the first eight floats of eight rows as eight eight-lane columns.
/// These transpositions are the kernels' gather and scatter, always inlined:
/// left to GCC, a grown file had them called out of line from the contact
/// solve (v3's many_pyramids: storeColumns' own samples four times as many,
/// the step 3-5 % longer).
[[gnu::always_inline]] inline void loadColumns(const float* const rows[8], F8 columns[8]) {
  __m256 r[8];
  for (int i = 0; i < 8; ++i) r[i] = _mm256_loadu_ps(rows[i]);
  __m256 t0 = _mm256_unpacklo_ps(r[0], r[1]), t1 = _mm256_unpackhi_ps(r[0], r[1]);
  __m256 t2 = _mm256_unpacklo_ps(r[2], r[3]), t3 = _mm256_unpackhi_ps(r[2], r[3]);
  __m256 t4 = _mm256_unpacklo_ps(r[4], r[5]), t5 = _mm256_unpackhi_ps(r[4], r[5]);
  __m256 t6 = _mm256_unpacklo_ps(r[6], r[7]), t7 = _mm256_unpackhi_ps(r[6], r[7]);
  // Per 128-bit half: rows 0-3 (and 4-7) of columns k and k+4.
  __m256 c0 = _mm256_shuffle_ps(t0, t2, 0x44), c1 = _mm256_shuffle_ps(t0, t2, 0xEE);
  __m256 c2 = _mm256_shuffle_ps(t1, t3, 0x44), c3 = _mm256_shuffle_ps(t1, t3, 0xEE);
  __m256 c4 = _mm256_shuffle_ps(t4, t6, 0x44), c5 = _mm256_shuffle_ps(t4, t6, 0xEE);
  __m256 c6 = _mm256_shuffle_ps(t5, t7, 0x44), c7 = _mm256_shuffle_ps(t5, t7, 0xEE);
  columns[0] = {_mm256_permute2f128_ps(c0, c4, 0x20)};
  columns[1] = {_mm256_permute2f128_ps(c1, c5, 0x20)};
  columns[2] = {_mm256_permute2f128_ps(c2, c6, 0x20)};
  columns[3] = {_mm256_permute2f128_ps(c3, c7, 0x20)};
  columns[4] = {_mm256_permute2f128_ps(c0, c4, 0x31)};
  columns[5] = {_mm256_permute2f128_ps(c1, c5, 0x31)};
  columns[6] = {_mm256_permute2f128_ps(c2, c6, 0x31)};
  columns[7] = {_mm256_permute2f128_ps(c3, c7, 0x31)};
}

/// Writes four columns back as the first four floats of eight rows.
[[gnu::always_inline]] inline void storeColumns(const F8 columns[4], float* const rows[8]) {
  for (int half = 0; half < 2; ++half) {
    __m128 r0 = half == 0 ? _mm256_castps256_ps128(columns[0].v) : _mm256_extractf128_ps(columns[0].v, 1);
    __m128 r1 = half == 0 ? _mm256_castps256_ps128(columns[1].v) : _mm256_extractf128_ps(columns[1].v, 1);
    __m128 r2 = half == 0 ? _mm256_castps256_ps128(columns[2].v) : _mm256_extractf128_ps(columns[2].v, 1);
    __m128 r3 = half == 0 ? _mm256_castps256_ps128(columns[3].v) : _mm256_extractf128_ps(columns[3].v, 1);
    _MM_TRANSPOSE4_PS(r0, r1, r2, r3);
    _mm_storeu_ps(rows[4 * half + 0], r0);
    _mm_storeu_ps(rows[4 * half + 1], r1);
    _mm_storeu_ps(rows[4 * half + 2], r2);
    _mm_storeu_ps(rows[4 * half + 3], r3);
  }
}

}  // namespace impulse::simd
