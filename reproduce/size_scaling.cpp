/* NARRATIVE
Question: the paper's conclusion asks for "universal scaling relations by changing the system size
parameters", and its figure S1 shows mu_s falling with N at a fixed block size. How do the
macroscopic mu_s and mu_d change with the number of blocks N (a) at a fixed length L_x = 7.2 cm
(finer blocks of the same body) and (b) at a fixed block size l_x = 0.02 cm (a longer body), on a
smooth and on two patterned surfaces, and is there one variable in which the two families fall on
one curve?
Physics that fixes the candidates: K_int = E (N-1) l_y l_z / L_x and K_s = G l_y L_x / (l_z N), so
the chain's elastic length (the distance over which a block's slider spring is relieved by its
neighbours) is ell = l_x sqrt(K_int / K_s) = l_z sqrt((E/G)(N-1)/N), about 0.173 cm whatever N and
L_x. At fixed L_x the chain's length in elastic lengths, Lambda = L_x / ell, stays put (~41.6) and
the blocks per elastic length, n_e = ell / l_x, grow as N; at fixed l_x it is the other way round.
The load per unit area and t0 (0.4 s) are the same in every scene, so every run covers the same
physical time (the tier's 4 t0). Candidates, named before any run: N (the number of independent
micro thresholds, the fibre-bundle reading the paper gives for figure S1), Lambda and n_e.
Surfaces: smooth; periodic:10,10 and hierarchical:30,10 as laid out on the paper's N = 360 chain
of 7.2 cm, i.e. pawls and grooves of 0.2 cm (periodic) and level grooves of 0.6 and 0.2 cm
(hierarchical). At fixed L_x their PHYSICAL sizes are kept as blocks get finer: the block counts
scale with N (periodic:N/36,N/36 and hierarchical:N/12,N/36), so N runs over multiples of 36. At
fixed l_x the block counts stay those of N = 360 (the physical sizes are then fixed too).
Scene: the paper's default parameters, N = 36, 108, 360, 1080, 3600, 10800, 36000 and 108000
(36 times 1, 3, 10, ..., 3000), event method (exact), the tier's run length.
Costs measured before choosing (one core, shared machine, one repetition): a whole run of the
smooth chain at N = 3600 over 7.2 cm took 147 s (0.7 s at 1080; its fine blocks ring fast all
through the sliding phase), so whole runs (mu_s and mu_d) stop at N = 1080 and larger chains stop
at the first slip (stop_after_mu_s: mu_s only). To the first slip over 7.2 cm: smooth 19 s at
108000. The patterned surfaces' grooves at fixed L_x are hundreds of fine, fast blocks: stepped
(the default modal_max_groove, 64) a first slip of periodic took 3 s at 3600 and 88 s at 10800,
and of hierarchical 9 s at 3600. Propagated by their modes instead (modal_max_groove = the longest
groove, up to 300 blocks: kModalGrooveMax), periodic took 1.5 s at 3600 and 34 s at 10800 and
hierarchical 5.6 s at 3600, and ten repetitions of periodic at 3600 gave the same mu_s either way
(0.5218 +- 0.0007 stepped, 0.5217 +- 0.0010 by modes); hierarchical at 10800 (grooves of 900
blocks) took 225 s as modes. So the fixed-L_x grooves are modal up to 300 blocks, periodic at fixed
L_x goes to N = 10800 and hierarchical to 3600; at fixed l_x every surface reaches 108000 (about
1.6 s per repetition at 10800; its grooves keep N = 360's sizes). Repetitions: the tier's (20 at the paper tier) up to
N = 1080, then at most 10 (3600, 10800), 5 (36000) and 3 (108000). The smoke tier stops at 360.
Criterion, fixed before any run (paper/choices.md, "Size scaling"): paper/scaling_fits.py fits
each family's mu against N by weighted least squares on the repetitions' standard errors, (i)
mu = a + b log10 N and (ii) mu = a + b N^-c (scipy curve_fit, its covariance), each judged by its
chi^2 p-value (adequate when p >= 0.01). A candidate variable X collapses a surface's two families
for a quantity when the one curve mu = a + b X^-c fitted to both families' points together is
adequate by the same rule; a candidate that is constant over a family can collapse only if that
family is flat.
Cost: aimed at about 10 CPU minutes at the paper tier, and over it (ten first slips of periodic
at fixed L_x and N = 10800 at about 34 s each come on top); the report gives the measured total
and the cost per repetition of the large chains (the document's wall_seconds and every run's
cpu_s).
Output: every scene's statistics and runs (their cpu_s are the study's cost), with x = {family, surface, N, L_x_cm, l_x_cm,
K_int_over_K_s, elastic_length_cm, Lambda, n_e, groove_blocks, whole_run, modal_max_groove}.
*/
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "common.hpp"

namespace {

constexpr int kRefN = 360;           // the paper's chain the patterns are laid out on
constexpr double kRefLengthCm = 7.2;  // fixed-length family
constexpr double kBlockCm = 0.02;     // fixed-block family: l_x of the reference chain
constexpr int kLargestWholeRun = 1080;
constexpr int kModalGrooveMax = 300;  // fixed L_x: grooves up to this long move by their modes
const std::vector<int> kN = {36, 108, 360, 1080, 3600, 10800, 36000, 108000};

struct Surface {
  std::string id;
  std::vector<int> counts;  // block counts at kRefN (periodic: n_p, n_g; hierarchical: G1, G2)
  std::string kind;
  int longest_groove;       // blocks, at kRefN
  int largest_fixed_length; // the largest N of the fixed-L_x family (cost: the NARRATIVE)
};
const std::vector<Surface> kSurfaces = {{"smooth", {}, "smooth", 0, 108000},
                                        {"periodic_10_10", {10, 10}, "periodic", 10, 10800},
                                        {"hierarchical_30_10", {30, 10}, "hierarchical", 30, 3600}};

// The pattern of `sf` on N blocks, its counts scaled by `scale` (N / 360 at fixed L_x, 1 at fixed l_x).
std::string pattern_of(const Surface& sf, int scale_num, int scale_den) {
  if (sf.kind == "smooth") return "smooth";
  std::string text = sf.kind + ":";
  for (std::size_t k = 0; k < sf.counts.size(); ++k)
    text += (k ? "," : "") + std::to_string(sf.counts[k] * scale_num / scale_den);
  return text;
}

// Repetitions at N: the tier's, fewer where a repetition is costly (stated in the NARRATIVE).
int reps_at(int N, int tier_reps) {
  const int cap = N <= kLargestWholeRun ? tier_reps : N <= 10800 ? 10 : N <= 36000 ? 5 : 3;
  return std::min(tier_reps, cap);
}

}  // namespace

int main(int argc, char** argv) {
  return repro::run_target(
      argc, argv, "size_scaling", "mu_s and mu_d against N at fixed L_x and at fixed l_x, three surfaces",
      [](const repro::Context& ctx) {
        std::vector<repro::LabelledScene> out;
        for (const std::string family : {"fixed_length", "fixed_block"})
          for (const auto& sf : kSurfaces)
            for (int N : kN) {
              if (ctx.tier.reduced && N > kRefN) continue;
              const bool fixed_length = family == "fixed_length";
              if (fixed_length && N > sf.largest_fixed_length) continue;
              const double L_cm = fixed_length ? kRefLengthCm : N * kBlockCm;
              const std::string pattern = fixed_length ? pattern_of(sf, N, kRefN) : pattern_of(sf, 1, 1);
              sb::Scene s = ctx.chain(N, fmt::format("{:.6g}cm", L_cm), pattern);
              s.reps = reps_at(N, ctx.tier.reps);
              const bool whole = N <= kLargestWholeRun;
              s.run.stop_after_mu_s = !whole;
              const int longest = sf.longest_groove * (fixed_length ? N / kRefN : 1);
              if (longest <= kModalGrooveMax) s.run.modal_max_groove = std::max(s.run.modal_max_groove, longest);
              const auto d = s.derived();
              const double ratio = d.K_int_N_per_m / d.K_s_N_per_m;
              const double ell_cm = 100 * d.l_x_m * std::sqrt(ratio);
              const int groove = sf.kind == "smooth" ? 0 : sf.counts.back() * (fixed_length ? N / kRefN : 1);
              repro::LabelledScene ls{
                  fmt::format("{}_{}_N{}", family, sf.id, N),
                  fmt::format("{}, {}, N = {}, L_x = {:.6g} cm", family, pattern, N, L_cm),
                  {{"family", family}, {"surface", sf.id}, {"pattern", pattern}, {"N", N}, {"L_x_cm", L_cm},
                   {"l_x_cm", 100 * d.l_x_m}, {"K_int_over_K_s", ratio}, {"elastic_length_cm", ell_cm},
                   {"Lambda", L_cm / ell_cm}, {"n_e", std::sqrt(ratio)}, {"groove_blocks", groove},
                   {"whole_run", whole}, {"modal_max_groove", s.run.modal_max_groove}},
                  s};
              out.push_back(ls);
            }
        return out;
      },
      [](const repro::Context&, nlohmann::json& doc) {
        doc["question"] = "How do the macroscopic mu_s and mu_d change with N at a fixed L_x (finer blocks) and "
                          "at a fixed block size (longer body), on smooth and patterned surfaces, and does one "
                          "variable (N, Lambda = L_x / ell or n_e = ell / l_x) put both families on one curve?";
        doc["criterion"] = "Each family's trend: weighted least squares on the standard errors, mu = a + b log10 N "
                           "and mu = a + b N^-c, adequate when chi^2 p >= 0.01. A variable X collapses the two "
                           "families when one curve mu = a + b X^-c through both families' points is adequate.";
        doc["largest_whole_run"] = kLargestWholeRun;
        nlohmann::json largest;
        for (const auto& sf : kSurfaces) largest[sf.id] = sf.largest_fixed_length;
        doc["largest_fixed_length"] = largest;
      });
}
