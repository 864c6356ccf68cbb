// worker_pool.h — the fixed set of threads that run the parallel parts of the pipeline (vertex shading, primitive
// processing and binning in batches, then one screen tile per job).
//
// Run(jobs, fn) calls fn(job, worker) once for every job in [0, jobs), on the calling thread (worker 0) and the
// pool's threads (workers 1 .. Threads()-1), and returns when all have finished. Jobs are handed out in order but
// run concurrently, so fn must write only what its job owns; `worker` indexes per-thread scratch memory.
//
// A draw runs the pool a few times in a row (vertex shading, then binning, piece after piece), so a thread that
// has finished its part spins for a short while (kSpin) watching for the next run, or for the others to finish,
// before it sleeps: a sleeping thread costs a system call to wake, and on a virtual machine tens of microseconds.
#pragma once

#include <atomic>
#include <condition_variable>
#include <type_traits>
#include <mutex>
#include <thread>
#include <vector>

namespace softgl::detail {

/// The thread count a context uses when none is asked for: SOFTGL_THREADS from the environment when it holds a
/// number from 1 to 256, else the number of hardware threads (at least 1).
int DefaultThreadCount();

/// A reference to a callable fn(job, worker), which must outlive it: what Run takes. Unlike std::function it
/// never allocates (a draw runs two pools' worth of jobs, and small draws are many).
class JobFn {
 public:
  JobFn() = default;
  template <class F>
    requires(!std::is_same_v<std::remove_cvref_t<F>, JobFn>)
  JobFn(F&& fn)  // implicit, as std::function is: Run(jobs, [&](int job, int worker) { ... })
      : object_(const_cast<void*>(static_cast<const void*>(&fn))),
        call_([](void* object, int job, int worker) { (*static_cast<std::remove_reference_t<F>*>(object))(job, worker); }) {}
  void operator()(int job, int worker) const { call_(object_, job, worker); }

 private:
  void* object_ = nullptr;
  void (*call_)(void*, int, int) = nullptr;
};

class WorkerPool {
 public:
  /// A pool of `threads` threads in all, the calling thread included (clamped to 1 .. 256).
  explicit WorkerPool(int threads);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  int Threads() const { return threads_; }

  /// Runs fn(job, worker) for every job; an exception thrown by fn is caught and rethrown here (the first one)
  /// after every job has finished or been skipped.
  void Run(int jobs, JobFn fn);

 private:
  void Work(int worker);
  void Drain(int worker);

  int threads_ = 1;
  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  std::atomic<std::uint64_t> generation_{0};  // (written under mutex_; read while spinning too)
  bool stop_ = false;
  std::atomic<int> busy_{0};  // workers still inside the current generation (written under mutex_)
  int waiting_ = 0;  // workers that have started (the constructor waits for all of them)
  // The current run.
  JobFn fn_;
  int jobs_ = 0;
  std::atomic<int> next_{0};
  std::atomic<bool> failed_{false};
  std::exception_ptr error_;
};

}  // namespace softgl::detail
