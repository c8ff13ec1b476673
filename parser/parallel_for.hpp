// Runs independent work items on several threads: the project-wide passes (checking every file,
// collecting every file's calls) have no order between files.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace rung {

// Calls `work(i)` for every i in [0, count) on up to `threads` threads (0: one per core), the
// calling thread included. Items are handed out one at a time, so uneven items balance out.
// `work` must be safe to call concurrently for different items.
template <typename Work>
void parallel_for(size_t count, unsigned threads, Work&& work) {
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  threads = static_cast<unsigned>(std::min<size_t>(threads, std::max<size_t>(1, count)));
  std::atomic<size_t> next{0};
  auto run = [&]() {
    for (size_t i = next++; i < count; i = next++) work(i);
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < threads; ++t) pool.emplace_back(run);
  run();
  for (auto& thread : pool) thread.join();
}

}  // namespace rung
