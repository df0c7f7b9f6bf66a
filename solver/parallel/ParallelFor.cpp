#include "parallel/ParallelFor.hpp"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstdlib>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace mcdda {
namespace {

int default_thread_count() {
    if (const char* env = std::getenv("MCDDA_THREADS")) {
        const int n = std::atoi(env);
        if (n > 0) return std::min(n, 256);
    }
    return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

std::atomic<int> requested_threads{0};  // 0: default

/// Workers 1..n−1 (the caller is range 0). A loop is a generation: the workers wake, run their
/// range and count down; the caller waits for the count to reach zero.
class Pool {
public:
    explicit Pool(int threads) {
        for (int w = 1; w < threads; ++w) workers_.emplace_back([this, w] { work(w); });
    }
    ~Pool() {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            stopping_ = true;
        }
        wake_.notify_all();
        for (std::thread& t : workers_) t.join();
    }
    int threads() const { return static_cast<int>(workers_.size()) + 1; }

    void run(int count, const std::function<void(int, int)>& body) {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            body_ = &body;
            count_ = count;
            pending_ = static_cast<int>(workers_.size());
            error_ = nullptr;
            ++generation_;
        }
        wake_.notify_all();
        run_range(0, body);
        std::unique_lock<std::mutex> lock(mutex_);
        done_.wait(lock, [this] { return pending_ == 0; });
        body_ = nullptr;
        if (error_) std::rethrow_exception(error_);
    }

private:
    std::vector<std::thread> workers_;
    std::mutex mutex_;
    std::condition_variable wake_, done_;
    const std::function<void(int, int)>* body_ = nullptr;
    int count_ = 0;
    int pending_ = 0;
    long long generation_ = 0;
    bool stopping_ = false;
    std::exception_ptr error_;

    void run_range(int index, const std::function<void(int, int)>& body) {
        const long long n = count_, t = threads();
        const int begin = static_cast<int>(n * index / t), end = static_cast<int>(n * (index + 1) / t);
        if (begin >= end) return;
        try {
            body(begin, end);
        } catch (...) {
            std::lock_guard<std::mutex> lock(mutex_);
            if (!error_) error_ = std::current_exception();
        }
    }

    void work(int index) {
        long long seen = 0;
        while (true) {
            const std::function<void(int, int)>* body;
            {
                std::unique_lock<std::mutex> lock(mutex_);
                wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
                if (stopping_) return;
                seen = generation_;
                body = body_;
            }
            run_range(index, *body);
            {
                std::lock_guard<std::mutex> lock(mutex_);
                if (--pending_ == 0) done_.notify_one();
            }
        }
    }
};

std::mutex pool_mutex;  // held while a loop runs, and while the pool is replaced
std::unique_ptr<Pool> pool;

}  // namespace

void set_thread_count(int threads) { requested_threads = std::max(0, threads); }

int thread_count() {
    const int requested = requested_threads;
    return requested > 0 ? std::min(requested, 256) : default_thread_count();
}

void parallel_for(int count, const std::function<void(int, int)>& body) {
    if (count <= 0) return;
    const int threads = thread_count();
    std::unique_lock<std::mutex> lock(pool_mutex, std::try_to_lock);
    if (threads <= 1 || count < 2 || !lock.owns_lock()) {
        body(0, count);
        return;
    }
    if (!pool || pool->threads() != threads) {
        pool.reset();
        pool = std::make_unique<Pool>(threads);
    }
    pool->run(count, body);
}

}  // namespace mcdda
