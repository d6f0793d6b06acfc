// The contact solver's passes eight constraints at a time on AVX2. Only the
// code below the pragma (GCC's target pragma, clang's attribute region) is
// compiled for AVX2, and it runs only after wideContactKernels() found the
// CPU able to; the headers above it (the
// standard library's included) stay plain x86-64, so nothing this file
// shares with others by name carries AVX2 instructions.

#include <algorithm>
#include <array>
#include <bit>
#include <span>
#include <type_traits>
#include <vector>

#include "contact_solver.h"
#include "contact_solver_wide.h"
#include "world_data.h"

#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx2"))), apply_to = function)
#else
#pragma GCC target("avx2")
#endif

#include "simd_avx2.h"

namespace impulse {

struct Avx2Bundles {
  std::vector<WideConstraint<simd::F8>> list;
  std::vector<WideContactCold<simd::F8>> cold;
  std::vector<WideSupportRow<simd::F8>> support;
};

// Called only for a set that holds eight-lane bundles, so only after the
// CPU check.
void Avx2BundlesDeleter::operator()(Avx2Bundles* bundles) const { delete bundles; }

template <>
std::vector<WideConstraint<simd::F8>>& bundlesOf<simd::F8>(WideContactSet& set) {
  if (!set.bundles8) set.bundles8.reset(new Avx2Bundles);
  return set.bundles8->list;
}

template <>
std::vector<WideContactCold<simd::F8>>& coldPartsOf<simd::F8>(WideContactSet& set) {
  if (!set.bundles8) set.bundles8.reset(new Avx2Bundles);
  return set.bundles8->cold;
}

template <>
std::vector<WideSupportRow<simd::F8>>& supportBundlesOf<simd::F8>(WideContactSet& set) {
  if (!set.bundles8) set.bundles8.reset(new Avx2Bundles);
  return set.bundles8->support;
}

}  // namespace impulse

#include "contact_solver_wide_impl.h"

namespace impulse {

const WideContactKernels& avx2WideContactKernels() {
  static const WideContactKernels kernels = makeWideContactKernels<simd::F8>();
  return kernels;
}

}  // namespace impulse

#if defined(__clang__)
#pragma clang attribute pop
#endif
