/// \file
/// An internal helper of the library and its command line, not part of the API.
// for_each_index: f(0) .. f(count - 1) on up to two threads (the machines this library is
// measured on have two cores), in the calling thread alone when the work is small or threads
// are not available (WebAssembly without pthreads). Indices are handed out one at a time, so a
// few large items among many small ones still spread over both threads. The first exception
// thrown by f is rethrown in the caller once every thread has stopped. The other thread's
// exact_stats() are added to the caller's (core/exact.hpp).
#pragma once

#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>

#include "momentlab/core/exact.hpp"

namespace momentlab::detail {

template <class F>
void for_each_index(std::size_t count, bool large, F f) {
#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
    large = false;
#endif
    if (!large || count < 2 || std::thread::hardware_concurrency() < 2) {
        for (std::size_t i = 0; i < count; ++i) f(i);
        return;
    }
    std::atomic<std::size_t> next{0};
    std::exception_ptr error;
    std::mutex error_mutex;
    const auto work = [&] {
        for (std::size_t i = next++; i < count; i = next++) {
            try {
                f(i);
            } catch (...) {
                const std::lock_guard<std::mutex> lock(error_mutex);
                if (!error) error = std::current_exception();
                next = count;  // the other thread stops after its current item
            }
        }
    };
    ExactStats other_stats;
    std::thread other([&] {
        work();
        other_stats = exact_stats();
    });
    work();
    other.join();
    exact_stats().filtered += other_stats.filtered;
    exact_stats().exact += other_stats.exact;
    if (error) std::rethrow_exception(error);
}

}  // namespace momentlab::detail
