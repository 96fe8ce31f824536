#include "springblock/parallel/mpi/mpi_scheduler.hpp"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <map>
#include <exception>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>

#include "springblock/parallel/dealer.hpp"
#include "springblock/parallel/liveness.hpp"
#include "springblock/parallel/mpi/outbox.hpp"

namespace sb::parallel {
namespace {

// A request is MessagePack, not JSON text: a batch's record texts are carried as they are (JSON
// text would escape every quote in them and rank 0 would unescape it), and its numbers as binary
// doubles, exactly.
constexpr int kRequestTag = 1;  // worker -> 0: {done, returned, want, idle, stop | error}
constexpr int kAssignTag = 2;   // 0 -> worker: unit ids, none when it has nothing for that rank now
constexpr int kBeatTag = 3;     // worker -> 0: nothing, "still here" while its threads run
// The answer to a rank taken for dead that speaks again: it stops (its units went elsewhere).
constexpr int kTakenForDead = -1;

double now_s() { return MPI_Wtime(); }

// After a rank was lost, MPI_Finalize may wait for it for ever (Open MPI 4.1 with
// --enable-recovery: its closing fence hung in about one run in three here). So the job is ended
// at exit instead, once the output is out: MPI_Abort stops the ranks still in MPI, and mpirun
// then exits (status 0 under --enable-recovery, which ignores the ranks' exit codes anyway).
extern "C" void end_job_after_lost_rank() {
  std::fflush(nullptr);
  std::fprintf(stderr, "springblock: the job lost a rank, so it ends with MPI_Abort rather than a shutdown that "
                       "would wait for that rank; the results are complete\n");
  std::fflush(stderr);
  MPI_Abort(MPI_COMM_WORLD, 0);
}

class MpiScheduler : public Scheduler {
 public:
  MpiScheduler(int threads, double batch_s, double silence_s) : batch_s_(batch_s), silence_s_(silence_s) {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    if (provided < MPI_THREAD_FUNNELED) throw std::runtime_error("MPI does not support MPI_THREAD_FUNNELED");
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &ranks_);
    // A send to a dead rank may fail rather than end this process: the coordinator then takes
    // that rank for dead.
    MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
    threads_ = threads > 0 || std::getenv("OMP_NUM_THREADS") ? resolve_threads(threads) : share_of_node();
  }
  // Every rank gets here: run() aborts the job itself when one of them fails inside it.
  ~MpiScheduler() override {
    if (lost_.empty())
      MPI_Finalize();
    else
      std::atexit(end_job_after_lost_rank);  // after the caller's output (the ensemble is printed later)
  }
  // "All cores" for one of several ranks on a machine: its share of them (at least one), so that
  // mpirun -np 4 on 4 cores runs 4 threads in all, not 16. The numbers do not depend on it.
  static int share_of_node() {
    MPI_Comm node;
    MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
    int local = 1;
    MPI_Comm_size(node, &local);
    MPI_Comm_free(&node);
    return std::max(1, resolve_threads(0) / std::max(1, local));
  }
  int rank() const override { return rank_; }
  int ranks() const override { return ranks_; }
  int threads() const override { return threads_; }

  bool agree(bool ok) override {
    int v = ok ? 1 : 0;
    MPI_Bcast(&v, 1, MPI_INT, 0, MPI_COMM_WORLD);
    return v != 0;
  }

  std::string share(const std::string& text) override {
    unsigned long long n = text.size();
    MPI_Bcast(&n, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
    std::string out = rank_ == 0 ? text : std::string(n, '\0');
    // In pieces: a count is an int.
    constexpr unsigned long long kPiece = 1ULL << 30;
    for (unsigned long long at = 0; at < n; at += kPiece)
      MPI_Bcast(out.data() + at, static_cast<int>(std::min(kPiece, n - at)), MPI_CHAR, 0, MPI_COMM_WORLD);
    return out;
  }

  void abort(int code) override { MPI_Abort(MPI_COMM_WORLD, code); }

  Outcome run(const std::vector<int>& ids, const UnitRunner& run_unit, const Hooks& hooks,
              const std::atomic<bool>* interrupt) override {
    // Rank 0 learns how many threads each rank has: the batches' fair share is per thread.
    std::vector<int> slots(ranks_, 0);
    MPI_Gather(&threads_, 1, MPI_INT, slots.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
    try {
      if (rank_ != 0) {
        work(run_unit, interrupt);
        return {};
      }
      return coordinate(ids, run_unit, hooks, interrupt, std::accumulate(slots.begin(), slots.end(), 0));
    } catch (const std::exception& e) {
      // The other ranks wait on this one: say why here, then end them all.
      std::fprintf(stderr, "springblock: rank %d: error: %s\n", rank_, e.what());
      std::fflush(stderr);
      MPI_Abort(MPI_COMM_WORLD, 1);
      throw;
    }
  }

 private:
  Outcome coordinate(const std::vector<int>& ids, const UnitRunner& run_unit, const Hooks& hooks,
                     const std::atomic<bool>* interrupt, int all_slots);
  // Answers one waiting worker request (false if none): takes in the records and given-back
  // units it carries and sends the next batch; an empty answer to a worker that said it is idle
  // retires that rank (--open_ranks).
  bool answer_one(Dealer& dealer, int& open_ranks, int all_slots, Liveness& live);
  // Heartbeats received: their ranks are heard.
  void take_beats(Liveness& live);
  // `rank` is taken for dead: its units go back to the queue, its answers are abandoned.
  void bury(int rank, Dealer& dealer, int& open_ranks, Liveness& live);
  void work(const UnitRunner& run_unit, const std::atomic<bool>* interrupt);
  std::vector<int> ask(const nlohmann::json& message);
  // How many units to ask for: enough to keep this rank's threads busy about batch_s_, from the
  // running mean of its units' wall time; one while none is measured or batching is off.
  int batch_size(double unit_s) const;

  int rank_ = 0, ranks_ = 1, threads_ = 1;
  double batch_s_ = 0, silence_s_ = 10;
  double last_sent_ = 0;  // a worker's last message to rank 0
  std::vector<int> lost_;  // ranks taken for dead
  Outbox outbox_;  // lives until MPI_Finalize: abandoned sends may still read their buffers
  long messages_ = 0;
  double message_s_ = 0;
};

Outcome MpiScheduler::coordinate(const std::vector<int>& ids, const UnitRunner& run_unit, const Hooks& hooks,
                                 const std::atomic<bool>* interrupt, int all_slots) {
  Dealer dealer(ids, hooks, interrupt);
  UnitPool pool(threads_, [&](int id) { return run_unit(id, interrupt); });
  int open_ranks = ranks_ - 1;  // worker ranks not yet retired nor taken for dead
  Liveness live(ranks_, silence_s_, now_s());
  for (;;) {
    if (dealer.interrupted() && pool.busy() == 0) break;  // the caller aborts the workers
    if (!dealer.interrupted() && dealer.queue_empty() && pool.busy() == 0 && open_ranks == 0) break;
    // Short waits while workers may be asking: a request is answered within about a millisecond.
    serve_pool(pool, dealer, 0, std::chrono::milliseconds(open_ranks > 0 ? 1 : 100));
    bool answered = false;
    // Ranks taken for dead are still heard while rank 0 deals: one that was only stalled is told to stop.
    while ((open_ranks > 0 || !lost_.empty()) && !dealer.interrupted() && answer_one(dealer, open_ranks, all_slots, live))
      answered = true;
    take_beats(live);
    for (int r : live.newly_dead(now_s())) bury(r, dealer, open_ranks, live);
    outbox_.reap();
    // With no unit left to run itself, rank 0 would spin on MPI_Iprobe and take a core from the
    // workers finishing the last units: a short nap instead (it bounds the answer's delay). Not
    // while units remain: its pool is empty for a moment after each of its own units.
    if (!answered && pool.busy() == 0 && (dealer.queue_empty() || dealer.interrupted()))
      std::this_thread::sleep_for(std::chrono::microseconds(500));
    dealer.tick();
  }
  if (!dealer.interrupted()) outbox_.drain();  // the retired ranks' last answers
  Outcome o = dealer.outcome();
  o.lost_ranks = lost_;
  o.messages = messages_;
  o.message_s = message_s_;
  return o;
}

void MpiScheduler::take_beats(Liveness& live) {
  for (;;) {
    int flag = 0;
    MPI_Status st;
    MPI_Iprobe(MPI_ANY_SOURCE, kBeatTag, MPI_COMM_WORLD, &flag, &st);
    if (!flag) return;
    MPI_Recv(nullptr, 0, MPI_BYTE, st.MPI_SOURCE, kBeatTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    live.heard(st.MPI_SOURCE, now_s());
  }
}

void MpiScheduler::bury(int rank, Dealer& dealer, int& open_ranks, Liveness& live) {
  const double silent = live.silent_for(rank, now_s());
  live.mark_dead(rank);
  lost_.push_back(rank);
  outbox_.abandon(rank);
  const auto ids = dealer.reclaim(rank);
  --open_ranks;
  std::string list;
  for (int id : ids) list += (list.empty() ? "" : ", ") + std::to_string(id);
  char text[160];
  std::snprintf(text, sizeof text, "rank %d stopped answering: silent %.1f s (limit %.1f s), taken for dead; ", rank,
                silent, silence_s_);
  // Said now, not with the notes at the end: when it was noticed is part of the message.
  std::fprintf(stderr, "springblock: %s%s\n", text,
               (ids.empty() ? std::string("it held no unit") : "its unit(s) " + list + " were dealt again").c_str());
  std::fflush(stderr);
}

bool MpiScheduler::answer_one(Dealer& dealer, int& open_ranks, int all_slots, Liveness& live) {
  const double t0 = now_s();
  int flag = 0;
  MPI_Status st;
  MPI_Iprobe(MPI_ANY_SOURCE, kRequestTag, MPI_COMM_WORLD, &flag, &st);
  if (!flag) return false;
  int n = 0;
  MPI_Get_count(&st, MPI_BYTE, &n);
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(n));
  const int src = st.MPI_SOURCE;
  MPI_Recv(bytes.data(), n, MPI_BYTE, src, kRequestTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  live.heard(src, now_s());
  if (live.dead(src)) {  // back from the dead: its units went elsewhere, nothing it brings counts
    outbox_.send({kTakenForDead}, src, kAssignTag, MPI_COMM_WORLD);
    return true;
  }
  auto msg = nlohmann::json::from_msgpack(bytes);
  message_s_ += now_s() - t0;  // receiving and decoding; the hooks (checkpoint) are timed by their owner
  if (msg.contains("error"))
    throw std::runtime_error("rank " + std::to_string(src) + ": " + msg.at("error").get<std::string>());
  if (auto done = msg.find("done"); done != msg.end())  // found, not value(): no copy of the batch
    for (auto& d : *done) dealer.finished(d.at("id").get<int>(), src, std::move(d.at("record")));
  for (const auto& id : msg.value("returned", nlohmann::json::array())) {
    dealer.give_back(id.get<int>());
    dealer.notes.push_back("rank " + std::to_string(src) + " was interrupted and gave back unit " +
                           std::to_string(id.get<int>()) + " (run elsewhere)");
  }
  std::vector<int> ids;
  const int want = msg.value("want", 0);
  if (want > 0 && !msg.value("stop", false)) {
    // At most half a fair share of what is left per thread, so the last batches are small and
    // no rank is left holding many units while the others idle.
    const int fair = std::max(1, dealer.queued() / (2 * all_slots));
    ids = dealer.next_batch(src, std::min(want, fair));
  }
  dealer.settle();  // the records and the new assignment in one write, before the answer goes
  const double t1 = now_s();
  const bool retire = ids.empty() && msg.value("idle", false);
  if (!outbox_.send(std::move(ids), src, kAssignTag, MPI_COMM_WORLD)) {
    bury(src, dealer, open_ranks, live);  // unreachable
  } else if (retire) {
    --open_ranks;
    live.forget(src);
  }
  ++messages_;
  message_s_ += now_s() - t1;
  return true;
}

std::vector<int> MpiScheduler::ask(const nlohmann::json& message) {
  const auto bytes = nlohmann::json::to_msgpack(message);
  last_sent_ = now_s();
  MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, 0, kRequestTag, MPI_COMM_WORLD);
  MPI_Status st;
  MPI_Probe(0, kAssignTag, MPI_COMM_WORLD, &st);
  int n = 0;
  MPI_Get_count(&st, MPI_INT, &n);
  std::vector<int> ids(static_cast<std::size_t>(n));
  MPI_Recv(ids.data(), n, MPI_INT, 0, kAssignTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return ids;
}

int MpiScheduler::batch_size(double unit_s) const {
  if (batch_s_ <= 0 || unit_s <= 0) return 1;
  return static_cast<int>(std::clamp(std::llround(threads_ * batch_s_ / unit_s), 1LL, 100000LL));
}

// A worker: asks for a batch when its queue is empty and a thread is free, sending with it the
// records finished since its last request; once rank 0 has nothing more for it (or it is
// interrupted: the units not finished go back) it sends what is left as it comes in, and stops
// after rank 0 has answered a request that said it is idle.
void MpiScheduler::work(const UnitRunner& run_unit, const std::atomic<bool>* interrupt) {
  UnitPool pool(threads_, [&](int id) { return run_unit(id, interrupt); });
  std::deque<int> todo;
  std::map<int, double> started;  // unit -> when it was handed to a thread
  double unit_s = 0;              // running mean of this rank's unit wall time
  nlohmann::json msg = nlohmann::json::object();  // what the next request carries
  bool more = true;               // rank 0 may still have units for this rank
  const double beat_s = heartbeat_s(silence_s_);
  last_sent_ = now_s();
  for (;;) {
    const bool stop = interrupt && interrupt->load();
    if (stop)
      for (; !todo.empty(); todo.pop_front()) msg["returned"].push_back(todo.front());
    for (; !stop && pool.has_room() && !todo.empty(); todo.pop_front()) {
      started[todo.front()] = now_s();
      pool.submit(todo.front());
    }
    const bool hungry = more && !stop && todo.empty() && pool.has_room();
    const bool winding_down = !more || stop;
    if (hungry || msg.contains("error") || (winding_down && (!msg.empty() || pool.busy() == 0))) {
      const bool idle = pool.busy() == 0 && todo.empty();
      msg["want"] = hungry ? batch_size(unit_s) : 0;
      msg["idle"] = idle;
      if (stop) msg["stop"] = true;
      const auto ids = ask(msg);
      msg = nlohmann::json::object();
      if (ids.size() == 1 && ids[0] == kTakenForDead) {
        std::fprintf(stderr, "springblock: rank %d was silent too long and was taken for dead; its units were "
                             "dealt to other ranks: it stops\n", rank_);
        return;  // the pool's running units finish and are dropped
      }
      todo.insert(todo.end(), ids.begin(), ids.end());
      if (ids.empty()) {
        more = false;
        if (idle) return;
      }
      continue;
    }
    if (now_s() - last_sent_ >= beat_s) {
      last_sent_ = now_s();
      MPI_Send(nullptr, 0, MPI_BYTE, 0, kBeatTag, MPI_COMM_WORLD);
    }
    auto d = pool.collect(std::chrono::milliseconds(100));
    if (!d) continue;
    const double wall_s = now_s() - started[d->id];
    started.erase(d->id);
    if (d->error) {
      try {
        std::rethrow_exception(d->error);
      } catch (const std::exception& e) {
        msg["error"] = e.what();
      }
    } else if (d->result.is_null()) {
      msg["returned"].push_back(d->id);  // cut short by an interrupt: not a result
    } else {
      unit_s = unit_s > 0 ? 0.8 * unit_s + 0.2 * wall_s : wall_s;
      msg["done"].push_back({{"id", d->id}, {"record", std::move(d->result)}});
    }
  }
}

}  // namespace

std::unique_ptr<Scheduler> make_mpi_scheduler(int threads, double batch_s, double silence_s) {
  return std::make_unique<MpiScheduler>(threads, batch_s, silence_s);
}

}  // namespace sb::parallel
