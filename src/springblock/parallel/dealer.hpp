#pragma once
// The coordinator's side of a scheduler: the queue of units not yet handed out, who holds which
// unit, the hooks. One thread uses it (the coordinator's calling thread).
#include <chrono>
#include <deque>
#include <map>
#include <optional>

#include "springblock/parallel/scheduler.hpp"
#include "springblock/pool/thread_pool.hpp"

namespace sb::parallel {

// A rank's threads: the thread pool of the core library (pool/), each job a unit returning its
// record (null when interrupted). The calling thread hands out units and collects their records;
// under MPI it is also the only thread that talks to other ranks.
using UnitPool = ThreadPool<nlohmann::json>;

class Dealer {
 public:
  Dealer(const std::vector<int>& ids, const Hooks& hooks, const std::atomic<bool>* interrupt);

  // The next unit for `rank`, or nothing when none is left or the run is interrupted.
  std::optional<int> next(int rank);
  // The next `count` units (fewer when fewer are left; none when interrupted) for `rank`, from
  // the front of the queue, so the dearest still go first; logged as one assignment.
  std::vector<int> next_batch(int rank, int count);
  // A unit's result came back; a null record (cut short by an interrupt) stays unfinished. A
  // record from a rank that no longer holds the unit (it was dealt again after that rank was taken
  // for dead, and may be done already) is dropped, so no unit is counted twice: returns whether it
  // was taken.
  bool finished(int id, int rank, nlohmann::json record);
  // A worker gave a unit back unrun (it was interrupted): another rank will run it.
  void give_back(int id);
  // Every unit `rank` holds goes back to the front of the queue (that rank was taken for dead);
  // returns them, in increasing order.
  std::vector<int> reclaim(int rank);
  bool interrupted() const { return interrupt_ && interrupt_->load(); }
  bool queue_empty() const { return queue_.empty(); }
  int in_flight() const { return static_cast<int>(holder_.size()); }
  int queued() const { return static_cast<int>(queue_.size()); }
  void tick();  // calls hooks.tick at most every 0.2 s
  void settle() const {  // calls hooks.settled
    if (hooks_.settled) hooks_.settled();
  }
  Outcome outcome() const;
  std::vector<std::string> notes;

 private:
  std::deque<int> queue_;
  std::map<int, int> holder_;  // unit -> rank running it
  const Hooks& hooks_;
  const std::atomic<bool>* interrupt_;
  std::chrono::steady_clock::time_point last_tick_{};
};

// One round of the coordinator's own threads: fills free threads from the dealer, then waits at
// most `wait` for a finished unit and hands it to the dealer. Rethrows a unit's exception.
void serve_pool(UnitPool& pool, Dealer& dealer, int rank, std::chrono::milliseconds wait);

}  // namespace sb::parallel
