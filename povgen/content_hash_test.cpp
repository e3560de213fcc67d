// The FNV-1a hash against its published values.
#include "povgen/content_hash.h"

#include <gtest/gtest.h>

namespace raintrace::povgen {
namespace {

TEST(ContentHash, IsFnv1a64) {
  // Published FNV-1a 64-bit test vectors (Fowler/Noll/Vo reference test suite).
  EXPECT_EQ(content_hash(""), "cbf29ce484222325");
  EXPECT_EQ(content_hash("a"), "af63dc4c8601ec8c");
  EXPECT_EQ(content_hash("foobar"), "85944171f73967e8");
  EXPECT_NE(content_hash("frame 1"), content_hash("frame 2"));
}

TEST(ContentHash, HashingInPiecesEqualsHashingAtOnce) {
  ContentHasher hasher;
  hasher.update("foo");
  hasher.update("");
  hasher.update("bar");
  EXPECT_EQ(hasher.hex(), "85944171f73967e8");
}

}  // namespace
}  // namespace raintrace::povgen
