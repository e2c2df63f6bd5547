// Parallel loops for the pipeline and the core's load-time work (smooth normals, PNG bands):
// task i of count runs exactly once, on some worker with a worker index in [0, workers). oneTBB
// does the scheduling; ThreadSanitizer builds use plain std::threads instead, because Debian's
// libtbb is not instrumented and TSan would report its internal hand-offs as races (our code is
// what that build is meant to check).
#pragma once

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

#ifndef FACET_SANITIZE_THREAD
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>
#endif

namespace facet {

// Runs body(task, worker) for every task in [0, count). The renderer calls it inside its
// tbb::task_arena of `workers` threads; load-time work, in the default arena with
// default_workers().
// The threads of the default arena (the cores), for load-time work.
inline int default_workers() {
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

template <class Body>
void parallel_tasks(int count, int workers, Body&& body) {
#ifndef FACET_SANITIZE_THREAD
  (void)workers;
  // One task per index (simple_partitioner, grain 1): the unit of work is what decides
  // the result, never the schedule.
  tbb::parallel_for(
      tbb::blocked_range<int>(0, count, 1),
      [&](const tbb::blocked_range<int>& range) {
        int worker = tbb::this_task_arena::current_thread_index();
        for (int i = range.begin(); i < range.end(); ++i) body(i, worker);
      },
      tbb::simple_partitioner());
#else
  std::atomic<int> next{0};
  auto run = [&](int worker) {
    for (int i = next++; i < count; i = next++) body(i, worker);
  };
  std::vector<std::thread> threads;
  for (int w = 1; w < std::min(workers, count); ++w) threads.emplace_back(run, w);
  run(0);
  for (auto& t : threads) t.join();
#endif
}

}  // namespace facet
