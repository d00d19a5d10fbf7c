// A parallel loop over independent items, on the thread_pool library.
#pragma once

#include <algorithm>
#include <cstddef>
#include <exception>
#include <future>
#include <thread_pool/thread_pool.hpp>
#include <vector>

namespace pd {

/// Calls fn(0) … fn(n − 1) on up to `threads` threads (in this thread when
/// `threads` <= 1) and returns when every call has ended and every thread is
/// joined: the work queue forks after the parallel stages, and fork is only
/// safe in a process with one thread. If calls throw, the exception of the
/// lowest index is rethrown, as a serial loop would have thrown it.
template <class Fn>
void parallel_for(std::size_t n, int threads, Fn&& fn) {
  if (threads <= 1 || n < 2) {
    for (std::size_t k = 0; k < n; ++k) fn(k);
    return;
  }
  std::vector<std::exception_ptr> failed(n);
  {
    thread_pool::ThreadPool pool(std::min<std::size_t>(threads, n));
    std::vector<std::future<void>> pending;
    pending.reserve(n);
    for (std::size_t k = 0; k < n; ++k)
      pending.push_back(pool.Submit([&fn, &failed, k] {
        try {
          fn(k);
        } catch (...) {
          failed[k] = std::current_exception();
        }
      }));
    for (auto& f : pending) f.get();
  }  // the pool's destructor joins its threads
  for (const auto& e : failed)
    if (e) std::rethrow_exception(e);
}

}  // namespace pd
