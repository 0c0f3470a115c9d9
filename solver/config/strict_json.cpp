#include "config/strict_json.hpp"

#include <set>
#include <vector>

#include "config/run_config.hpp"

namespace slidewave {
namespace {

using nlohmann::json;

/// Where the parser is: one frame per open object (its keys so far, the current one) or array (the
/// index of the current element).
struct Frame {
  bool is_object;
  std::set<std::string> keys;
  std::string key;
  std::size_t index = 0;
};

std::string path_of(const std::vector<Frame>& frames) {
  std::string path;
  for (const auto& f : frames) {
    if (f.is_object && !f.key.empty())
      path += (path.empty() ? "" : ".") + excerpt(f.key);
    else if (!f.is_object)
      path += "[" + std::to_string(f.index) + "]";
  }
  return path.empty() ? "(top level)" : path;
}

}  // namespace

std::string excerpt(const std::string& text, std::size_t max_chars) {
  return text.size() <= max_chars ? text : text.substr(0, max_chars) + "...";
}

json parse_strict_json(const std::string& text, const std::string& origin) {
  std::vector<Frame> frames;
  std::vector<std::string> problems;
  const auto element_done = [&frames] {
    if (!frames.empty() && !frames.back().is_object) ++frames.back().index;
  };
  const json::parser_callback_t watch = [&](int, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
        frames.push_back({true, {}, {}, 0});
        break;
      case json::parse_event_t::array_start:
        frames.push_back({false, {}, {}, 0});
        break;
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        frames.pop_back();
        element_done();
        break;
      case json::parse_event_t::key:
        frames.back().key = parsed.get<std::string>();
        if (!frames.back().keys.insert(frames.back().key).second)
          problems.push_back(path_of(frames) + ": key given twice in one object (JSON keeps only one of them)");
        break;
      case json::parse_event_t::value:
        element_done();
        break;
    }
    return true;
  };
  json parsed;
  try {
    parsed = json::parse(text, watch);
  } catch (const json::out_of_range& e) {
    // 406, "number overflow parsing '1e999'": a literal beyond the range of a double; the frames say
    // whose value it was.
    const std::string what = e.what(), mark = "parsing '";
    const auto start = what.find(mark);
    const std::string literal =
        start == std::string::npos ? what : what.substr(start + mark.size(), what.size() - start - mark.size() - 1);
    throw ConfigError({path_of(frames) + ": " + excerpt(literal) +
                       " is beyond the range of a double; allowed a finite "
                       "number"});
  } catch (const json::exception& e) {
    throw ConfigError({origin + ": not valid JSON: " + excerpt(e.what(), 200)});
  }
  if (!problems.empty()) throw ConfigError(problems);
  return parsed;
}

}  // namespace slidewave
