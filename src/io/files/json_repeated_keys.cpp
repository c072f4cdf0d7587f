#include "pmdplan/io/files/json_repeated_keys.hpp"

#include <memory>
#include <unordered_set>
#include <vector>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/core/message_text.hpp"

namespace pmdplan {
namespace {

/// An object or array being read, and which of its members is being read.
struct JsonLevel {
  bool isArray = false;
  std::size_t index = 0;  ///< an array: the element being read
  std::string key;        ///< an object: the key of the member being read
  std::unordered_set<std::string> keys;
};

struct RepeatedKeyCheck {
  std::string file;
  std::string where;
  std::vector<JsonLevel> levels;

  /// A value, object or array ended: the enclosing array moves on to its next element.
  void finishedMember() {
    if (!levels.empty() && levels.back().isArray) ++levels.back().index;
  }

  std::string pathTo(const std::string& key) const {
    std::string path;
    for (const JsonLevel& level : levels) {
      if (&level == &levels.back()) break;
      if (level.isArray)
        path += "[" + std::to_string(level.index) + "]";
      else
        path += (path.empty() ? "" : ".") + fieldKeyText(level.key);
    }
    return path + (path.empty() ? "" : ".") + fieldKeyText(key);
  }

  void fail(const std::string& key) const {
    const std::string path = pathTo(key);
    throw InputError(file, where.empty() ? path : where + ", " + path,
                     "given twice in one object; each key may appear once");
  }
};

}  // namespace

nlohmann::json::parser_callback_t refuseRepeatedJsonKeys(const std::string& file, const std::string& where) {
  // std::function copies its target: the state is shared, not copied.
  auto check = std::make_shared<RepeatedKeyCheck>(RepeatedKeyCheck{file, where, {}});
  return [check](int, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
    using Event = nlohmann::json::parse_event_t;
    switch (event) {
      case Event::object_start:
      case Event::array_start:
        check->levels.push_back(JsonLevel{event == Event::array_start, 0, {}, {}});
        break;
      case Event::key: {
        JsonLevel& object = check->levels.back();
        std::string key = parsed.get<std::string>();
        if (!object.keys.insert(key).second) check->fail(key);
        object.key = std::move(key);
        break;
      }
      case Event::object_end:
      case Event::array_end:
        check->levels.pop_back();
        check->finishedMember();
        break;
      case Event::value:
        check->finishedMember();
        break;
    }
    return true;
  };
}

}  // namespace pmdplan
