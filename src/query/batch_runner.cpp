#include "batch_runner.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>

#include "raylab/core/thread_count.h"

namespace raylab {

namespace {

// Items between two stop checks: about 10 ms of tracing on one core, so that Ctrl-C in Python
// is answered well within a second even on one thread.
constexpr std::size_t kWave = std::size_t{1} << 16;

}  // namespace

void run_query_batch(std::size_t count, const QueryOptions& options,
                     const std::function<void(std::size_t, std::size_t)>& work) {
  tbb::task_arena arena(usable_threads(options.threads));
  for (std::size_t wave = 0; wave < count; wave += kWave) {
    if (options.should_stop && options.should_stop()) throw QueryInterrupted();
    const std::size_t wave_end = std::min(count, wave + kWave);
    arena.execute([&] {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(wave, wave_end, kQueryChunk),
                        [&](const tbb::blocked_range<std::size_t>& r) {
                          // blocked_range splits down to at most the grain size; keep each
                          // call within one chunk anyway, as promised.
                          for (std::size_t b = r.begin(); b < r.end(); b += kQueryChunk) {
                            work(b, std::min(r.end(), b + kQueryChunk));
                          }
                        });
    });
  }
  if (options.should_stop && options.should_stop()) throw QueryInterrupted();
}

}  // namespace raylab
