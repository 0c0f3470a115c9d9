// The key table rendered for people (the key section of docs/contracts.md) and for tools
// (`slidewave keys --json`, which tests use to check study/config.schema.yaml).
#include "config/config_keys.hpp"
#include "config/run_config.hpp"

namespace slidewave {
namespace {

using nlohmann::json;

std::string kind_name(KeyKind kind) {
  switch (kind) {
    case KeyKind::number:
      return "number";
    case KeyKind::optional_number:
      return "optional_number";
    case KeyKind::integer:
      return "integer";
    case KeyKind::choice:
      return "choice";
    case KeyKind::number_list:
      return "number_list";
  }
  return "";
}

/// A Markdown table cell: a literal `|` would end the cell.
std::string cell(const std::string& text) {
  std::string out;
  for (const char ch : text) out += ch == '|' ? std::string("\\|") : std::string(1, ch);
  return out;
}

}  // namespace

json config_keys_json() {
  json out = json::array();
  for (const auto& k : config_keys()) {
    json row = {{"group", k.group},
                {"name", k.name},
                {"kind", kind_name(k.kind)},
                {"default", k.default_value()},
                {"unit", k.unit},
                {"description", k.description},
                {"allowed", k.allowed()}};
    if (k.lower) row["minimum"] = {{"value", k.lower->value}, {"exclusive", k.lower->open}};
    if (k.upper) row["maximum"] = {{"value", k.upper->value}, {"exclusive", k.upper->open}};
    if (!k.choices.empty()) row["choices"] = k.choices;
    out.push_back(row);
  }
  return out;
}

std::string config_keys_markdown() {
  // The defaults as one JSON object, a line per group, in the table's order (the groups of the default
  // resolved configuration: `substrate` is absent by default, docs/substrate.md).
  std::string block = "```json\n{\n";
  const json defaults = RunConfig{}.to_json();
  std::vector<std::string> groups;
  for (const auto& g : config_groups())
    if (defaults.contains(g)) groups.push_back(g);
  for (size_t g = 0; g < groups.size(); ++g) {
    std::string line = "  \"" + groups[g] + "\":";
    line += std::string(line.size() < 18 ? 18 - line.size() : 1, ' ') + "{";
    bool first = true;
    for (const auto& k : config_keys()) {
      if (k.group != groups[g]) continue;
      line += (first ? "" : ", ") + json(k.name).dump() + ": " + k.default_value().dump();
      first = false;
    }
    block += line + "}" + (g + 1 < groups.size() ? "," : "") + "\n";
  }
  block += "}\n```\n";

  std::string table = "| key | default | allowed | meaning |\n|---|---|---|---|\n";
  for (const auto& k : config_keys())
    table += "| `" + k.path() + "` | " + cell(k.default_value().dump()) + " | " + cell(k.allowed()) + " | " +
             cell(k.description) + " |\n";
  return block + "\n" + table;
}

}  // namespace slidewave
