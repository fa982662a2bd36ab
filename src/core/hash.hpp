#pragma once
// Two stable 64-bit hashes (not for security): FNV-1a (Fowler, Noll and Vo;
// http://www.isthe.com/chongo/tech/comp/fnv/) for cache keys and other short texts, and
// block_hash for large payloads (the disk cache's content check, megabytes). Chain calls by
// passing the previous hash as the seed.
#include <cstddef>
#include <cstdint>
#include <cstring>
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

namespace detail {

// Odd multipliers: 2^64 over the golden ratio, and the second constant of Stafford's "Mix13"
// variant of the SplitMix64 finaliser. Being odd makes each multiplication a bijection.
constexpr std::uint64_t block_k1 = 0x9E3779B97F4A7C15ull;
constexpr std::uint64_t block_k2 = 0x94D049BB133111EBull;

// One lane step: a bijection of the lane for a fixed word and of the word for a fixed lane, so
// a change of one word always changes the lane. The shift carries the product's high bits,
// which a multiplication never spreads downwards, into the low ones before the second product.
inline std::uint64_t block_step(std::uint64_t lane, std::uint64_t word) {
  std::uint64_t x = (lane ^ word) * block_k1;
  x ^= x >> 32;
  return x * block_k2;
}

// A bijective finaliser (xor-shifts and odd multiplications): every input bit reaches every
// output bit.
inline std::uint64_t block_mix(std::uint64_t x) {
  x ^= x >> 31;
  x *= block_k1;
  x ^= x >> 29;
  x *= block_k2;
  return x ^ (x >> 32);
}

}  // namespace detail

// A 64-bit hash of `bytes` bytes, written for this project. FNV-1a takes a byte per step
// through one chain of multiplications (0.8 GB/s here); this takes 8-byte words (native byte
// order) in four independent lanes, so the processor overlaps their multiplications (12 GB/s;
// docs/performance.md, "render with the noise cache"). The length and `seed` start the lanes, the tail (under 32
// bytes) goes word by word into the lanes, a last partial word zero-padded, and the lanes are
// folded through the finaliser. Every step is a bijection in the word it takes, so changing any
// one 8-byte word of the data always changes the hash; other changes collide with probability
// about 2^-64 (not against an adversary).
inline std::uint64_t block_hash(const void* data, std::size_t bytes, std::uint64_t seed = 0) {
  using namespace detail;
  const auto* p = static_cast<const unsigned char*>(data);
  const std::uint64_t start = block_mix(seed ^ (static_cast<std::uint64_t>(bytes) * block_k2));
  std::uint64_t lane[4] = {start, start + block_k1, start + 2 * block_k1, start + 3 * block_k1};
  auto word_at = [](const unsigned char* q) {
    std::uint64_t w;
    std::memcpy(&w, q, sizeof w);  // unaligned-safe; compiles to one load
    return w;
  };
  std::size_t i = 0;
  for (; i + 32 <= bytes; i += 32) {
    lane[0] = block_step(lane[0], word_at(p + i));
    lane[1] = block_step(lane[1], word_at(p + i + 8));
    lane[2] = block_step(lane[2], word_at(p + i + 16));
    lane[3] = block_step(lane[3], word_at(p + i + 24));
  }
  for (int l = 0; i < bytes; i += 8, ++l) {
    std::uint64_t w = 0;
    std::memcpy(&w, p + i, bytes - i < 8 ? bytes - i : 8);
    lane[l] = block_step(lane[l], w);
  }
  std::uint64_t hash = start;
  for (const std::uint64_t v : lane) hash = block_mix(hash ^ v);
  return hash;
}

// A hash as 16 lowercase hex digits (cache keys and file names).
inline std::string hex_digits(std::uint64_t hash) {
  static const char digits[] = "0123456789abcdef";
  std::string text(16, '0');
  for (int k = 15; k >= 0; --k, hash >>= 4) text[static_cast<std::size_t>(k)] = digits[hash & 15u];
  return text;
}

}  // namespace nephele::core
