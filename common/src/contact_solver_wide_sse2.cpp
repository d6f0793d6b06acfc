// The contact solver's passes four constraints at a time on SSE2, which
// every x86-64 CPU has; and the choice of width.

#include "contact_solver_wide.h"
#include "simd.h"

namespace impulse {

template <>
std::vector<WideConstraint<simd::F4>>& bundlesOf<simd::F4>(WideContactSet& set) {
  return set.bundles4;
}

template <>
std::vector<WideContactCold<simd::F4>>& coldPartsOf<simd::F4>(WideContactSet& set) {
  return set.cold4;
}

template <>
std::vector<WideSupportRow<simd::F4>>& supportBundlesOf<simd::F4>(WideContactSet& set) {
  return set.support4;
}

}  // namespace impulse

#include "contact_solver_wide_impl.h"

namespace impulse {

const WideContactKernels& sse2WideContactKernels() {
  static const WideContactKernels kernels = makeWideContactKernels<simd::F4>();
  return kernels;
}

const WideContactKernels& wideContactKernels(SimdWidth requested) {
  static const bool hasAvx2 = __builtin_cpu_supports("avx2");
  if (requested != SimdWidth::Sse2 && hasAvx2) return avx2WideContactKernels();
  return sse2WideContactKernels();
}

}  // namespace impulse
