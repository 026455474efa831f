// Room for a large array, asked of the kernel in 2 MiB pages where it allows them (Linux's
// transparent huge pages in "madvise" mode): a hierarchy of 100k triangles fills about 50 MiB of
// fresh memory, and with 4 KiB pages a third of its build time went to page faults.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace cc {

/// Reserves room for n elements (as std::vector::reserve) and, for 2 MiB or more, advises the
/// kernel to back the whole 2 MiB pages inside it with huge pages, before they are first
/// touched. Only a hint: nothing changes where the kernel does not take it.
template <class T>
void reserve_large(std::vector<T>& v, std::size_t n) {
  v.reserve(n);
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t kPage = std::uintptr_t{1} << 21;
  const std::size_t bytes = v.capacity() * sizeof(T);
  if (bytes < kPage || !v.empty()) return;
  const auto begin = reinterpret_cast<std::uintptr_t>(v.data());
  const std::uintptr_t first = (begin + kPage - 1) & ~(kPage - 1), last = (begin + bytes) & ~(kPage - 1);
  if (last > first) madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
#endif
}

}  // namespace cc
