// FNV-1a, 64 bit (Fowler, Noll, Vo): xor each byte in, multiply by the FNV prime.
#include "povgen/content_hash.h"

#include <cstdio>

namespace raintrace::povgen {

void ContentHasher::update(std::string_view bytes) {
  std::uint64_t hash = m_hash;
  for (unsigned char c : bytes) {
    hash ^= c;
    hash *= 0x100000001b3ULL;  // FNV-1a 64-bit prime
  }
  m_hash = hash;
}

std::string ContentHasher::hex() const {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(m_hash));
  return text;
}

std::string content_hash(std::string_view bytes) {
  ContentHasher hasher;
  hasher.update(bytes);
  return hasher.hex();
}

}  // namespace raintrace::povgen
