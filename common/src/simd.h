#pragma once
// Four float lanes on SSE2 (part of every x86-64 CPU, so no build flag is
// needed). The contact solver works on four independent constraints at once;
// Eigen's fixed-size types cover one vector, not lanes of unrelated rows,
// hence this small type. Operation order is fixed, so results stay
// deterministic.

#include <emmintrin.h>  // includes xmmintrin.h (_MM_TRANSPOSE4_PS)

namespace impulse::simd {

struct F4 {
  __m128 v;
};

inline F4 splat(float x) { return {_mm_set1_ps(x)}; }
inline F4 zero() { return {_mm_setzero_ps()}; }
inline F4 operator+(F4 a, F4 b) { return {_mm_add_ps(a.v, b.v)}; }
inline F4 operator-(F4 a, F4 b) { return {_mm_sub_ps(a.v, b.v)}; }
inline F4 operator*(F4 a, F4 b) { return {_mm_mul_ps(a.v, b.v)}; }
inline F4 operator-(F4 a) { return {_mm_sub_ps(_mm_setzero_ps(), a.v)}; }
inline F4& operator+=(F4& a, F4 b) { return a = a + b; }
inline F4& operator-=(F4& a, F4 b) { return a = a - b; }
inline F4 max(F4 a, F4 b) { return {_mm_max_ps(a.v, b.v)}; }
inline F4 min(F4 a, F4 b) { return {_mm_min_ps(a.v, b.v)}; }
inline F4 clamp(F4 x, F4 lo, F4 hi) { return min(max(x, lo), hi); }
/// All-ones lanes where a > b.
inline F4 greater(F4 a, F4 b) { return {_mm_cmpgt_ps(a.v, b.v)}; }
inline F4 less(F4 a, F4 b) { return {_mm_cmplt_ps(a.v, b.v)}; }
inline F4 notEqual(F4 a, F4 b) { return {_mm_cmpneq_ps(a.v, b.v)}; }
inline F4 both(F4 a, F4 b) { return {_mm_and_ps(a.v, b.v)}; }
/// mask ? a : b, lane by lane.
inline F4 select(F4 mask, F4 a, F4 b) {
  return {_mm_or_ps(_mm_and_ps(mask.v, a.v), _mm_andnot_ps(mask.v, b.v))};
}
/// True when any lane of a mask is set.
inline bool any(F4 mask) { return _mm_movemask_ps(mask.v) != 0; }
inline F4 load(const float* p) { return {_mm_loadu_ps(p)}; }
inline void store(float* p, F4 a) { _mm_storeu_ps(p, a.v); }
inline F4 set(float a, float b, float c, float d) { return {_mm_setr_ps(a, b, c, d)}; }

}  // namespace impulse::simd
