#include "springblock/parallel/mpi/outbox.hpp"

namespace sb::parallel {

bool Outbox::send(std::vector<int> ids, int rank, int tag, MPI_Comm comm) {
  sent_.push_back({rank, MPI_REQUEST_NULL, std::move(ids)});
  auto& s = sent_.back();
  if (MPI_Isend(s.ids.data(), static_cast<int>(s.ids.size()), MPI_INT, rank, tag, comm, &s.request) != MPI_SUCCESS) {
    sent_.pop_back();
    return false;
  }
  return true;
}

void Outbox::reap() {
  for (auto it = sent_.begin(); it != sent_.end();) {
    int done = 0;
    MPI_Test(&it->request, &done, MPI_STATUS_IGNORE);
    it = done ? sent_.erase(it) : std::next(it);
  }
}

void Outbox::abandon(int rank) {
  for (auto it = sent_.begin(); it != sent_.end();)
    if (it->rank == rank) {
      MPI_Request_free(&it->request);
      abandoned_.push_back(std::move(it->ids));
      it = sent_.erase(it);
    } else {
      ++it;
    }
}

void Outbox::drain() {
  for (auto& s : sent_) MPI_Wait(&s.request, MPI_STATUS_IGNORE);
  sent_.clear();
}

}  // namespace sb::parallel
