// ordered_chunks(): commits in chunk order whatever the thread count, every chunk exactly
// once, worker scratch never clobbered, and the first failure in chunk order rethrown.
#include "povgen/ordered_chunks.h"

#include <gtest/gtest.h>
#include <stdexcept>
#include <string>
#include <vector>

namespace raintrace::povgen {
namespace {

/// Chunk c's text is "<c>"; workers' scratch holds it between fill and commit.
std::string joined(std::size_t chunks, int threads) {
  std::vector<std::string> scratch(static_cast<std::size_t>(std::max(threads, 1)));
  std::string out;
  ordered_chunks(
      chunks, threads,
      [&](std::size_t c, std::size_t w) { scratch[w] = "<" + std::to_string(c) + ">"; },
      [&](std::size_t, std::size_t w) { out += scratch[w]; });
  return out;
}

TEST(OrderedChunks, CommitsInChunkOrderWhateverTheThreadCount) {
  std::string expected;
  for (std::size_t c = 0; c < 500; ++c) expected += "<" + std::to_string(c) + ">";
  for (const int threads : {0, 1, 2, 3, 8}) {
    EXPECT_EQ(joined(500, threads), expected) << threads << " threads";
  }
}

TEST(OrderedChunks, FinishSeesWhatCommitDecided) {
  // commit hands out offsets in chunk order; finish writes chunk c's c+1 values there, in
  // parallel: the result is the sequence 0, 1, 1, 2, 2, 2, ... whatever the thread count.
  for (const int threads : {1, 2, 3}) {
    const std::size_t chunks = 60;
    std::vector<std::size_t> out(chunks * (chunks + 1) / 2);
    std::vector<std::size_t> offset(static_cast<std::size_t>(threads));
    std::size_t next = 0;
    ordered_chunks(
        chunks, threads, [](std::size_t, std::size_t) {},
        [&](std::size_t c, std::size_t w) {
          offset[w] = next;
          next += c + 1;
        },
        [&](std::size_t c, std::size_t w) {
          for (std::size_t i = 0; i <= c; ++i) out[offset[w] + i] = c;
        });
    std::size_t i = 0;
    for (std::size_t c = 0; c < chunks; ++c) {
      for (std::size_t k = 0; k <= c; ++k, ++i) ASSERT_EQ(out[i], c) << threads << " threads";
    }
  }
}

TEST(OrderedChunks, NoChunksRunsNothing) {
  EXPECT_EQ(joined(0, 4), "");
  EXPECT_EQ(joined(1, 4), "<0>");
}

TEST(OrderedChunks, FirstFailureInChunkOrderIsRethrown) {
  for (const int threads : {1, 2, 3}) {
    std::size_t committed = 0;
    auto fill = [](std::size_t c, std::size_t) {
      if (c == 37 || c == 80) throw std::runtime_error("chunk " + std::to_string(c));
    };
    try {
      ordered_chunks(200, threads, fill, [&](std::size_t, std::size_t) { ++committed; });
      ADD_FAILURE() << "no exception";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), "chunk 37");
    }
    EXPECT_EQ(committed, 37u) << "chunks before the failure are committed, none after";
  }
}

}  // namespace
}  // namespace raintrace::povgen
