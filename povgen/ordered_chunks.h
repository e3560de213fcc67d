// Work cut into chunks that threads fill in parallel and hand on strictly in chunk order: the
// one pattern behind both the frame values and the frame text, whose bytes must never depend
// on the thread count.
#pragma once

#include <cstddef>
#include <functional>

namespace raintrace::povgen {

/// fill(chunk, worker) / commit(chunk, worker): `worker` in [0, threads) names the thread's
/// own scratch (buffers, vectors) that fill writes and commit reads.
using ChunkStep = std::function<void(std::size_t chunk, std::size_t worker)>;

/// Runs fill(c, w) for every chunk c in [0, chunks) on up to `threads` threads (the calling
/// thread is one of them; values below 1 count as 1), each fill followed by commit(c, w) on
/// the same thread with the same worker index. Fills run in parallel; commits run one at a
/// time in ascending chunk order, and each sees everything earlier commits wrote. A worker
/// starts its next chunk only after committing the last, so its scratch is never
/// overwritten before it is used. If `finish` is given, finish(c, w) runs right after
/// commit(c, w) on the same thread but outside the turn, in parallel with other chunks: the
/// place for work that needs what commit decided (an offset) but not the order. Threads live
/// for this call only: one start per call, not per chunk. If a step throws, later chunks are
/// skipped and, once all threads have stopped, the first exception from a fill or commit in
/// chunk order is rethrown (else the first one from a finish).
void ordered_chunks(std::size_t chunks, int threads, const ChunkStep& fill, const ChunkStep& commit,
                    const ChunkStep& finish = {});

}  // namespace raintrace::povgen
