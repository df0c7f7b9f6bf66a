#pragma once
/// \file ParallelFor.hpp
/// A fixed pool of worker threads for loops over elements. The ranges handed out depend only on
/// the loop length and the thread count, and callers write one result per index and reduce them
/// in index order afterwards: results are the same, bit for bit, for any number of threads.
/// Idle workers sleep on a condition variable (no spinning: on a small machine a spinning
/// worker takes a core from the solver between loops).

#include <functional>

namespace mcdda {

/// Sets the number of threads loops use, the caller's included (1: serial; 0: one per core).
void set_thread_count(int threads);

/// The number of threads loops use: set_thread_count's, else $MCDDA_THREADS, else one per core.
int thread_count();

/// Calls body(begin, end) on contiguous ranges that cover [0, count), each on one thread, and
/// returns when all are done; an exception thrown by a body is rethrown here (the first one).
/// A loop started while another runs (a second simulation on another thread) runs serially.
void parallel_for(int count, const std::function<void(int begin, int end)>& body);

}  // namespace mcdda
