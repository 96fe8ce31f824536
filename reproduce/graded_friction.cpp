/* NARRATIVE
Question: none of the paper's, but one its conclusion names: does a friction gradient along the
chain change the macroscopic friction of a chain whose micro mu_s has the same mean, and does it
matter whether mu_s rises or falls in the pulling direction?
Geometry: every block hangs from the slider by its own spring and the slider moves towards +x;
block i rests at i l_x, so the block index grows in the pulling direction (block 0 trails, block
N-1 leads). "Rising" is mu_s growing with the block index. There is no pulled end: the equations
are unchanged when the chain is read backwards, so on a surface that is its own mirror image
(smooth) the two directions are the same ensemble and any difference between them is noise; a
patterned surface laid out from block 0 (periodic:10,10: pawl first, groove last) is not its own
mirror image, which is the only way the direction can enter.
Scene: the paper's chain (N = 360, L_x = 7.2 cm, default parameters: mu_s 1.0 sd 0.1, mu_d 0.5
sd 0.01), smooth and periodic:10,10; micro mu_s a linear ramp over the blocks with a total
change (last block minus first) of 0, +-0.2, +-0.4, placed so that its mean over the contact
blocks is exactly 1.0 (the uniform chain's). Event method (exact), the tier's repetitions and run
length. Every scene of the study shares one seed: repetition r of each slope draws the same
Gaussian deviates, so differences between slopes are paired repetition by repetition.
Criterion, fixed before any run: a difference (a slope against the uniform chain, or rising
against falling at the same |slope|) is resolved when its paired mean exceeds 3 of its standard
errors (sd of the paired differences / sqrt(n)); among its 24 comparisons (12 per quantity) a
3-sigma rule raises one false alarm or more about 6% of the time. Otherwise it is "not resolved" and the
document gives the standard error, i.e. the size of effect the study could have seen.
Cost: about 10 CPU s at the paper tier (measured figure in the document's wall_seconds).
Output: each scene's result (runs kept for the pairing) and `comparisons`: per surface, quantity
(mu_s, mu_d) and comparison, the paired mean difference, its standard error, z and the verdict.
*/
#include <cmath>
#include <fmt/format.h>

#include "common.hpp"
#include "springblock/surface.hpp"

namespace {

constexpr double kMean = 1.0;
const std::vector<double> kSlopes = {-0.4, -0.2, 0.0, 0.2, 0.4};
const std::vector<std::pair<std::string, std::string>> kSurfaces = {{"smooth", "smooth"},
                                                                    {"periodic_10_10", "periodic:10,10"}};

std::string slope_id(double s) { return fmt::format("{}{:.0f}", s < 0 ? "m" : "p", std::fabs(100 * s)); }

// A ramp a + b i with b = slope / (N - 1) and a chosen so the mean over the contact blocks is kMean.
sb::MaterialSegment ramp(const sb::Scene& s, double slope) {
  const int N = s.geometry.N;
  const auto mask = sb::build_contact_mask(s.pattern, N, 0);
  double sum_i = 0;
  int n = 0;
  for (int i = 0; i < N; ++i)
    if (mask[i]) sum_i += i, ++n;
  const double b = slope / (N - 1), a = kMean - b * sum_i / n;
  return {sb::BlockField::MuS, 0, -1, true, 0, a, a + b * (N - 1)};
}

struct Paired {
  double mean = 0, sem = 0;
  int n = 0;
};

Paired paired(const nlohmann::json& a, const nlohmann::json& b, const char* key) {
  std::vector<double> d;
  for (std::size_t r = 0; r < a.size() && r < b.size(); ++r)
    if (a[r].at(key).is_number() && b[r].at(key).is_number())
      d.push_back(a[r].at(key).get<double>() - b[r].at(key).get<double>());
  Paired p;
  p.n = static_cast<int>(d.size());
  if (p.n < 2) return p;
  for (double x : d) p.mean += x / p.n;
  double ss = 0;
  for (double x : d) ss += (x - p.mean) * (x - p.mean);
  p.sem = std::sqrt(ss / (p.n - 1) / p.n);
  return p;
}

const nlohmann::json& runs_of(const nlohmann::json& doc, const std::string& id) {
  for (const auto& rec : doc.at("scenes"))
    if (rec.at("id") == id) return rec.at("result").at("runs");
  throw std::runtime_error("graded_friction: no scene " + id);
}

nlohmann::json comparison(const nlohmann::json& doc, const std::string& surface, const std::string& a,
                          const std::string& b, const char* key, const std::string& what) {
  const Paired p = paired(runs_of(doc, surface + "_" + a), runs_of(doc, surface + "_" + b), key);
  const double z = p.sem > 0 ? p.mean / p.sem : 0.0;
  return {{"surface", surface}, {"quantity", key}, {"what", what}, {"a", a}, {"b", b}, {"n", p.n},
          {"diff", p.mean}, {"sem", p.sem}, {"z", z}, {"resolved", std::fabs(z) >= 3.0}};
}

}  // namespace

int main(int argc, char** argv) {
  return repro::run_target(
      argc, argv, "graded_friction", "graded micro mu_s along the chain against the uniform chain, N=360",
      [](const repro::Context& ctx) {
        std::vector<repro::LabelledScene> out;
        for (const auto& [id, pattern] : kSurfaces)
          for (double slope : kSlopes) {
            sb::Scene s = ctx.chain(360, "7.2cm", pattern);
            const auto seg = ramp(s, slope);
            if (slope != 0) s.materials.segments.push_back(seg);
            repro::LabelledScene ls{id + "_" + slope_id(slope), fmt::format("{}, mu_s change {:+.1f}", pattern, slope),
                                    {{"pattern", pattern}, {"slope", slope}, {"mu_s_first", seg.start},
                                     {"mu_s_last", seg.end}}, s};
            ls.shared_seed = true;
            out.push_back(ls);
          }
        return out;
      },
      [](const repro::Context&, nlohmann::json& doc) {
        nlohmann::json cmp = nlohmann::json::array();
        for (const auto& sf : kSurfaces)
          for (const char* key : {"mu_s", "mu_d"}) {
            for (double slope : kSlopes)
              if (slope != 0)
                cmp.push_back(comparison(doc, sf.first, slope_id(slope), slope_id(0), key, "graded - uniform"));
            for (double slope : {0.2, 0.4})
              cmp.push_back(comparison(doc, sf.first, slope_id(slope), slope_id(-slope), key, "rising - falling"));
          }
        doc["comparisons"] = cmp;
        doc["mean_mu_s"] = kMean;
        doc["question"] = "Does a linear ramp of micro mu_s along the chain (same mean over the contact blocks) "
                          "change the macroscopic mu_s or mu_d, and does its direction matter?";
        doc["criterion"] = "A paired mean difference (same seeds, repetition by repetition) is resolved when "
                           "|difference| >= 3 standard errors of the paired differences; otherwise not resolved.";
      });
}
