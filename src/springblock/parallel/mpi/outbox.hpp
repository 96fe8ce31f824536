#pragma once
// The coordinator's answers in flight. An answer is sent without waiting for it to arrive
// (MPI_Isend): a blocking send of a large batch to a rank that died after asking would never
// return. Sends to a rank taken for dead are abandoned (their buffers kept until the end, as MPI
// may still read them).
#include <mpi.h>

#include <list>
#include <vector>

namespace sb::parallel {

class Outbox {
 public:
  // Sends `ids` to `rank` with `tag`; false if MPI refused (the rank is unreachable).
  bool send(std::vector<int> ids, int rank, int tag, MPI_Comm comm);
  // Forgets the answers that have arrived.
  void reap();
  // Gives up the answers to `rank`.
  void abandon(int rank);
  // Waits for every answer not abandoned (to ranks that are still there).
  void drain();

 private:
  struct Sent {
    int rank;
    MPI_Request request;
    std::vector<int> ids;
  };
  std::list<Sent> sent_;
  std::list<std::vector<int>> abandoned_;
};

}  // namespace sb::parallel
