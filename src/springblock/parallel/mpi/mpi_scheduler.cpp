#include "springblock/parallel/mpi/mpi_scheduler.hpp"

#include <mpi.h>

#include <cstdio>
#include <exception>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>

#include "springblock/parallel/dealer.hpp"

namespace sb::parallel {
namespace {

constexpr int kRequestTag = 1;  // worker -> 0: JSON text {id and record | returned, stop, error}
constexpr int kAssignTag = 2;   // 0 -> worker: a unit id, or -1 (that thread gets no more)

double now_s() { return MPI_Wtime(); }

class MpiScheduler : public Scheduler {
 public:
  explicit MpiScheduler(int threads) {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    if (provided < MPI_THREAD_FUNNELED) throw std::runtime_error("MPI does not support MPI_THREAD_FUNNELED");
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &ranks_);
    threads_ = resolve_threads(threads);
  }
  // Every rank gets here: run() aborts the job itself when one of them fails inside it.
  ~MpiScheduler() override { MPI_Finalize(); }
  int rank() const override { return rank_; }
  int ranks() const override { return ranks_; }
  int threads() const override { return threads_; }

  bool agree(bool ok) override {
    int v = ok ? 1 : 0;
    MPI_Bcast(&v, 1, MPI_INT, 0, MPI_COMM_WORLD);
    return v != 0;
  }

  void abort(int code) override { MPI_Abort(MPI_COMM_WORLD, code); }

  Outcome run(const std::vector<int>& ids, const UnitRunner& run_unit, const Hooks& hooks,
              const std::atomic<bool>* interrupt) override {
    // Rank 0 learns how many threads (request slots) each worker has.
    std::vector<int> slots(ranks_, 0);
    MPI_Gather(&threads_, 1, MPI_INT, slots.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
    try {
      if (rank_ != 0) {
        work(run_unit, interrupt);
        return {};
      }
      return coordinate(ids, run_unit, hooks, interrupt, std::accumulate(slots.begin() + 1, slots.end(), 0));
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
                     const std::atomic<bool>* interrupt, int worker_slots);
  // Answers one waiting worker request (false if none): takes in the record it carries and sends
  // the next unit, or -1, which retires that worker thread (--open_slots).
  bool answer_one(Dealer& dealer, int& open_slots);
  void work(const UnitRunner& run_unit, const std::atomic<bool>* interrupt);
  std::optional<int> ask(const nlohmann::json& message);

  int rank_ = 0, ranks_ = 1, threads_ = 1;
  long messages_ = 0;
  double message_s_ = 0;
};

Outcome MpiScheduler::coordinate(const std::vector<int>& ids, const UnitRunner& run_unit, const Hooks& hooks,
                                 const std::atomic<bool>* interrupt, int worker_slots) {
  Dealer dealer(ids, hooks, interrupt);
  UnitPool pool(threads_, [&](int id) { return run_unit(id, interrupt); });
  int open_slots = worker_slots;  // worker threads not yet told "no more"
  for (;;) {
    if (dealer.interrupted() && pool.busy() == 0) break;  // the caller aborts the workers
    if (!dealer.interrupted() && dealer.queue_empty() && pool.busy() == 0 && open_slots == 0) break;
    // Short waits while workers may be asking: a request is answered within about a millisecond.
    serve_pool(pool, dealer, 0, std::chrono::milliseconds(open_slots > 0 ? 1 : 100));
    bool answered = false;
    while (open_slots > 0 && !dealer.interrupted() && answer_one(dealer, open_slots)) answered = true;
    // With no unit left to run itself, rank 0 would spin on MPI_Iprobe and take a core from the
    // workers finishing the last units: a short nap instead (it bounds the answer's delay). Not
    // while units remain: its pool is empty for a moment after each of its own units.
    if (!answered && pool.busy() == 0 && (dealer.queue_empty() || dealer.interrupted()))
      std::this_thread::sleep_for(std::chrono::microseconds(500));
    dealer.tick();
  }
  Outcome o = dealer.outcome();
  o.messages = messages_;
  o.message_s = message_s_;
  return o;
}

bool MpiScheduler::answer_one(Dealer& dealer, int& open_slots) {
  const double t0 = now_s();
  int flag = 0;
  MPI_Status st;
  MPI_Iprobe(MPI_ANY_SOURCE, kRequestTag, MPI_COMM_WORLD, &flag, &st);
  if (!flag) return false;
  int n = 0;
  MPI_Get_count(&st, MPI_CHAR, &n);
  std::string text(static_cast<std::size_t>(n), '\0');
  const int src = st.MPI_SOURCE;
  MPI_Recv(text.data(), n, MPI_CHAR, src, kRequestTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  const auto msg = text.empty() ? nlohmann::json::object() : nlohmann::json::parse(text);
  message_s_ += now_s() - t0;  // receiving and decoding; the hooks (checkpoint) are timed by their owner
  if (msg.contains("error"))
    throw std::runtime_error("rank " + std::to_string(src) + ": " + msg.at("error").get<std::string>());
  if (msg.contains("record")) dealer.finished(msg.at("id").get<int>(), src, msg.at("record"));
  if (msg.contains("returned")) {
    dealer.give_back(msg.at("returned").get<int>());
    dealer.notes.push_back("rank " + std::to_string(src) + " was interrupted and gave back unit " +
                           std::to_string(msg.at("returned").get<int>()) + " (run elsewhere)");
  }
  std::optional<int> id;
  if (!msg.value("stop", false)) id = dealer.next(src);
  const int reply = id ? *id : -1;
  const double t1 = now_s();
  MPI_Send(&reply, 1, MPI_INT, src, kAssignTag, MPI_COMM_WORLD);
  if (!id) --open_slots;
  ++messages_;
  message_s_ += now_s() - t1;
  return true;
}

std::optional<int> MpiScheduler::ask(const nlohmann::json& message) {
  const std::string text = message.empty() ? "" : message.dump();
  MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, 0, kRequestTag, MPI_COMM_WORLD);
  int id = -1;
  MPI_Recv(&id, 1, MPI_INT, 0, kAssignTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return id >= 0 ? std::optional<int>(id) : std::nullopt;
}

// A worker: one request per thread to start, then each finished unit goes back with a request
// for the next, until rank 0 has nothing left for any of its threads.
void MpiScheduler::work(const UnitRunner& run_unit, const std::atomic<bool>* interrupt) {
  UnitPool pool(threads_, [&](int id) { return run_unit(id, interrupt); });
  for (int t = 0; t < threads_; ++t)
    if (auto id = ask(nlohmann::json::object())) pool.submit(*id);
  while (pool.busy() > 0) {
    auto d = pool.collect(std::chrono::milliseconds(100));
    if (!d) continue;
    nlohmann::json msg = nlohmann::json::object();
    if (d->error) {
      try {
        std::rethrow_exception(d->error);
      } catch (const std::exception& e) {
        msg["error"] = e.what();
      }
    } else if (d->result.is_null()) {
      msg["returned"] = d->id;  // cut short by an interrupt: not a result
    } else {
      msg["id"] = d->id;
      msg["record"] = std::move(d->result);
    }
    if (interrupt && interrupt->load()) msg["stop"] = true;
    if (auto id = ask(msg)) pool.submit(*id);
  }
}

}  // namespace

std::unique_ptr<Scheduler> make_mpi_scheduler(int threads) { return std::make_unique<MpiScheduler>(threads); }

}  // namespace sb::parallel
