/* NARRATIVE
Question: none of the paper's, but one its conclusion names (composite materials): does a chain
of alternating soft and hard segments have another macroscopic mu_s or mu_d than the uniform
chain, and how does that depend on the stiffness contrast and on the segments' length?
Composite: segments of L blocks alternate soft, hard, soft, ... from block 0. A hard segment's
internal springs and masses are c times a soft one's, scaled about the uniform chain's
(soft 1/sqrt(c), hard sqrt(c), for k_int_scale and mass_scale alike), so contrast c = 1 is the
uniform chain and the geometric means of stiffness and mass stay the uniform chain's; the local
wave speed sqrt(K_int / m) is the same in both phases, only the impedance changes. The spring
joining block i to i + 1 takes block i's phase (paper/choices.md, "Composite chains").
Scene: N = 200 over 4 cm (the paper's block size l_x = 0.02 cm), smooth surface, default
parameters, contrasts 3 and 10, segment lengths 1, 2, 5, 10, 25 and 50 blocks (N/4), and the uniform
chain, by the method the build reproduces with (the event method, exact on such chains: each run
of blocks that differ gets its own modes, paper/choices.md "Materials given block by block").
Every scene shares one seed, so the friction draws are the same in every scene and differences are
paired repetition by repetition.
Criterion, fixed before any run: a composite's difference from the uniform chain is resolved when
its paired mean exceeds 3 standard errors of the paired differences; otherwise "not resolved",
with the standard error as the size of effect the study could have seen.
Cost: the document's wall_seconds and each run's cpu_s say what it took.
Output: each scene's result (runs kept for the pairing) and `comparisons` (per composite and
quantity: paired mean difference from the uniform chain, standard error, z, verdict).
*/
#include <cmath>
#include <fmt/format.h>

#include "common.hpp"

namespace {

constexpr int kN = 200;
const std::vector<double> kContrasts = {3.0, 10.0};
const std::vector<int> kLengths = {1, 2, 5, 10, 25, 50};

// Block i's phase: soft in even segments, hard in odd ones.
void make_composite(sb::Scene& s, double c, int length) {
  std::vector<double> scale(kN);
  for (int i = 0; i < kN; ++i) scale[i] = (i / length) % 2 ? std::sqrt(c) : 1.0 / std::sqrt(c);
  s.materials.columns[sb::index_of(sb::BlockField::KIntScale)] = scale;
  s.materials.columns[sb::index_of(sb::BlockField::MassScale)] = scale;
  s.materials.source = fmt::format("composite_stiffness: contrast {:g}, segments of {} blocks", c, length);
}

nlohmann::json paired(const nlohmann::json& a, const nlohmann::json& b, const char* key) {
  std::vector<double> d;
  for (std::size_t r = 0; r < a.size() && r < b.size(); ++r)
    if (a[r].at(key).is_number() && b[r].at(key).is_number())
      d.push_back(a[r].at(key).get<double>() - b[r].at(key).get<double>());
  const int n = static_cast<int>(d.size());
  double mean = 0, ss = 0;
  for (double x : d) mean += x / n;
  for (double x : d) ss += (x - mean) * (x - mean);
  const double sem = n > 1 ? std::sqrt(ss / (n - 1) / n) : 0.0;
  const double z = sem > 0 ? mean / sem : 0.0;
  return {{"quantity", key}, {"n", n}, {"diff", mean}, {"sem", sem}, {"z", z}, {"resolved", n > 1 && std::fabs(z) >= 3}};
}

}  // namespace

int main(int argc, char** argv) {
  return repro::run_target(
      argc, argv, "composite_stiffness", "alternating soft and hard segments (K_int and mass) against the uniform chain, N=200",
      [](const repro::Context& ctx) {
        std::vector<repro::LabelledScene> out;
        auto add = [&](double c, int length) {
          sb::Scene s = ctx.chain(kN, "4cm");
          if (c != 1.0) make_composite(s, c, length);
          repro::LabelledScene ls{c == 1.0 ? "uniform" : fmt::format("c{:g}_L{}", c, length),
                                  c == 1.0 ? "uniform" : fmt::format("contrast {:g}, segments of {}", c, length),
                                  {{"contrast", c}, {"segment_blocks", c == 1.0 ? kN : length}}, s};
          ls.shared_seed = true;
          out.push_back(ls);
        };
        add(1.0, kN);
        for (double c : kContrasts)
          for (int length : kLengths) add(c, length);
        return out;
      },
      [](const repro::Context&, nlohmann::json& doc) {
        const nlohmann::json* uniform = nullptr;
        for (const auto& rec : doc.at("scenes"))
          if (rec.at("id") == "uniform") uniform = &rec.at("result").at("runs");
        nlohmann::json cmp = nlohmann::json::array();
        for (const auto& rec : doc.at("scenes")) {
          if (rec.at("id") == "uniform") continue;
          for (const char* key : {"mu_s", "mu_d"}) {
            auto p = paired(rec.at("result").at("runs"), *uniform, key);
            p["id"] = rec.at("id");
            cmp.push_back(p);
          }
        }
        doc["comparisons"] = cmp;
        doc["question"] = "Does a chain of alternating soft and hard segments (internal springs and masses c times "
                          "apart) have another macroscopic mu_s or mu_d than the uniform chain?";
        doc["criterion"] = "A paired mean difference from the uniform chain (same seeds) is resolved when "
                           "|difference| >= 3 standard errors of the paired differences; otherwise not resolved.";
      });
}
