#pragma once
// Four float lanes on SSE2 (part of every x86-64 CPU, so no build flag is
// needed), or one; eight on AVX2 live in simd_avx2.h. The
// contact solver works on independent constraints side by side; Eigen's
// fixed-size types cover one vector, not lanes of unrelated rows, hence
// these small types. Operation order is fixed and the same at both widths
// (no fused multiply-add), so results stay deterministic and identical.

#include <cstdint>

#include <emmintrin.h>  // includes xmmintrin.h (_MM_TRANSPOSE4_PS)

namespace impulse::simd {

/// Lanes of one SSE register: four (F4), or the first alone (F1: a row
/// that is alone in its bundle, a tower's support row, costs its own two
/// bodies instead of a whole bundle's gather and scatter). The arithmetic,
/// compares and masks are the same instructions for both, as no lane's
/// bits depend on another's; a lone lane's neighbours hold whatever those
/// instructions make of the zeros it was loaded with, and only what reads
/// or writes memory, or asks which lanes are set, counts lanes.
template <int Lanes>
struct SseLanes {
  static constexpr int kLanes = Lanes;
  __m128 v;
};
using F4 = SseLanes<4>;
using F1 = SseLanes<1>;

template <int N>
inline SseLanes<N> operator+(SseLanes<N> a, SseLanes<N> b) { return {_mm_add_ps(a.v, b.v)}; }
template <int N>
inline SseLanes<N> operator-(SseLanes<N> a, SseLanes<N> b) { return {_mm_sub_ps(a.v, b.v)}; }
template <int N>
inline SseLanes<N> operator*(SseLanes<N> a, SseLanes<N> b) { return {_mm_mul_ps(a.v, b.v)}; }
template <int N>
inline SseLanes<N> operator/(SseLanes<N> a, SseLanes<N> b) { return {_mm_div_ps(a.v, b.v)}; }
template <int N>
inline SseLanes<N> operator-(SseLanes<N> a) { return {_mm_sub_ps(_mm_setzero_ps(), a.v)}; }
/// The correctly rounded square root, as std::sqrt's of each lane.
template <int N>
inline SseLanes<N> sqrt(SseLanes<N> a) { return {_mm_sqrt_ps(a.v)}; }
template <int N>
inline SseLanes<N>& operator+=(SseLanes<N>& a, SseLanes<N> b) { return a = a + b; }
template <int N>
inline SseLanes<N>& operator-=(SseLanes<N>& a, SseLanes<N> b) { return a = a - b; }
/// |a|: the sign bit cleared.
template <int N>
inline SseLanes<N> abs(SseLanes<N> a) { return {_mm_andnot_ps(_mm_set1_ps(-0.0f), a.v)}; }
/// -a exactly as a scalar negation: the sign flipped, also of a zero.
template <int N>
inline SseLanes<N> negated(SseLanes<N> a) { return {_mm_xor_ps(_mm_set1_ps(-0.0f), a.v)}; }
template <int N>
inline SseLanes<N> max(SseLanes<N> a, SseLanes<N> b) { return {_mm_max_ps(a.v, b.v)}; }
template <int N>
inline SseLanes<N> min(SseLanes<N> a, SseLanes<N> b) { return {_mm_min_ps(a.v, b.v)}; }
template <int N>
inline SseLanes<N> clamp(SseLanes<N> x, SseLanes<N> lo, SseLanes<N> hi) { return min(max(x, lo), hi); }
/// All-ones lanes where a > b.
template <int N>
inline SseLanes<N> greater(SseLanes<N> a, SseLanes<N> b) { return {_mm_cmpgt_ps(a.v, b.v)}; }
template <int N>
inline SseLanes<N> less(SseLanes<N> a, SseLanes<N> b) { return {_mm_cmplt_ps(a.v, b.v)}; }
template <int N>
inline SseLanes<N> atLeast(SseLanes<N> a, SseLanes<N> b) { return {_mm_cmpge_ps(a.v, b.v)}; }
template <int N>
inline SseLanes<N> notEqual(SseLanes<N> a, SseLanes<N> b) { return {_mm_cmpneq_ps(a.v, b.v)}; }
template <int N>
inline SseLanes<N> both(SseLanes<N> a, SseLanes<N> b) { return {_mm_and_ps(a.v, b.v)}; }
template <int N>
inline SseLanes<N> either(SseLanes<N> a, SseLanes<N> b) { return {_mm_or_ps(a.v, b.v)}; }
/// mask ? a : b, lane by lane.
template <int N>
inline SseLanes<N> select(SseLanes<N> mask, SseLanes<N> a, SseLanes<N> b) {
  return {_mm_or_ps(_mm_and_ps(mask.v, a.v), _mm_andnot_ps(mask.v, b.v))};
}
/// All-ones lanes where a, read as a 32-bit integer, is greater than b (a
/// lane that carries an index or a count rather than a float).
template <int N>
inline SseLanes<N> intGreater(SseLanes<N> a, std::int32_t b) {
  return {_mm_castsi128_ps(_mm_cmpgt_epi32(_mm_castps_si128(a.v), _mm_set1_epi32(b)))};
}
/// A mask's lanes as bits (lane i: bit i); maskOfBits turns them back.
template <int N>
inline std::uint8_t bitsOf(SseLanes<N> mask) {
  return std::uint8_t(_mm_movemask_ps(mask.v) & ((1 << N) - 1));
}
/// True when any lane of a mask is set.
template <int N>
inline bool any(SseLanes<N> mask) { return bitsOf(mask) != 0; }
inline void store(float* p, F4 a) { _mm_storeu_ps(p, a.v); }
inline void store(float* p, F1 a) { _mm_store_ss(p, a.v); }

/// F's lanes from p[0], p[1], ... (width-generic code).
template <class F>
F load(const float* p);
template <>
inline F4 load<F4>(const float* p) {
  return {_mm_loadu_ps(p)};
}
template <>
inline F1 load<F1>(const float* p) {
  return {_mm_load_ss(p)};
}

/// Lanes of 32-bit integers from p[0], p[1], ... (an index column), and
/// back: one vector move each way (width-generic code). Copied through
/// floats on the stack instead, a column's load waited on the two halves
/// the copy had just stored there.
template <class F>
F loadInts(const std::int32_t* p);
template <>
inline F4 loadInts<F4>(const std::int32_t* p) {
  return {_mm_castsi128_ps(_mm_loadu_si128(reinterpret_cast<const __m128i*>(p)))};
}
template <>
inline F1 loadInts<F1>(const std::int32_t* p) {
  return {_mm_castsi128_ps(_mm_cvtsi32_si128(*p))};
}
inline void storeInts(std::int32_t* p, F4 a) { _mm_storeu_si128(reinterpret_cast<__m128i*>(p), _mm_castps_si128(a.v)); }
inline void storeInts(std::int32_t* p, F1 a) { *p = _mm_cvtsi128_si32(_mm_castps_si128(a.v)); }

/// x in every lane of F (width-generic code).
template <class F>
F broadcast(float x);
template <>
inline F4 broadcast<F4>(float x) {
  return {_mm_set1_ps(x)};
}
template <>
inline F1 broadcast<F1>(float x) {
  return {_mm_set_ss(x)};
}

/// A mask with lane i all ones where bit i of `bits` is set (width-generic
/// code).
template <class F>
F maskOfBits(std::uint8_t bits);
template <>
inline F4 maskOfBits<F4>(std::uint8_t bits) {
  const __m128i laneBit = _mm_setr_epi32(1, 2, 4, 8);
  return {_mm_castsi128_ps(_mm_cmpeq_epi32(_mm_and_si128(_mm_set1_epi32(bits), laneBit), laneBit))};
}
template <>
inline F1 maskOfBits<F1>(std::uint8_t bits) {
  return {_mm_castsi128_ps(_mm_cvtsi32_si128((bits & 1u) != 0 ? -1 : 0))};
}

/// Reads the first eight floats of four rows as eight four-lane columns.
[[gnu::always_inline]] inline void loadColumns(const float* const rows[4], F4 columns[8]) {
  __m128 a0 = _mm_loadu_ps(rows[0]), a1 = _mm_loadu_ps(rows[1]), a2 = _mm_loadu_ps(rows[2]),
         a3 = _mm_loadu_ps(rows[3]);
  __m128 b0 = _mm_loadu_ps(rows[0] + 4), b1 = _mm_loadu_ps(rows[1] + 4),
         b2 = _mm_loadu_ps(rows[2] + 4), b3 = _mm_loadu_ps(rows[3] + 4);
  _MM_TRANSPOSE4_PS(a0, a1, a2, a3);
  _MM_TRANSPOSE4_PS(b0, b1, b2, b3);
  columns[0] = {a0}, columns[1] = {a1}, columns[2] = {a2}, columns[3] = {a3};
  columns[4] = {b0}, columns[5] = {b1}, columns[6] = {b2}, columns[7] = {b3};
}

/// Writes four columns back as the first four floats of four rows.
[[gnu::always_inline]] inline void storeColumns(const F4 columns[4], float* const rows[4]) {
  __m128 r0 = columns[0].v, r1 = columns[1].v, r2 = columns[2].v, r3 = columns[3].v;
  _MM_TRANSPOSE4_PS(r0, r1, r2, r3);
  _mm_storeu_ps(rows[0], r0);
  _mm_storeu_ps(rows[1], r1);
  _mm_storeu_ps(rows[2], r2);
  _mm_storeu_ps(rows[3], r3);
}

/// The first eight floats of one row, each its own column.
[[gnu::always_inline]] inline void loadColumns(const float* const rows[1], F1 columns[8]) {
  for (int i = 0; i < 8; ++i) columns[i] = {_mm_load_ss(rows[0] + i)};
}
/// Four columns back as the first four floats of one row.
[[gnu::always_inline]] inline void storeColumns(const F1 columns[4], float* const rows[1]) {
  for (int i = 0; i < 4; ++i) _mm_store_ss(rows[0] + i, columns[i].v);
}

}  // namespace impulse::simd
