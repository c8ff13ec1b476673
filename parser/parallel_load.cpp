#include "parser/parallel_load.hpp"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <thread>

namespace rung {

void load_documents_in_order(const std::vector<std::filesystem::path>& paths, unsigned threads,
                             const std::function<void(LoadedDocument&)>& consume,
                             const std::function<void(LoadedDocument&)>& prepare) {
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  threads = std::min<unsigned>(threads, static_cast<unsigned>(std::max<size_t>(1, paths.size())));

  auto load = [&](size_t i) {
    LoadedDocument item;
    item.index = i;
    item.path = paths[i];
    if (std::optional<Document> document = Document::load(paths[i], &item.error)) {
      item.document = std::make_unique<Document>(std::move(*document));
      if (prepare) prepare(item);
    }
    return item;
  };
  if (threads <= 1) {
    for (size_t i = 0; i < paths.size(); ++i) {
      LoadedDocument item = load(i);
      consume(item);
    }
    return;
  }

  // Workers may run at most `window` files ahead of the consumer, which bounds memory.
  const size_t window = size_t{threads} * 4;
  std::vector<std::optional<LoadedDocument>> slots(paths.size());
  std::mutex mutex;
  std::condition_variable ready;
  std::condition_variable room;
  size_t next_to_claim = 0;
  size_t next_to_consume = 0;

  auto worker = [&] {
    while (true) {
      size_t i;
      {
        std::unique_lock lock(mutex);
        room.wait(lock, [&] { return next_to_claim >= paths.size() || next_to_claim < next_to_consume + window; });
        if (next_to_claim >= paths.size()) return;
        i = next_to_claim++;
      }
      LoadedDocument item = load(i);
      {
        std::lock_guard lock(mutex);
        slots[i] = std::move(item);
      }
      ready.notify_all();
    }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < threads; ++t) pool.emplace_back(worker);

  for (size_t i = 0; i < paths.size(); ++i) {
    std::optional<LoadedDocument> item;
    {
      std::unique_lock lock(mutex);
      ready.wait(lock, [&] { return slots[i].has_value(); });
      item = std::move(slots[i]);
      slots[i].reset();
      next_to_consume = i + 1;
    }
    room.notify_all();
    consume(*item);
  }
  for (auto& t : pool) t.join();
}

}  // namespace rung
