#include "springblock/parallel/dealer.hpp"

namespace sb::parallel {

Dealer::Dealer(const std::vector<int>& ids, const Hooks& hooks, const std::atomic<bool>* interrupt)
    : queue_(ids.begin(), ids.end()), hooks_(hooks), interrupt_(interrupt) {}

std::optional<int> Dealer::next(int rank) {
  const auto ids = next_batch(rank, 1);
  if (ids.empty()) return std::nullopt;
  return ids[0];
}

std::vector<int> Dealer::next_batch(int rank, int count) {
  std::vector<int> ids;
  if (interrupted()) return ids;
  while (static_cast<int>(ids.size()) < count && !queue_.empty()) {
    ids.push_back(queue_.front());
    queue_.pop_front();
    holder_[ids.back()] = rank;
  }
  if (!ids.empty() && hooks_.assigned) hooks_.assigned(ids, rank);
  return ids;
}

bool Dealer::finished(int id, int rank, nlohmann::json record) {
  if (record.is_null()) return false;  // interrupted: still held, reported as unfinished
  const auto held = holder_.find(id);
  if (held == holder_.end() || held->second != rank) return false;
  holder_.erase(held);
  if (hooks_.finished) hooks_.finished(id, rank, std::move(record));
  return true;
}

void Dealer::give_back(int id) {
  holder_.erase(id);
  queue_.push_front(id);
}

std::vector<int> Dealer::reclaim(int rank) {
  std::vector<int> ids;
  for (auto it = holder_.begin(); it != holder_.end();)
    if (it->second == rank) {
      ids.push_back(it->first);
      it = holder_.erase(it);
    } else {
      ++it;
    }
  for (auto it = ids.rbegin(); it != ids.rend(); ++it) queue_.push_front(*it);
  return ids;
}

void Dealer::tick() {
  const auto now = std::chrono::steady_clock::now();
  if (now - last_tick_ < std::chrono::milliseconds(200)) return;
  last_tick_ = now;
  if (hooks_.tick) hooks_.tick();
}

Outcome Dealer::outcome() const {
  Outcome o;
  o.interrupted = interrupted();
  for (auto& [id, rank] : holder_) o.unfinished.push_back({id, rank});
  o.notes = notes;
  return o;
}

namespace {

void fill(UnitPool& pool, Dealer& dealer, int rank) {
  while (pool.has_room()) {
    auto id = dealer.next(rank);
    if (!id) break;
    pool.submit(*id);
  }
}

}  // namespace

void serve_pool(UnitPool& pool, Dealer& dealer, int rank, std::chrono::milliseconds wait) {
  fill(pool, dealer, rank);
  if (pool.busy() > 0) {
    if (auto d = pool.collect(wait)) {
      if (d->error) std::rethrow_exception(d->error);
      dealer.finished(d->id, rank, std::move(d->result));
      fill(pool, dealer, rank);  // the freed thread's next unit
    }
  }
  // A finished unit's record and the assignment of the unit that replaced it in one write.
  dealer.settle();
}

}  // namespace sb::parallel
