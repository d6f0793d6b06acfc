#pragma once
// Asking for memory ahead of its use.

#include <cstddef>

namespace impulse {

namespace detail {

/// Calls fetch(line) for the cache lines at address, address + 64, ...
/// below address + bytes (the first at least).
template <class Fetch>
inline void forEachLine(const void* address, std::size_t bytes, Fetch fetch) {
  const char* start = static_cast<const char*>(address);
  for (std::size_t offset = 0; offset < bytes; offset += 64) fetch(start + offset);
}

}  // namespace detail

/// Starts loading the cache lines at address, address + 64, ... below
/// address + bytes (an object that straddles a line boundary past its
/// last multiple of 64 needs its last byte asked for too). An asm
/// statement rather than __builtin_prefetch: GCC counts the builtin as
/// without effect, so a function made only of prefetches is taken for pure
/// and its calls are dropped (the contact fill once fetched nothing ahead
/// that way). Elsewhere than x86, the builtin.
inline void fetchLines(const void* address, std::size_t bytes = 1) {
  detail::forEachLine(address, bytes, [](const char* line) {
#if defined(__x86_64__) || defined(__i386__)
    asm volatile("prefetcht0 %0" : : "m"(*line));
#else
    __builtin_prefetch(line);
#endif
  });
}

/// The same for lines about to be written: fetched ready to be written
/// (prefetchw), so the stores that follow need not wait for them.
inline void fetchLinesForWrite(void* address, std::size_t bytes = 1) {
  detail::forEachLine(address, bytes, [](const char* line) {
#if defined(__x86_64__) || defined(__i386__)
    asm volatile("prefetchw %0" : : "m"(*line));
#else
    __builtin_prefetch(line, 1);
#endif
  });
}

}  // namespace impulse
