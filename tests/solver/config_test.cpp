// Run configuration (config/run_config) and the CLI's handling of bad input (docs/contracts.md §1):
// every invalid value is a ConfigError naming the key and the allowed range, all problems at once,
// and `slidewave run bad.json -o out.h5` exits 2 without writing out.h5.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "config/run_config.hpp"
#include "test_support.hpp"

namespace slidewave {
namespace {

using nlohmann::json;

struct Rejection {
  json input;
  std::string key;      ///< the key the message must name
  std::string allowed;  ///< text of the allowed range the message must contain
};

std::string slurp_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> problems_of(const json& input) {
  try {
    parse_run_config(input);
  } catch (const ConfigError& e) {
    return e.problems;
  }
  return {};
}

TEST(Config, EveryInvalidValueIsRejectedWithKeyAndAllowedRange) {
  const std::vector<Rejection> cases = {
      {{{"material", {{"nu", 0.5}}}}, "material.nu", "0 <= nu < 0.5"},
      {{{"material", {{"nu", -0.1}}}}, "material.nu", "0 <= nu < 0.5"},
      {{{"material", {{"E", 0.0}}}}, "material.E", "E > 0"},
      {{{"material", {{"E", -1000.0}}}}, "material.E", "E > 0"},
      {{{"material", {{"rho", 0.0}}}}, "material.rho", "rho > 0"},
      {{{"material", {{"rho", -1.0}}}}, "material.rho", "rho > 0"},
      {{{"geometry", {{"H", 0.0}}}}, "geometry.H", "H > 0"},
      {{{"geometry", {{"H", -25.0}}}}, "geometry.H", "H > 0"},
      {{{"geometry", {{"lambda_over_H", 0.0}}}}, "geometry.lambda_over_H", "lambda_over_H > 0"},
      {{{"geometry", {{"lambda_over_H", 1.3}}}, {"mesh", {{"elements_per_H", 16}}}},
       "geometry.lambda_over_H",
       "must be an integer"},  // 20.8 elements per period
      {{{"friction", {{"f", -0.1}}}}, "friction.f", "f >= 0"},
      {{{"time", {{"dt", 0.0}}}}, "time.dt", "dt > 0"},
      {{{"time", {{"dt", -0.5}}}}, "time.dt", "dt > 0"},
      {{{"time", {{"dt_times_cs", 0.0}}}}, "time.dt_times_cs", "dt_times_cs > 0"},
      {{{"time", {{"hht_alpha", 0.34}}}}, "time.hht_alpha", "0 <= hht_alpha <= 1/3"},
      {{{"time", {{"hht_alpha", -0.01}}}}, "time.hht_alpha", "0 <= hht_alpha <= 1/3"},
      {{{"time", {{"t_end", 0.0}}}}, "time.t_end", "t_end > 0"},
      {{{"time", {{"stop_after_opening", 0.0}}}}, "time.stop_after_opening", "> 0"},
      {{{"time", {{"contact_weighting", "middle"}}}}, "time.contact_weighting", "alpha|end"},
      {{{"mesh", {{"elements_per_H", 1}}}}, "mesh.elements_per_H", "integer in [2, 4096]"},
      {{{"mesh", {{"elements_per_H", 16.5}}}}, "mesh.elements_per_H", "integer in [2, 4096]"},
      {{{"mesh", {{"elements_per_H", "16"}}}}, "mesh.elements_per_H", "integer in [2, 4096]"},
      {{{"mesh", {{"integration", "bogus"}}}}, "mesh.integration", "full|reduced|reduced_pure"},
      {{{"mesh", {{"mass", "diagonal"}}}}, "mesh.mass", "consistent|lumped"},
      {{{"loading", {{"Uy_over_H", 0.0}}}}, "loading.Uy_over_H", "Uy_over_H < 0"},
      {{{"loading", {{"Uy_over_H", 0.001}}}}, "loading.Uy_over_H", "Uy_over_H < 0"},
      {{{"loading", {{"Uy_over_H", -0.2}}}}, "loading.Uy_over_H", "Uy_over_H < 0"},
      {{{"loading", {{"preshear_ratio", 1.0}}}}, "loading.preshear_ratio", "0 <= preshear_ratio < 1"},
      {{{"loading", {{"preshear_ratio", -0.1}}}}, "loading.preshear_ratio", "0 <= preshear_ratio < 1"},
      {{{"loading", {{"V0_over_cs", 0.0}}}}, "loading.V0_over_cs", "0 < V0_over_cs <= 0.1"},
      {{{"loading", {{"V0_over_cs", 0.2}}}}, "loading.V0_over_cs", "0 < V0_over_cs <= 0.1"},
      {{{"friction", {{"regularization", "rate_state"}}}}, "friction.regularization", "none|prakash_clifton"},
      {{{"friction", {{"pc_length", 0.0}}}}, "friction.pc_length", "pc_length > 0"},
      {{{"friction", {{"pc_velocity", -1.0}}}}, "friction.pc_velocity", "pc_velocity >= 0"},
      {{{"contact", {{"tolerance", 0.0}}}}, "contact.tolerance", "0 < tolerance <= 0.01"},
      {{{"contact", {{"tolerance", 0.1}}}}, "contact.tolerance", "0 < tolerance <= 0.01"},
      {{{"contact", {{"max_iterations", 0}}}}, "contact.max_iterations", "integer in [1, 100000000]"},
      {{{"perturbation", {{"amplitude", -1e-5}}}}, "perturbation.amplitude", "amplitude"},
      {{{"perturbation", {{"seed", -1}}}}, "perturbation.seed", "integer in [0, 9007199254740991]"},
      {{{"perturbation", {{"seed", 1e19}}}}, "perturbation.seed", "integer in [0, 9007199254740991]"},
      {{{"numerics", {{"linear_solver", "lu"}}}}, "numerics.linear_solver", "cholmod"},
      {{{"numerics", {{"threads", 0}}}}, "numerics.threads", "integer in [1, 256]"},
      {{{"numerics", {{"solver", "lu"}}}}, "numerics.solver", "unknown key"},
      {{{"time", {{"max_steps", 0}}}}, "time.max_steps", "integer in [1, 1000000000]"},
      {{{"time", {{"max_steps", 1e10}}}}, "time.max_steps", "integer in [1, 1000000000]"},
      {{{"output", {{"interface_stride", 0}}}}, "output.interface_stride", "integer in [1, 1000000]"},
      {{{"output", {{"snapshot_times", {10.0, -1.0}}}}}, "output.snapshot_times", "list of numbers >= 0 (s)"},
      {{{"output", {{"snapshot_times", 5.0}}}}, "output.snapshot_times", "list of numbers >= 0 (s)"},
      {{{"output", {{"progress", "sometimes"}}}}, "output.progress", "always"},
      // wrong types
      {{{"material", {{"E", "1000"}}}}, "material.E", "E > 0"},
      {{{"friction", {{"f", nullptr}}}}, "friction.f", "f >= 0"},
      {{{"time", {{"dt", "0.1"}}}}, "time.dt", "dt > 0"},
      {{{"mesh", {{"integration", 1}}}}, "mesh.integration", "full|reduced|reduced_pure"},
      // unknown group
      {{{"materials", {{"E", 1000.0}}}}, "materials", "allowed material, geometry, mesh"},
      // unknown key (allowed keys: see UnknownKeyListsTheAllowedKeys)
      {{{"material", {{"Ee", 1000.0}}}}, "material.Ee", "unknown key"},
      {{{"time", {{"alpha", 0.1}}}}, "time.alpha", "unknown key"},
  };
  for (const auto& c : cases) {
    const std::string where = c.input.dump();
    try {
      parse_run_config(c.input);
      ADD_FAILURE() << where << ": accepted";
    } catch (const ConfigError& e) {
      ASSERT_EQ(e.problems.size(), 1u) << where << ":\n" << e.what();
      EXPECT_NE(e.problems[0].find(c.key), std::string::npos) << where << ": " << e.problems[0];
      EXPECT_NE(e.problems[0].find(c.allowed), std::string::npos) << where << ": " << e.problems[0];
      EXPECT_NE(std::string(e.what()).find(e.problems[0]), std::string::npos) << "what() lists every problem";
    } catch (const std::exception& e) {
      ADD_FAILURE() << where << ": threw something else than ConfigError: " << e.what();
    }
  }
}

TEST(Config, GroupThatIsNotAnObject) {
  const auto problems = problems_of({{"material", 5}});
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].find("material"), std::string::npos);
  EXPECT_EQ(problems_of(json::array({1, 2})).size(), 1u) << "top level must be an object";
}

TEST(Config, SeveralProblemsAreReportedAtOnce) {
  const json input = {{"material", {{"nu", 0.5}, {"E", -1.0}}},
                      {"time", {{"hht_alpha", 0.5}, {"dt", -1.0}, {"bogus", 1}}},
                      {"mesh", {{"integration", "x"}}},
                      {"extra", {}}};
  const auto problems = problems_of(input);
  ASSERT_EQ(problems.size(), 7u);
  std::string all;
  for (const auto& p : problems) all += p + "\n";
  for (const char* key :
       {"material.nu", "material.E", "time.hht_alpha", "time.dt", "time.bogus", "mesh.integration", "extra"})
    EXPECT_NE(all.find(key), std::string::npos) << key << " missing from:\n" << all;
}

TEST(Config, BoundaryValuesAreAccepted) {
  const std::vector<json> accepted = {
      {{"material", {{"nu", 0.0}}}},
      {{"material", {{"nu", 0.49}}}},
      {{"friction", {{"f", 0.0}}}},
      {{"time", {{"hht_alpha", 0.0}}}},
      {{"time", {{"hht_alpha", 1.0 / 3.0}}}},
      {{"time", {{"dt", nullptr}}}},
      {{"time", {{"dt", 0.1}}}},
      {{"mesh", {{"elements_per_H", 2}}}},                                          // lambda_over_H = 2: n_x = 4
      {{"mesh", {{"elements_per_H", 16.0}}}},                                       // an integral float is an integer
      {{"geometry", {{"lambda_over_H", 1.5}}}, {"mesh", {{"elements_per_H", 2}}}},  // n_x = 3
      {{"loading", {{"preshear_ratio", 0.0}}}},
      {{"loading", {{"V0_over_cs", 0.1}}}},
      {{"contact", {{"tolerance", 1e-2}}}},
      {{"output", {{"snapshot_times", json::array()}}}},
      json::object(),
  };
  for (const auto& input : accepted) EXPECT_NO_THROW(parse_run_config(input)) << input.dump();
  EXPECT_EQ(problems_of({{"geometry", {{"lambda_over_H", 1.0}}}, {"mesh", {{"elements_per_H", 2}}}}).size(), 1u)
      << "n_x = 2 < 3 periodic columns";
}

/// docs/contracts.md, read at test time so that the test follows the contract document itself.
std::string contract_text() { return slurp_file(std::string(SLIDEWAVE_SOURCE_DIR) + "/docs/contracts.md"); }

// Defaults are the paper's, as listed in the JSON block of docs/contracts.md §1.
TEST(Config, DefaultsAreThoseOfTheContract) {
  const std::string text = contract_text();
  const auto begin = text.find("```json"), end = text.find("```", begin + 7);
  ASSERT_NE(begin, std::string::npos) << "docs/contracts.md has no ```json block";
  const json contract = json::parse(text.substr(begin + 7, end - begin - 7));
  EXPECT_EQ(parse_run_config(json::object()).to_json(), contract);
  EXPECT_EQ(parse_run_config(contract).to_json(), contract);
}

TEST(Config, ResolvedConfigRoundTrips) {
  const RunConfig c = testing::make_config({{"material", {{"nu", 0.45}}},
                                            {"mesh", {{"integration", "full"}, {"mass", "lumped"}}},
                                            {"time", {{"dt", 0.3}, {"stop_after_opening", 100.0}}},
                                            {"friction", {{"regularization", "prakash_clifton"}}},
                                            {"output", {{"snapshot_times", {1.0, 2.0}}}}});
  EXPECT_EQ(parse_run_config(c.to_json()).to_json(), c.to_json());
  EXPECT_EQ(c.mesh.integration, Integration::full);
  EXPECT_EQ(c.mesh.mass, MassKind::lumped);
  EXPECT_EQ(c.time.dt.value(), 0.3);
  EXPECT_EQ(c.derived().dt, 0.3) << "an explicit dt overrides dt_times_cs";
}

TEST(Config, DerivedConstants) {
  const RunConfig c = testing::make_config({{"material", {{"nu", 0.25}}}, {"mesh", {{"elements_per_H", 16}}}});
  const DerivedConstants d = c.derived();
  const double E = 1000, nu = 0.25, rho = 1000, H = 25;
  EXPECT_NEAR(d.c_s, std::sqrt(E / (2 * (1 + nu)) / rho), 1e-15);
  EXPECT_NEAR(d.c_l, std::sqrt(E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)) / rho), 1e-15);
  EXPECT_NEAR(d.p0, 0.001 * E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)), 1e-15);
  EXPECT_EQ(d.n_y, 16);
  EXPECT_EQ(d.n_x, 32);
  EXPECT_DOUBLE_EQ(d.h, H / 16);
  EXPECT_DOUBLE_EQ(d.lambda, 2 * H);
  EXPECT_DOUBLE_EQ(d.dt, 0.5 / d.c_s);
  EXPECT_DOUBLE_EQ(d.V0, 1e-5 * d.c_s);
  // Quasi-static onset: G u / H grows from 0.95 f p0 to f p0 at u = V0 t.
  EXPECT_NEAR(d.t_onset_estimate, 0.05 * 1.5 * d.p0 * H / (d.G * d.V0), 1e-9 * d.t_onset_estimate);
}

// docs/contracts.md §1 says loading.Uy_over_H is "< 0, > -0.1" (open at -0.1).
TEST(Config, ContractUyOverHLowerBoundIsExclusive) {
  EXPECT_EQ(problems_of({{"loading", {{"Uy_over_H", -0.1}}}}).size(), 1u);
}

// docs/contracts.md §1 says perturbation.amplitude is ">= 0" (no upper bound).
TEST(Config, ContractAmplitudeHasNoUpperBound) {
  EXPECT_NO_THROW(parse_run_config({{"perturbation", {{"amplitude", 2.0}}}}));
}

// "every invalid or unknown key reported ... with the allowed range": for an unknown group the message
// lists the allowed groups; for an unknown key it should list the keys of the group.
TEST(Config, UnknownKeyListsTheAllowedKeys) {
  const auto problems = problems_of({{"material", {{"Ee", 1000.0}}}});
  ASSERT_EQ(problems.size(), 1u);
  const auto allowed = problems[0].find("allowed");
  ASSERT_NE(allowed, std::string::npos) << problems[0];
  for (const char* key : {"E", "nu", "rho"})
    EXPECT_NE(problems[0].find(key, allowed), std::string::npos) << problems[0];
}

// issue 11 item 3: a step count over time.max_steps (counted in floating point, so that 2^31 and more
// cannot wrap) is rejected before the run, naming the computed count.
TEST(Config, StepCountOverMaxStepsIsRejectedWithTheCount) {
  const std::vector<json> too_long = {
      {{"time", {{"t_end", 1e12}}}},
      {{"material", {{"rho", 1e-300}}}},
      {{"mesh", {{"elements_per_H", 16}}}, {"time", {{"t_end", 1500.0}, {"dt_times_cs", 1e-7}}}},
      {{"material", {{"rho", 5e-324}}}},  // G / rho overflows: c_s = inf, dt = 0
  };
  for (const auto& input : too_long) {
    const auto problems = problems_of(input);
    ASSERT_EQ(problems.size(), 1u) << input.dump();
    EXPECT_NE(problems[0].find("time.max_steps = 20000000"), std::string::npos) << problems[0];
    EXPECT_NE(problems[0].find(" steps"), std::string::npos) << problems[0];
  }
  // t_end = 1e12 s at dt = 0.5 m / c_s: the message gives that count.
  const double dt = 0.5 / std::sqrt(1000 / (2 * 1.2) / 1000.0);
  char count[32];
  std::snprintf(count, sizeof count, "%.4g steps", std::ceil(1e12 / dt - 1e-9));
  EXPECT_NE(problems_of(too_long[0])[0].find(count), std::string::npos) << problems_of(too_long[0])[0];
}

TEST(Config, StepCountAtMaxStepsIsAccepted) {
  const json at_limit = {{"time", {{"dt", 0.5}, {"t_end", 50.0}, {"max_steps", 100}}}};
  EXPECT_NO_THROW(parse_run_config(at_limit));
  EXPECT_EQ(parse_run_config(at_limit).derived().n_steps, 100.0);
  json over = at_limit;
  over["time"]["max_steps"] = 99;
  const auto problems = problems_of(over);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].find("100 steps, over time.max_steps = 99"), std::string::npos) << problems[0];
}

// The count is checked only once its inputs are valid: a rejected t_end gives one message, not two.
TEST(Config, StepCountIsNotCheckedOnTopOfAnInvalidValue) {
  EXPECT_EQ(problems_of({{"time", {{"t_end", -1.0}, {"max_steps", 1}}}}).size(), 1u);
}

// --threads reaches the configuration as an override of numerics.threads, validated like the file.
TEST(Config, OverridesAreMergedAndValidated) {
  const std::string text = R"({"numerics": {"threads": 2}, "material": {"nu": 0.3}})";
  EXPECT_EQ(parse_run_config_text(text, "x.json").numerics.threads, 2);
  EXPECT_EQ(parse_run_config_text(text, "x.json", {{"numerics", {{"threads", 4}}}}).numerics.threads, 4);
  EXPECT_EQ(parse_run_config_text(text, "x.json", {{"numerics", {{"threads", 4}}}}).material.nu, 0.3);
  EXPECT_THROW(parse_run_config_text(text, "x.json", {{"numerics", {{"threads", 0}}}}), ConfigError);
  EXPECT_THROW(parse_run_config_text("{", "x.json"), ConfigError);
}

// issue 11 item 7: the run parses the bytes it read once; they stay what the file held at that moment.
TEST(Config, ConfigBytesAreReadOnceAndVerbatim) {
  const auto path =
      std::filesystem::temp_directory_path() / ("slidewave_bytes_" + std::to_string(::getpid()) + ".json");
  const std::string original = "{\"material\": {\"nu\": 0.3}}\n  ";
  std::ofstream(path) << original;
  const std::string bytes = read_config_bytes(path.string());
  std::ofstream(path) << R"({"material": {"nu": 0.1}})";
  EXPECT_EQ(bytes, original);
  EXPECT_EQ(parse_run_config_text(bytes, path.string()).material.nu, 0.3);
  std::filesystem::remove(path);
  try {
    read_config_bytes(path.string());
    ADD_FAILURE() << "a missing file was read";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("No such file or directory"), std::string::npos) << e.what();
  }
}

// ---- the CLI -------------------------------------------------------------------------------------

using testing::TempDir;

/// Runs a shell command; returns the exit code (-1 if it did not exit normally).
int run(const std::string& command) {
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(ConfigCli, RunWithBadConfigExits2AndWritesNothing) {
  const TempDir dir("cli_bad");
  const auto config = dir.path / "bad.json", out = dir.path / "out.h5", err = dir.path / "stderr.txt";
  std::ofstream(config) << R"({"material": {"nu": 0.5, "E": -1}, "time": {"hht_alpha": 0.4}, "typo": 1})";
  const int code =
      run(std::string(SLIDEWAVE_BIN) + " run " + config.string() + " -o " + out.string() + " 2> " + err.string());
  EXPECT_EQ(code, 2);
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_FALSE(std::filesystem::exists(dir.path / "out.xdmf"));
  size_t n_files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path)) n_files += entry.is_regular_file();
  EXPECT_EQ(n_files, 2u) << "only bad.json and the captured stderr";
  const std::string message = slurp(err);
  for (const char* key : {"material.nu", "material.E", "time.hht_alpha", "typo"})
    EXPECT_NE(message.find(key), std::string::npos) << key << " missing from:\n" << message;
}

TEST(ConfigCli, CheckValidatesAndPrintsTheResolvedConfig) {
  const TempDir dir("cli_check");
  const auto good = dir.path / "good.json", bad = dir.path / "bad.json", out = dir.path / "resolved.json";
  std::ofstream(good) << R"({"material": {"nu": 0.3}})";
  std::ofstream(bad) << R"({"material": {"nu": 0.3,})";  // not JSON
  EXPECT_EQ(run(std::string(SLIDEWAVE_BIN) + " check " + good.string() + " > " + out.string()), 0);
  EXPECT_EQ(json::parse(slurp(out))["material"]["nu"], 0.3);
  EXPECT_EQ(run(std::string(SLIDEWAVE_BIN) + " check " + bad.string() + " 2> /dev/null"), 2);
  EXPECT_EQ(run(std::string(SLIDEWAVE_BIN) + " check " + (dir.path / "missing.json").string() + " 2> /dev/null"), 2);
}

}  // namespace
}  // namespace slidewave
