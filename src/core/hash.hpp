#pragma once
// FNV-1a, 64 bits (Fowler, Noll and Vo; http://www.isthe.com/chongo/tech/comp/fnv/): a cheap,
// stable hash for cache keys (not for security). Chain calls by passing the previous hash.
#include <cstddef>
#include <cstdint>
#include <string>

namespace nephele::core {

constexpr std::uint64_t fnv1a_offset = 14695981039346656037ull;

inline std::uint64_t fnv1a(const void* data, std::size_t bytes, std::uint64_t hash = fnv1a_offset) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < bytes; ++i) {
    hash ^= p[i];
    hash *= 1099511628211ull;
  }
  return hash;
}

inline std::uint64_t fnv1a(const std::string& text, std::uint64_t hash = fnv1a_offset) {
  return fnv1a(text.data(), text.size(), hash);
}

}  // namespace nephele::core
