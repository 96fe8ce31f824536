#pragma once
// Which worker ranks the coordinator still hears from. Without fault-tolerant MPI a rank that was
// killed or lost its node says nothing more: the only sign is silence. Every worker sends
// something (a request, or a heartbeat while its threads run) at least every heartbeat_s(); a rank
// silent for longer than `silence_s` is taken for dead, so detection takes at most silence_s plus
// the coordinator's polling delay, whatever the units cost. Times are seconds on any one clock.
#include <vector>

namespace sb::parallel {

// The workers' heartbeat period for a given silence allowed: a quarter of it, at most a second,
// so a rank must miss four beats in a row before it is taken for dead.
double heartbeat_s(double silence_s);

class Liveness {
 public:
  // Ranks 1 .. ranks-1 are watched, each as if heard at `now`.
  Liveness(int ranks, double silence_s, double now);
  double silence_s() const { return silence_s_; }
  void heard(int rank, double now);
  // The rank is done (retired) or taken for dead: no longer watched.
  void forget(int rank);
  // Taken for dead by other means (a send to it failed).
  void mark_dead(int rank);
  bool watched(int rank) const { return watched_[rank]; }
  bool dead(int rank) const { return dead_[rank]; }
  // Watched ranks silent for more than silence_s at `now`, each reported once: they are marked
  // dead and no longer watched.
  std::vector<int> newly_dead(double now);
  double silent_for(int rank, double now) const { return now - last_[rank]; }

 private:
  double silence_s_;
  std::vector<double> last_;
  std::vector<bool> watched_, dead_;
};

}  // namespace sb::parallel
