// worker_pool.cpp — a fixed pool of threads that share the jobs of one Run at a time.
#include "worker_pool.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <exception>

namespace softgl::detail {

namespace {

// How long a thread watches for what it waits for before it sleeps (worker_pool.h).
constexpr auto kSpin = std::chrono::microseconds(50);

// A hint to the core that this thread is spinning.
inline void CpuRelax() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#elif defined(__aarch64__)
  asm volatile("yield");
#endif
}

// Whether ready() became true within about kSpin, checked between pauses.
template <class Ready>
bool SpinUntil(Ready&& ready) {
  const auto until = std::chrono::steady_clock::now() + kSpin;
  for (int i = 1;; ++i) {
    if (ready()) return true;
    CpuRelax();
    if (i % 64 == 0 && std::chrono::steady_clock::now() >= until) return ready();
  }
}

}  // namespace

int DefaultThreadCount() {
  if (const char* env = std::getenv("SOFTGL_THREADS")) {
    char* end = nullptr;
    const long n = std::strtol(env, &end, 10);
    if (end != env && *end == '\0' && n >= 1 && n <= 256) return int(n);
  }
  return int(std::max(1u, std::thread::hardware_concurrency()));
}

WorkerPool::WorkerPool(int threads) : threads_(std::clamp(threads, 1, 256)) {
  workers_.reserve(std::size_t(threads_ - 1));
  try {
    for (int w = 1; w < threads_; ++w) workers_.emplace_back([this, w] { Work(w); });
  } catch (...) {  // fewer threads than asked for (the system refused more): run with those there are
    threads_ = int(workers_.size()) + 1;
  }
  // Returns once every worker is waiting for work: from then on the workers run only inside Run, so a caller
  // that forks between Runs (Model::Load's bounded import) never forks while one of them is starting up inside
  // the allocator, which AddressSanitizer's allocator does not survive in the child.
  std::unique_lock<std::mutex> lock(mutex_);
  done_.wait(lock, [this] { return waiting_ == int(workers_.size()); });
}

WorkerPool::~WorkerPool() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  for (std::thread& t : workers_) t.join();
}

void WorkerPool::Drain(int worker) {
  for (int job = next_.fetch_add(1); job < jobs_; job = next_.fetch_add(1)) {
    if (failed_.load(std::memory_order_relaxed)) continue;
    try {
      fn_(job, worker);
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex_);
      if (!error_) error_ = std::current_exception();
      failed_ = true;
    }
  }
}

void WorkerPool::Work(int worker) {
  std::uint64_t seen = 0;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    ++waiting_;
  }
  done_.notify_all();
  for (;;) {
    SpinUntil([&] { return generation_.load(std::memory_order_acquire) != seen; });  // (stop_ is seen below)
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
      if (stop_) return;
      seen = generation_;
    }
    Drain(worker);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (--busy_ == 0) done_.notify_one();
    }
  }
}

void WorkerPool::Run(int jobs, JobFn fn) {
  if (jobs <= 0) return;
  if (jobs == 1) return fn(0, 0);  // one job: the caller's, without waking anyone
  fn_ = fn;
  jobs_ = jobs;
  next_ = 0;
  failed_ = false;
  error_ = nullptr;
  const bool spread = !workers_.empty() && jobs > 1;
  if (spread) {
    std::lock_guard<std::mutex> lock(mutex_);
    busy_ = int(workers_.size());
    ++generation_;
  }
  if (spread) wake_.notify_all();
  Drain(0);
  if (spread && !SpinUntil([&] { return busy_.load(std::memory_order_acquire) == 0; })) {
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [&] { return busy_ == 0; });
  }
  fn_ = JobFn();
  if (error_) std::rethrow_exception(error_);
}

}  // namespace softgl::detail
