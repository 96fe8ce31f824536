// Bounded random-input test of the user-input parsers: 20000 random and mutated inputs with a
// fixed seed go through the same body as the libFuzzer harness (tests/fuzz/). Every input must
// be accepted or refused with sb::InputError: no other exception, crash or hang.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "../fuzz/fuzz_one_input.hpp"

namespace {

// Valid and nearly valid texts to mutate; mutation finds the interesting boundaries (a digit
// dropped, a separator doubled, a huge exponent) far faster than uniform bytes.
// One list per parser, in the order of fuzz_one_input.hpp.
constexpr int kParsers = 5;
const std::vector<std::string> kSeeds[kParsers] = {
    {"smooth", "periodic:2,1", "periodic:999999,1", "hierarchical:12,4,2", "hierarchical:1,1,1,1,1,1,1,1",
     "random:0.25", "random:0.9999999", "random:nan", "periodic:1,1,1", "hierarchical:4/2,2/1",
     "hierarchical:8/8,1/3", "mask:0110", "mask:1", "mask:@no_such.mask"},
    {"7.2cm", "1e-4ms", "10/ms", "5MPa", "1.2g/cm3", "0.05cm/s", " +3.5 um ", "1e308m", "1e-320s",
     "nan", "-inf", "0x1p3", "\xC2\xB5m", "\xCE\xBCs", "3 kHz", "2 s^-1"},
    {"{\"N\": 50, \"pattern\": \"periodic:2,1\"}", "{\"N\": 1000000, \"pattern\": \"hierarchical:8,4\"}",
     "{\"mu_s\": \"1.0,0.1\", \"dt\": \"1e-4ms\", \"duration\": \"4t0\", \"stress_times\": \"0.1s,0.2s\"}",
     "{\"velocity\": 1e-300, \"damping\": 1e300, \"reps\": 9223372036854775807}",
     "{\"N\": -1}", "{\"length\": [1]}", "{\"pair_policy\": \"keep\", \"k_int_scale\": 0}", "{}",
     "{\"N\": 5, \"segments\": [{\"field\": \"mu_s\", \"from\": 0, \"to\": -1, \"start\": 0.8, \"end\": 1.2}]}",
     "{\"N\": 5, \"segments\": [{\"field\": \"contact\", \"from\": 1, \"to\": 2, \"value\": 0}], \"segments.0.to\": 3}"},
    {"360", "7.2cm", "periodic:2,1", "1.0,0.1", "0.5,0.01", "keep", "0", "10/ms", "0.05cm/s", "1MPa",
     "1.2g/cm3", "20", "7", "2", "rk4", "event", "1e-4ms", "1e-9", "4t0", "1s", "0.05", "0.25",
     "true", "0.2s,0.3s", "0.2s,,0.3s"},
    {"mu_s\tmu_d\n1\t0.5\n", "contact\tmu_s\n1\t1.2\n0\t0.9\n", "# c\nk_int_scale\tmass_scale\n0\t2\n1\t1\n1\t1\n",
     "mu_s_sd\tmu_d_sd\tk_s_scale\n0.1\t0\t3\n0\t0.01\t1e8\n1\t1\t1\n0\t0\t1\n", "mu_s\n1e400\n", "mu_d\n-0\n"},
};
const std::string kAlphabet = "0123456789.,:-+eE /^smcugkHzPaMGnNx\"{}[]t";

std::string mutate(std::string s, std::mt19937_64& rng) {
  const int edits = rng() % 4;  // 0: the seed itself
  for (int k = 0; k < edits; ++k) {
    const std::size_t pos = s.empty() ? 0 : rng() % (s.size() + 1);
    const char c = (rng() % 4 == 0) ? static_cast<char>(rng() % 256) : kAlphabet[rng() % kAlphabet.size()];
    switch (rng() % 4) {
      case 0: s.insert(s.begin() + pos, c); break;
      case 1: if (pos < s.size()) s.erase(pos, 1); break;
      case 2: if (pos < s.size()) s[pos] = c; break;
      default: s.insert(pos, s.substr(0, std::min<std::size_t>(s.size(), 8))); break;  // repeat a chunk
    }
  }
  return s;
}

TEST(FuzzParsers, RandomAndMutatedInputsOnlyRaiseInputError) {
  std::mt19937_64 rng(20240601);
  int accepted = 0;
  for (int n = 0; n < 20000; ++n) {
    std::string text;
    if (n % 7 == 0) {
      text.resize(rng() % 40);
      for (auto& ch : text) ch = static_cast<char>(rng() % 256);
    } else {
      const auto& seeds = kSeeds[n % kParsers];
      text = mutate(seeds[rng() % seeds.size()], rng);
    }
    // Two header bytes: the parser (each in turn) and its sub-choice.
    std::string input;
    input += static_cast<char>(n % kParsers);
    input += static_cast<char>(rng() % 256);
    input += text;
    try {
      accepted += sbfuzz::parse_one(reinterpret_cast<const std::uint8_t*>(input.data()), input.size());
    } catch (const std::exception& e) {
      ADD_FAILURE() << "parser " << n % kParsers << " threw a non-InputError on '" << text << "': " << e.what();
    } catch (...) {
      ADD_FAILURE() << "parser " << n % kParsers << " threw a non-standard exception on '" << text << "'";
    }
  }
  // The mutations must still reach the accepting paths, or the test would only probe rejections.
  EXPECT_GT(accepted, 1000);
}

}  // namespace
