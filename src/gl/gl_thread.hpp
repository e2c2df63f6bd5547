// The thread every GL call of a GlRenderer runs on. An OpenGL context is current on one thread,
// and a program may already have another window-system API's context current on its own (the
// viewer's SDL window draws with GLX): glvnd refuses to make an EGL context current there
// (EGL_BAD_ACCESS). A thread of the renderer's own meets no other context.
#pragma once

#include <condition_variable>
#include <functional>
#include <future>
#include <mutex>
#include <thread>
#include <utility>

namespace facet::gl {

class GlThread {
 public:
  GlThread() : thread_([this] { loop(); }) {}
  ~GlThread() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
    }
    wake_.notify_one();
    thread_.join();
  }
  GlThread(const GlThread&) = delete;
  GlThread& operator=(const GlThread&) = delete;

  // Runs work on the thread and waits for it: its result, or its exception rethrown here.
  template <class Work>
  auto run(Work work) -> decltype(work()) {
    std::packaged_task<decltype(work())()> task(std::move(work));
    auto result = task.get_future();
    {
      std::lock_guard<std::mutex> lock(mutex_);
      job_ = [&task] { task(); };
    }
    wake_.notify_one();
    return result.get();
  }

 private:
  void loop() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (true) {
      wake_.wait(lock, [this] { return stopping_ || job_; });
      if (job_) {
        std::function<void()> job = std::exchange(job_, nullptr);
        lock.unlock();
        job();
        lock.lock();
        continue;
      }
      return;  // stopping, nothing left to run
    }
  }

  std::mutex mutex_;
  std::condition_variable wake_;
  std::function<void()> job_;
  bool stopping_ = false;
  std::thread thread_;  // last: starts once the members above exist
};

}  // namespace facet::gl
