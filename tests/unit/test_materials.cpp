// Per-block fields: the TSV reader and its messages, segments and ramps expanded to literal
// values, the hash, the checks of validate(), and the chain a file of the scene's own values
// builds (the uniform scene's, bit for bit).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "springblock/errors.hpp"
#include "springblock/materials.hpp"
#include "springblock/scene.hpp"
#include "springblock/trajectory_spec.hpp"

using namespace sb;

namespace {

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

const std::vector<double>& column(const BlockMaterials& m, BlockField f) { return m.columns[index_of(f)]; }

Scene small(int N) {
  Scene s;
  s.geometry.N = N;
  return s;
}

}  // namespace

TEST(MaterialsTsv, ReadsNamedColumnsSkippingCommentsAndBlankLines) {
  const auto m = parse_materials_tsv("# a comment\nmu_s\tk_s_scale\n\n1.25\t2\n 0.5 \t1e-1\r\n# end\n", "f.tsv");
  EXPECT_TRUE(m.file);
  EXPECT_EQ(m.source, "f.tsv");
  EXPECT_EQ(column(m, BlockField::MuS), (std::vector<double>{1.25, 0.5}));
  EXPECT_EQ(column(m, BlockField::KsScale), (std::vector<double>{2.0, 0.1}));
  EXPECT_TRUE(column(m, BlockField::MuD).empty());  // not given: the scene's uniform value
  EXPECT_EQ(m.lines, (std::vector<int>{4, 5}));
}

TEST(MaterialsTsv, ErrorsNameThePathLineAndColumn) {
  auto msg = [](const std::string& text) { return message_of([&] { parse_materials_tsv(text, "m.tsv"); }); };
  const auto unknown = msg("mu_s\tfriction\n1\t2\n");
  EXPECT_TRUE(has(unknown, "'m.tsv' line 1")) << unknown;
  EXPECT_TRUE(has(unknown, "unknown field 'friction'")) << unknown;
  EXPECT_TRUE(has(unknown, "contact, mu_s, mu_s_sd, mu_d, mu_d_sd, k_int_scale, k_s_scale, mass_scale")) << unknown;
  EXPECT_TRUE(has(msg("mu_s\tmu_s\n1\t1\n"), "column 'mu_s' appears twice"));
  const auto cells = msg("mu_s\tmu_d\n1\t0.5\n1\n");
  EXPECT_TRUE(has(cells, "'m.tsv' line 3: 1 cells where the header names 2 columns")) << cells;
  const auto word = msg("mu_s\tmu_d\n1\t0.5\n1\tabc\n");
  EXPECT_TRUE(has(word, "'m.tsv' line 3: column mu_d: 'abc' is not a number")) << word;
  EXPECT_TRUE(has(msg("mu_s\n1.5x\n"), "'1.5x' is not a number"));
  EXPECT_TRUE(has(msg("# only a comment\n"), "no header line"));
  EXPECT_TRUE(has(message_of([] { read_materials_tsv("/no/such/materials.tsv"); }),
                  "cannot read materials file '/no/such/materials.tsv'"));
}

TEST(MaterialsSegments, ValuesAndRampsExpandToLiteralValues) {
  Scene s = small(5);
  s.friction.mu_s_mean = 1.0;
  MaterialSegment value{BlockField::MuS, 1, 2, false, 1.5, 0, 0};
  MaterialSegment ramp{BlockField::KIntScale, 0, -1, true, 0, 1.0, 3.0};  // -1: the last block
  MaterialSegment last{BlockField::MuS, -1, -1, false, 0.25, 0, 0};
  s.materials.segments = {value, ramp, last};
  const auto r = resolve_materials(s);
  EXPECT_EQ(r.source, "segments");
  EXPECT_EQ(r.column[index_of(BlockField::MuS)], (std::vector<double>{1.0, 1.5, 1.5, 1.0, 0.25}));
  EXPECT_EQ(r.column[index_of(BlockField::KIntScale)], (std::vector<double>{1.0, 1.5, 2.0, 2.5, 3.0}));
  EXPECT_FALSE(r.has(BlockField::MuD));
  EXPECT_TRUE(r.mechanical());
}

TEST(MaterialsSegments, SceneFileFormAndSweepAxisName) {
  Scene s = small(4);
  apply_scene_json(s, nlohmann::json::parse(
                          R"({"segments": [{"field": "mu_d", "from": 0, "to": 1, "value": 0.3},
                                           {"field": "mu_s", "from": 2, "to": 3, "start": 1.0, "end": 2.0}]})"));
  apply_scene_json(s, nlohmann::json{{"segments.1.end", 3.0}, {"segments.0.value", 0.4}});
  const auto r = resolve_materials(s);
  EXPECT_EQ(r.column[index_of(BlockField::MuD)], (std::vector<double>{0.4, 0.4, 0.5, 0.5}));
  EXPECT_EQ(r.column[index_of(BlockField::MuS)], (std::vector<double>{1.0, 1.0, 1.0, 3.0}));
  const auto to_json_text = nlohmann::json(s).at("materials").dump();
  EXPECT_TRUE(has(to_json_text, "\"source\":\"segments\"")) << to_json_text;
  EXPECT_TRUE(has(message_of([&] { apply_scene_json(s, nlohmann::json{{"segments.2.value", 1.0}}); }),
                  "names segment 2 but the scene lists 2"));
  EXPECT_TRUE(has(message_of([&] {
                    apply_scene_json(s, nlohmann::json::parse(R"({"segments": [{"field": "mu_s", "from": 0, "to": 1}]})"));
                  }),
                  "needs either a value or both start and end"));
  EXPECT_TRUE(has(message_of([&] {
                    apply_scene_json(s, nlohmann::json::parse(
                                            R"({"segments": [{"field": "grip", "from": 0, "to": 1, "value": 1}]})"));
                  }),
                  "unknown field 'grip'"));
}

TEST(MaterialsHash, StableLiteralValues) {
  ResolvedMaterials r;
  EXPECT_EQ(materials_hash(r), "cbf29ce484222325");  // FNV-1a 64 of nothing: its offset basis
  r.column[index_of(BlockField::MuS)] = {1.0, 1.5};
  EXPECT_EQ(materials_hash(r), "0ca86232e84dca2b");
  r.column[index_of(BlockField::MassScale)] = {2.0, 1.0};
  EXPECT_EQ(materials_hash(r), "af2212d935afd7ff");
}

TEST(MaterialsValidate, RangesRowsAndMethods) {
  auto msg = [](const Scene& s) { return message_of([&] { validate(s); }); };
  Scene s = small(3);
  s.materials = parse_materials_tsv("mu_s\tmu_s_sd\n1\t0.1\n1\tnan\n1\t0.1\n", "m.tsv");
  EXPECT_TRUE(has(msg(s), "'m.tsv' line 3 (row 2, block 1), column mu_s_sd: value nan is outside the allowed range [0, 100]"))
      << msg(s);
  s.materials = parse_materials_tsv("mu_s\n1\n1\n", "m.tsv");
  EXPECT_TRUE(has(msg(s), "'m.tsv' has 2 rows; the scene has N = 3 blocks")) << msg(s);
  s.materials = parse_materials_tsv("mass_scale\n1\n0\n1\n", "m.tsv");
  EXPECT_TRUE(has(msg(s), "column mass_scale: value 0 is outside the allowed range [1e-8, 1e8]")) << msg(s);
  // Both ends of the slider spring's and the mass's range are in it; below the lower end is not.
  for (const char* ok : {"1e-08", "1e+08"}) {
    s.materials = parse_materials_tsv(std::string("mass_scale\tk_s_scale\n1\t1\n") + ok + "\t" + ok + "\n1\t1\n", "m.tsv");
    EXPECT_NO_THROW(validate(s)) << ok;
  }
  s.materials = parse_materials_tsv("mass_scale\n1\n9.9e-9\n1\n", "m.tsv");
  EXPECT_TRUE(has(msg(s), "column mass_scale: value 9.9e-09 is outside the allowed range [1e-8, 1e8]")) << msg(s);
  s.materials = parse_materials_tsv("k_s_scale\n1\n1e-300\n1\n", "m.tsv");
  EXPECT_TRUE(has(msg(s), "column k_s_scale: value 1e-300 is outside the allowed range [1e-8, 1e8]")) << msg(s);
  s.materials = parse_materials_tsv("contact\n0\n0\n0\n", "m.tsv");
  EXPECT_TRUE(has(msg(s), "no block in contact")) << msg(s);
  s.materials = parse_materials_tsv("mu_d\n0.5\n1.2\n0.5\n", "m.tsv");
  EXPECT_TRUE(has(msg(s), "'m.tsv' line 3 (row 2, block 1): mu_d mean 1.2 exceeds the mu_s mean 1")) << msg(s);
  // Springs and masses of their own: every method takes them.
  s.materials = parse_materials_tsv("k_s_scale\n1\n2\n1\n", "m.tsv");
  EXPECT_NO_THROW(validate(s));
  s.run.method = Method::RK4;
  EXPECT_NO_THROW(validate(s));
  // All 1 is uniform: the event method takes it.
  s.run.method = Method::Event;
  s.materials = parse_materials_tsv("k_s_scale\tmass_scale\tk_int_scale\n1\t1\t1\n1\t1\t1\n1\t1\t7\n", "m.tsv");
  EXPECT_NO_THROW(validate(s));  // the last row's k_int_scale has no spring
  s.materials = {};
  s.materials.segments = {{BlockField::MuS, 2, 3, false, 1.0, 0, 0}};
  EXPECT_TRUE(has(msg(s), "segments.0 (mu_s): blocks from = 2 to = 3 must satisfy 0 <= from <= to <= N - 1 = 2"))
      << msg(s);
}

TEST(MaterialsChain, DefaultsGiveTheUniformChainBitForBit) {
  Scene uniform = small(40);
  uniform.pattern = parse_pattern("periodic:3,2");
  Scene given = uniform;
  std::string text = "contact\tmu_s\tmu_s_sd\tmu_d\tmu_d_sd\tk_int_scale\tk_s_scale\tmass_scale\n";
  const auto mask = contact_mask(uniform.pattern, 40, 0);
  for (int i = 0; i < 40; ++i) text += std::to_string(int(mask[i])) + "\t1.0\t0.1\t0.5\t0.01\t1\t1\t1\n";
  given.materials = parse_materials_tsv(text, "defaults.tsv");
  ASSERT_NO_THROW(validate(given));
  for (int rep : {0, 3}) {
    const Chain a = build_chain(uniform, rep), b = build_chain(given, rep);
    EXPECT_EQ(a.contact, b.contact);
    EXPECT_EQ(0, std::memcmp(a.mu_s.data(), b.mu_s.data(), 40 * sizeof(double)));
    EXPECT_EQ(0, std::memcmp(a.mu_d.data(), b.mu_d.data(), 40 * sizeof(double)));
    EXPECT_EQ(0, std::memcmp(a.f_static.data(), b.f_static.data(), 40 * sizeof(double)));
    EXPECT_TRUE(b.blocks.uniform());
  }
  // Equal values, distinct provenance: the specs still differ only through the hash.
  EXPECT_NE(trajectory_spec(uniform)->materials_hash, trajectory_spec(given)->materials_hash);
  EXPECT_NE(*trajectory_spec(uniform), *trajectory_spec(given));
}
