#pragma once
// The one table of run-configuration keys. Each row gives the group, name, kind, bounds (open or
// closed), unit, description and allowed values of a key, and the RunConfig member it fills. Parsing,
// the error messages (key + allowed range), the resolved configuration (RunConfig::to_json, `slidewave
// check`), `slidewave keys` and the key section of docs/contracts.md all come from it.
// A key's default is its member initializer in config/run_config.hpp; the table reads it from
// RunConfig{} and writes it nowhere else.
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace slidewave {

struct RunConfig;

enum class KeyKind {
  number,           ///< finite real in the bounds
  optional_number,  ///< null (absent) or a finite real in the bounds
  integer,          ///< integral value in the closed bounds (an integral float such as 16.0 counts)
  choice,           ///< one of `choices`
  number_list       ///< list whose every element is a finite real in the bounds
};

/// One end of the allowed interval; `text` replaces the printed value where the decimal is clumsy (1/3).
struct Bound {
  double value;
  bool open = false;  ///< the bound itself is excluded
  std::string text;
};

struct ConfigKey {
  std::string group, name;
  KeyKind kind;
  std::optional<Bound> lower, upper;  ///< absent: unbounded on that side
  std::vector<std::string> choices;   ///< the allowed strings of a `choice`, in the documented order
  /// Values a `choice` once allowed, each with what the solver does instead (refused with that message).
  std::vector<std::pair<std::string, std::string>> retired;
  std::string unit;         ///< SI unit, empty for a dimensionless key
  std::string description;  ///< one paragraph of Markdown
  std::function<nlohmann::json(const RunConfig&)> get;
  std::function<void(RunConfig&, const nlohmann::json&)> set;  ///< precondition: `problem(value)` is empty

  std::string path() const { return group + "." + name; }
  /// The value of RunConfig{} (the member initializer).
  nlohmann::json default_value() const;
  /// The allowed values as written in error messages and docs: "0 <= nu < 0.5", "integer in [2, 4096]",
  /// "full|reduced|reduced_pure"; numbers carry their unit, e.g. "E > 0 (Pa)".
  std::string allowed() const;
  /// Empty when `value` is allowed, else the message "group.name: VALUE ...; allowed ...".
  std::string problem(const nlohmann::json& value) const;
};

/// Every key, grouped in the order of docs/contracts.md.
const std::vector<ConfigKey>& config_keys();
/// The groups in order (material, geometry, ...).
const std::vector<std::string>& config_groups();

/// `slidewave keys --json`: one object per key (group, name, kind, default, minimum / maximum with
/// exclusive flags, unit, description, choices), for tools that check other files against the table.
nlohmann::json config_keys_json();
/// `slidewave keys --markdown`: the generated key section of docs/contracts.md (the default
/// configuration as JSON, then one table row per key).
std::string config_keys_markdown();

}  // namespace slidewave
