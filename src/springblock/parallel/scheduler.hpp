#pragma once
// Who runs which work unit. A scheduler hands units to threads (ThreadScheduler: one process)
// or to ranks and their threads (the MPI scheduler, mpi/, built with SPRINGBLOCK_MPI), dealing
// them out from a queue on the coordinator (rank 0) as workers free up (one at a time to its own
// threads, in batches sized by their measured cost to other ranks), so units whose run times
// differ 100x leave nobody idle. Results come back to the coordinator, which
// alone calls the hooks (checkpoint, progress): in finish order, which is why a result must
// never depend on it.
#include <atomic>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace sb::parallel {

// Runs unit `id` and returns its record, or null when `interrupt` cut it short.
using UnitRunner = std::function<nlohmann::json(int id, const std::atomic<bool>* interrupt)>;

struct Hooks {
  std::function<void(const std::vector<int>& ids, int rank)> assigned;     // units handed out together
  std::function<void(int id, int rank, nlohmann::json record)> finished;  // its record is in
  std::function<void()> tick;                                              // about 5 times a second
  // What one message (or one of the coordinator's own threads) brought is in: the place to write
  // out together what the calls above held.
  std::function<void()> settled;
};

struct InFlight {
  int id = 0;
  int rank = 0;
};

struct Outcome {
  bool interrupted = false;
  std::vector<InFlight> unfinished;  // handed out but not finished when the run stopped
  std::vector<std::string> notes;    // e.g. a worker rank that was interrupted and gave back its units
  std::vector<int> lost_ranks;      // worker ranks taken for dead (their units were dealt again)
  // The coordinator's cost of talking to workers (the rank-0 bottleneck of the README's model):
  // messages received from workers and the seconds spent receiving, decoding and answering
  // them (the hooks, e.g. checkpoint writes, not included: their owner times them).
  long messages = 0;
  double message_s = 0;
};

class Scheduler {
 public:
  virtual ~Scheduler() = default;
  virtual int rank() const = 0;
  virtual int ranks() const = 0;
  virtual int threads() const = 0;  // per rank
  bool coordinator() const { return rank() == 0; }
  // The coordinator's verdict, given to every rank: whether to go on (false when the
  // coordinator refused its input; the others then stop too).
  virtual bool agree(bool coordinator_ok) = 0;
  // The coordinator's `text`, given to every rank (what the others pass is ignored).
  virtual std::string share(const std::string& text) = 0;
  // Runs `ids` (only the coordinator's list counts; workers are sent units). Hooks are called on
  // the coordinator only, from the calling thread. Rethrows a unit's exception.
  virtual Outcome run(const std::vector<int>& ids, const UnitRunner& run_unit, const Hooks& hooks,
                      const std::atomic<bool>* interrupt) = 0;
  // Ends every rank now (the coordinator was interrupted: the checkpoint already holds every
  // finished unit). Returns only without MPI.
  virtual void abort(int code) { (void)code; }
};

// One process, `threads` threads (0 = all cores, as for a scene: resolve_threads).
std::unique_ptr<Scheduler> make_thread_scheduler(int threads);

}  // namespace sb::parallel
