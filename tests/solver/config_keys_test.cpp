// The key table (config/config_keys): it drives parsing, messages and the resolved configuration, and
// the key section of docs/contracts.md is its output (regenerate with scripts/update_contract_keys.py).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "config/config_keys.hpp"
#include "config/run_config.hpp"

namespace slidewave {
namespace {

using nlohmann::json;

const char* kBegin = "<!-- BEGIN generated: slidewave keys --markdown";
const char* kEnd = "<!-- END generated: slidewave keys --markdown -->";

std::string contract_text() {
  std::ifstream in(std::string(SLIDEWAVE_SOURCE_DIR) + "/docs/contracts.md");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(ConfigKeys, ContractKeySectionIsTheTablesOutput) {
  const std::string text = contract_text();
  const auto begin = text.find(kBegin), end = text.find(kEnd);
  ASSERT_NE(begin, std::string::npos) << "docs/contracts.md lacks the marker " << kBegin;
  ASSERT_NE(end, std::string::npos) << "docs/contracts.md lacks the marker " << kEnd;
  const auto body = text.find('\n', begin) + 1;
  EXPECT_EQ(text.substr(body, end - body), config_keys_markdown())
      << "docs/contracts.md section 1 differs from the key table: run scripts/update_contract_keys.py";
}

TEST(ConfigKeys, EveryKeyOnceAndEveryMemberInTheResolvedConfig) {
  std::set<std::string> paths;
  for (const auto& k : config_keys()) EXPECT_TRUE(paths.insert(k.path()).second) << k.path() << " twice";
  std::set<std::string> resolved;
  // The substrate and mode_seed groups are resolved only when given (absent: the rigid flat, no mode seed).
  RunConfig with_substrate;
  with_substrate.substrate = SubstrateConfig{3e3, 0.3, 2e3, 25.0};
  with_substrate.mode_seed.amplitude_over_H = 1e-6;
  const json defaults = with_substrate.to_json();  // items() does not keep a temporary alive
  for (const auto& [group, keys] : defaults.items())
    for (const auto& [name, _] : keys.items()) resolved.insert(group + "." + name);
  EXPECT_EQ(paths, resolved);
  EXPECT_FALSE(RunConfig{}.to_json().contains("substrate")) << "no substrate: the group is left out";
  EXPECT_FALSE(RunConfig{}.to_json().contains("mode_seed")) << "no mode seed: the group is left out";
}

TEST(ConfigKeys, EveryDefaultIsAllowed) {
  for (const auto& k : config_keys()) EXPECT_EQ(k.problem(k.default_value()), "") << k.path();
}

// Each key writes the member it reads: set a non-default allowed value, read it back.
TEST(ConfigKeys, SetAndGetAddressTheSameMember) {
  for (const auto& k : config_keys()) {
    if (k.kind == KeyKind::choice && k.choices.size() == 1) continue;  // one allowed value: nothing else to set
    json value;
    switch (k.kind) {
      case KeyKind::choice:
        value = k.choices.back() == k.default_value() ? k.choices.front() : k.choices.back();
        break;
      case KeyKind::number_list:
        value = json::array({1.5, 2.5});
        break;
      case KeyKind::integer:
        value = static_cast<long long>(k.lower->value) + 2;
        break;
      default:
        value = k.lower ? (k.upper ? 0.5 * (k.lower->value + k.upper->value) : k.lower->value + 0.125) : -0.125;
    }
    ASSERT_EQ(k.problem(value), "") << k.path() << " " << value;
    ASSERT_NE(value, k.default_value()) << k.path();
    RunConfig c;
    k.set(c, value);
    EXPECT_EQ(k.get(c), value) << k.path();
    for (const auto& other : config_keys()) {
      if (other.path() != k.path()) {
        EXPECT_EQ(other.get(c), other.default_value()) << k.path() << " wrote " << other.path();
      }
    }
  }
}

// The bounds are what the parser enforces, open or closed, and the message gives key and range.
TEST(ConfigKeys, BoundsAreEnforcedWithKeyAndRangeInTheMessage) {
  int n_checked = 0;
  for (const auto& k : config_keys()) {
    if (k.kind == KeyKind::choice) {
      EXPECT_NE(k.problem("no-such-choice"), "") << k.path();
      continue;
    }
    for (const bool is_lower : {true, false}) {
      const auto& bound = is_lower ? k.lower : k.upper;
      if (!bound) continue;
      const double outward = is_lower ? -1 : 1;
      const double step = k.kind == KeyKind::integer ? 1 : std::max(1e-9, 1e-9 * std::fabs(bound->value));
      const json at = k.kind == KeyKind::integer ? json(static_cast<long long>(bound->value)) : json(bound->value);
      const json beyond = k.kind == KeyKind::integer ? json(static_cast<long long>(bound->value + outward))
                                                     : json(bound->value + outward * step);
      const json at_list = json::array({at}), beyond_list = json::array({beyond});
      const json& at_value = k.kind == KeyKind::number_list ? at_list : at;
      const json& beyond_value = k.kind == KeyKind::number_list ? beyond_list : beyond;
      EXPECT_EQ(k.problem(at_value).empty(), !bound->open) << k.path() << " at " << at;
      const std::string message = k.problem(beyond_value);
      EXPECT_NE(message.find(k.path()), std::string::npos) << message;
      EXPECT_NE(message.find("allowed " + k.allowed()), std::string::npos) << message;
      ++n_checked;
    }
  }
  EXPECT_GE(n_checked, 25);
}

TEST(ConfigKeys, JsonListsEveryKeyWithItsBounds) {
  const json keys = config_keys_json();
  ASSERT_EQ(keys.size(), config_keys().size());
  for (const auto& row : keys)
    if (row["group"] == "material" && row["name"] == "nu") {
      EXPECT_EQ(row["minimum"], json({{"value", 0.0}, {"exclusive", false}}));
      EXPECT_EQ(row["maximum"], json({{"value", 0.5}, {"exclusive", true}}));
      EXPECT_EQ(row["default"], 0.2);
    }
}

}  // namespace
}  // namespace slidewave
