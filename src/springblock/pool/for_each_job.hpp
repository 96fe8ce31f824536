#pragma once
// A fixed list of jobs on the thread pool, as an ensemble's repetitions need it: jobs 0 .. n-1
// dealt in index order, one at a time, to whichever thread is free. The threads are kept, idle,
// for the next call asking for as many.
#include <atomic>
#include <functional>
#include <vector>

namespace sb {

// Runs every job on `threads` threads (at least 1). `job(j)` returns whether job j finished;
// false means an interrupt cut it short, which is not a result. Once `interrupt` is set or a job
// has thrown, no job starts any more and the running ones are waited for; then the exception of
// the lowest-numbered job that threw, if any, is rethrown. `every_second` (optional) is called
// from the calling thread, which runs no job, about once a second while jobs run.
// Returns, for each job, whether it finished.
std::vector<char> for_each_job(int n_jobs, int threads, const std::function<bool(int)>& job,
                               const std::atomic<bool>* interrupt, const std::function<void()>& every_second = {});

}  // namespace sb
