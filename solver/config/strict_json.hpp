#pragma once
// Reads a configuration's JSON text more strictly than nlohmann::json does by itself, and keeps
// messages short:
//  - a key given twice in one object is an error (nlohmann keeps the last: a second "mesh" group would
//    silently replace the first whole);
//  - a number beyond a double (1e999) is reported with its key (nlohmann throws out_of_range 406,
//    which names no key);
//  - values and keys quoted back in messages are cut to excerpt() length, so that a 100 MB string is
//    never echoed to stderr.
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>

namespace slidewave {

/// `text` when it has at most `max_chars` characters, else its first `max_chars` followed by "...".
std::string excerpt(const std::string& text, std::size_t max_chars = 60);

/// Parses `text` (`origin` names it in messages). Throws ConfigError (config/run_config.hpp) with every
/// duplicated key ("mesh: key given twice ..."), or with the one syntax error or overflowing number
/// (with its key path, e.g. "friction.f").
nlohmann::json parse_strict_json(const std::string& text, const std::string& origin);

}  // namespace slidewave
