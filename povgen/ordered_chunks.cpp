// ordered_chunks(): chunks are claimed from one counter, and a turn counter lets each chunk's
// commit run only after the previous chunk's. No rounds and no barrier: a thread that finished
// filling waits only for the chunk before its own, and the sink work in commit overlaps with
// the other threads' fills.
#include "povgen/ordered_chunks.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace raintrace::povgen {

void ordered_chunks(std::size_t chunks, int threads, const ChunkStep& fill, const ChunkStep& commit,
                    const ChunkStep& finish) {
  const auto workers = std::min(static_cast<std::size_t>(std::clamp(threads, 1, 64)), chunks);
  if (workers <= 1) {
    for (std::size_t c = 0; c < chunks; ++c) {
      fill(c, 0);
      commit(c, 0);
      if (finish) finish(c, 0);
    }
    return;
  }
  std::atomic<std::size_t> next{0};  // the next chunk to claim
  std::atomic<std::size_t> turn{0};  // the chunk whose commit may run now
  std::atomic<bool> failed{false};
  std::exception_ptr error;  // written only by the thread whose turn it is
  std::mutex finish_error_mutex;
  std::exception_ptr finish_error;  // from finish(), which runs outside the turns
  auto run = [&](std::size_t worker) {
    for (std::size_t c = next.fetch_add(1); c < chunks; c = next.fetch_add(1)) {
      std::exception_ptr mine;
      if (!failed.load(std::memory_order_relaxed)) {
        try {
          fill(c, worker);
        } catch (...) {
          mine = std::current_exception();
        }
      }
      // Every chunk takes its turn, failed or not, so no later thread waits forever.
      for (std::size_t t = turn.load(std::memory_order_acquire); t != c;
           t = turn.load(std::memory_order_acquire)) {
        turn.wait(t, std::memory_order_acquire);
      }
      if (!mine && !failed.load(std::memory_order_relaxed)) {
        try {
          commit(c, worker);
        } catch (...) {
          mine = std::current_exception();
        }
      }
      const bool committed = !mine && !failed.load(std::memory_order_relaxed);
      if (mine && !error) {
        error = mine;
        failed.store(true, std::memory_order_relaxed);
      }
      turn.store(c + 1, std::memory_order_release);
      turn.notify_all();
      if (committed && finish) {
        try {
          finish(c, worker);
        } catch (...) {
          // Outside the turns there is no chunk order to keep: the first one seen wins.
          failed.store(true, std::memory_order_relaxed);
          std::lock_guard lock(finish_error_mutex);
          if (!finish_error) finish_error = std::current_exception();
        }
      }
    }
  };
  {
    // jthreads join when they go out of scope, also if starting one of them throws.
    std::vector<std::jthread> pool;
    pool.reserve(workers - 1);
    for (std::size_t w = 1; w < workers; ++w) pool.emplace_back(run, w);
    run(0);
  }
  if (error) std::rethrow_exception(error);
  if (finish_error) std::rethrow_exception(finish_error);
}

}  // namespace raintrace::povgen
