// The hash raintrace uses to tell files apart: 64-bit FNV-1a as 16 hex digits. Cheap, stable
// across platforms and runs, and fed piece by piece so a frame is hashed while it streams to
// disk. It detects changes, it does not resist forgery (nothing here needs that).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace raintrace::povgen {

/// 64-bit FNV-1a of bytes, as 16 lower-case hex digits.
std::string content_hash(std::string_view bytes);

/// content_hash() fed piece by piece: update("foo"); update("bar") gives content_hash("foobar").
class ContentHasher {
 public:
  void update(std::string_view bytes);
  [[nodiscard]] std::string hex() const;

 private:
  std::uint64_t m_hash = 0xcbf29ce484222325ULL;  // FNV-1a 64-bit offset basis
};

}  // namespace raintrace::povgen
