#include "bvh/build_scheduler.h"

#include <atomic>
#include <condition_variable>
#include <mutex>

#include "util/parallel.h"

namespace vkpt::internal {
namespace {

class Scheduler {
 public:
  Scheduler(unsigned threads, const Task& root, const SubdivideFn& subdivide)
      : threads_(threads), subdivide_(subdivide), shared_{root} {}

  void Run() {
    RunThreads(threads_, [&](unsigned) {
      try {
        Work();
      } catch (...) {
        Stop();
        throw;
      }
    });
  }

 private:
  void Work() {
    std::vector<Task> local;
    while (Take(local)) {
      while (!local.empty() && !stopped_) Step(local);
      std::lock_guard lock(mutex_);
      if (--busy_ == 0 && shared_.empty()) wake_.notify_all();
    }
  }

  // Waits for a shared subtree and moves it to `local`; false once the tree is done (no
  // shared subtree and no busy worker to make one) or a worker has failed.
  bool Take(std::vector<Task>& local) {
    std::unique_lock lock(mutex_);
    wake_.wait(lock, [&] { return !shared_.empty() || busy_ == 0 || stopped_; });
    if (shared_.empty() || stopped_) return false;
    local.push_back(shared_.back());
    shared_.pop_back();
    ++busy_;
    return true;
  }

  // Splits the last node of `local`; hands its right child to an idle thread if worth it.
  void Step(std::vector<Task>& local) {
    const Task task = local.back();
    local.pop_back();
    const size_t before = local.size();
    subdivide_(task, local, InnerThreads(task));
    if (threads_ == 1 || task.count < kShareNode || local.size() != before + 2) return;
    std::lock_guard lock(mutex_);
    if (threads_ - busy_ > shared_.size()) {
      shared_.push_back(local[before]);  // the right child
      local.erase(local.begin() + before);
      wake_.notify_one();
    }
  }

  unsigned InnerThreads(const Task& task) {
    if (threads_ == 1 || task.count < kParallelNode) return 1;
    std::lock_guard lock(mutex_);
    return shared_.empty() && busy_ == 1 ? threads_ : 1;
  }

  void Stop() {
    {
      std::lock_guard lock(mutex_);
      stopped_ = true;
    }
    wake_.notify_all();
  }

  const unsigned threads_;
  const SubdivideFn& subdivide_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::vector<Task> shared_;
  unsigned busy_ = 0;  // workers holding a subtree
  std::atomic<bool> stopped_{false};  // a worker failed: all stop
};

}  // namespace

unsigned BuildThreads(uint32_t n, unsigned requested) {
  if (n < kShareNode) return 1;
  return ThreadCount(requested);
}

void BuildSubtrees(unsigned threads, const Task& root, const SubdivideFn& subdivide) {
  Scheduler(threads, root, subdivide).Run();
}

}  // namespace vkpt::internal
