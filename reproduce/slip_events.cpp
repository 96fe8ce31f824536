/* NARRATIVE
Claim: none of the paper's: how large the slips under its friction traces are. Between quiet
phases the chain moves in slip events (avalanches); the paper reads mu_s and mu_d off the
friction force and says nothing of their sizes. This study records every slip event of the
paper's smooth chain and of its one-level periodic:10,10 chain (fig. 5's first two surfaces)
and gives the distribution of their size in blocks and of their total slip.
Scene: N = 360, L_x = 7.2 cm, default parameters, smooth and periodic:10,10, the tier's
repetitions and run length, slip events of every repetition recorded (scene field slip_events).
Cost: about 3 CPU s at the paper tier (20 repetitions of 4 t0): a study, not a target, so that
`make reproduce-all` keeps to the paper's work; `make studies` runs it and the figure and the
report read its committed document (paper/data/slip_events.json).
Output: per scene, the exact count of events of each size (result.slip_events.counts_by_blocks)
and, per repetition, the events in logarithmic bins of size and of total slip, and those of every
contact block with their summed slip (slip_event_bins),
from which a figure draws the mean over repetitions and its standard error; the per-event lists
are dropped to keep the document small.
Checked: nothing against the paper (it shows no slip statistics). The events' counts against
the work counters, a closed-form single block and the integrators' agreement are
tests/unit/test_slip_events.cpp.
*/
#include <algorithm>
#include <cmath>

#include "common.hpp"

namespace {

// Size bins in blocks: [1], [2], [3, 4], [5, 8], ... below the chain-spanning size n_contact, which
// is counted on its own (a stick-slip cycle of the whole chain).
std::vector<int> size_edges(int n_contact) {
  std::vector<int> e = {1, 2};
  while (e.back() < n_contact) e.push_back(2 * e.back() - 1);
  e.back() = n_contact;
  return e;
}

// Total slip bins: four per decade from 10 nm to 1 m (the paper's chain: about 0.3 um to 3 cm).
std::vector<double> slip_edges() {
  std::vector<double> e;
  for (int k = 0; k <= 32; ++k) e.push_back(std::pow(10.0, -8.0 + 0.25 * k));
  return e;
}

int bin_of(double x, const std::vector<double>& edges) {
  for (std::size_t b = 0; b + 1 < edges.size(); ++b)
    if (x >= edges[b] && x < edges[b + 1]) return static_cast<int>(b);
  return -1;
}

// One scene's events, binned per repetition; the per-event columns then leave the document.
void bin_events(nlohmann::json& rec) {
  const std::string mask = rec.at("contact_mask").get<std::string>();
  const int n_contact = static_cast<int>(std::count(mask.begin(), mask.end(), '1'));
  const std::vector<int> sizes = size_edges(n_contact);
  const std::vector<double> size_d(sizes.begin(), sizes.end()), slips = slip_edges();
  nlohmann::json size_counts = nlohmann::json::array(), slip_counts = size_counts, spanning = size_counts,
                 spanning_slip = size_counts, outside = size_counts;
  for (auto& run : rec.at("result").at("runs")) {
    std::vector<int> by_size(sizes.size() - 1, 0), by_slip(slips.size() - 1, 0);
    int whole = 0, out = 0;
    double whole_slip = 0;
    const auto& ev = run.at("slip_events");
    for (std::size_t k = 0; k < ev.at("blocks").size(); ++k) {
      const int blocks = ev.at("blocks").at(k).get<int>();
      const double slip = ev.at("slip_m").at(k).get<double>();
      if (blocks == n_contact) ++whole, whole_slip += slip;
      else ++by_size.at(bin_of(blocks, size_d));
      const int b = bin_of(slip, slips);
      if (b >= 0) ++by_slip[b];
      else ++out;
    }
    size_counts.push_back(by_size), slip_counts.push_back(by_slip), outside.push_back(out);
    spanning.push_back(whole), spanning_slip.push_back(whole_slip);
    run.erase("slip_events");
  }
  rec["slip_event_bins"] = {{"n_contact", n_contact},
                            {"size_edges", sizes},
                            {"size_counts", size_counts},
                            {"spanning", spanning},
                            {"spanning_slip_m", spanning_slip},
                            {"slip_edges_m", slips},
                            {"slip_counts", slip_counts},
                            {"slip_outside_edges", outside}};
}

}  // namespace

int main(int argc, char** argv) {
  return repro::run_target(
      argc, argv, "slip_events", "slip events: size in blocks and total slip, smooth and periodic:10,10, N=360",
      [](const repro::Context& ctx) {
        std::vector<repro::LabelledScene> out = {
            {"smooth", "smooth", {{"pattern", "smooth"}}, ctx.chain(360, "7.2cm")},
            {"periodic_10_10", "periodic 10,10", {{"pattern", "periodic:10,10"}},
             ctx.chain(360, "7.2cm", "periodic:10,10")}};
        for (auto& s : out) s.scene.observe.slip_events = true;
        return out;
      },
      [](const repro::Context&, nlohmann::json& doc) {
        for (auto& rec : doc.at("scenes")) bin_events(rec);
        doc["bins"] = "size_counts[r][b]: events of repetition r with size_edges[b] <= blocks < size_edges[b+1] "
                      "(those of all n_contact blocks in spanning[r], their total slip summed in "
                      "spanning_slip_m[r]); slip_counts[r][b]: events with "
                      "slip_edges_m[b] <= total slip < slip_edges_m[b+1]";
      });
}
