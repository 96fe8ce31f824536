// Without MPI (or without mpirun): every unit on this process's threads, dealt from the same
// queue as under MPI, so the two differ only in where a unit runs.
#include "springblock/parallel/dealer.hpp"

namespace sb::parallel {
namespace {

class ThreadScheduler : public Scheduler {
 public:
  explicit ThreadScheduler(int threads) : threads_(resolve_threads(threads)) {}
  int rank() const override { return 0; }
  int ranks() const override { return 1; }
  int threads() const override { return threads_; }
  bool agree(bool ok) override { return ok; }
  std::string share(const std::string& text) override { return text; }

  Outcome run(const std::vector<int>& ids, const UnitRunner& run_unit, const Hooks& hooks,
              const std::atomic<bool>* interrupt) override {
    Dealer dealer(ids, hooks, interrupt);
    UnitPool pool(threads_, [&](int id) { return run_unit(id, interrupt); });
    while (!(dealer.queue_empty() || dealer.interrupted()) || pool.busy() > 0) {
      serve_pool(pool, dealer, 0, std::chrono::milliseconds(100));
      dealer.tick();
    }
    return dealer.outcome();
  }

 private:
  int threads_;
};

}  // namespace

std::unique_ptr<Scheduler> make_thread_scheduler(int threads) { return std::make_unique<ThreadScheduler>(threads); }

}  // namespace sb::parallel
