#include "core/io/json_input.hpp"

#include <set>
#include <vector>

#include "core/base/input_error.hpp"

namespace filmdyn::io {

namespace {

// An open object or array while parsing: its path, and an object's keys so far.
struct Open {
  bool object = true;
  std::string path;            // "" at the top level
  std::set<std::string> keys;  // an object's keys
  std::string key;             // an object's last key
  int objects = 0;             // an array's object and array elements so far
};

std::string Join(const std::string& path, const std::string& name) {
  return path.empty() ? name : path + "." + name;
}

}  // namespace

nlohmann::json ParseInputJson(const std::string& text, const std::string& source, int max_depth,
                              const std::string& kind, bool bracketed) {
  using json = nlohmann::json;
  std::vector<Open> open;
  try {
    return json::parse(text, [&](int depth, json::parse_event_t event, json& parsed) {
      if (depth > max_depth) {
        throw InputError(source, "nested deeper than " + std::to_string(max_depth) + " levels",
                         kind + " is a few levels deep; this is not " + kind);
      }
      switch (event) {
        case json::parse_event_t::object_start:
        case json::parse_event_t::array_start: {
          std::string path;
          if (!open.empty()) {
            Open& parent = open.back();
            const std::string index = std::to_string(parent.objects++);
            path = parent.object ? Join(parent.path, parent.key)
                   : bracketed   ? parent.path + "[" + index + "]"
                                 : Join(parent.path, index);
          }
          open.push_back({event == json::parse_event_t::object_start, path, {}, {}, 0});
          break;
        }
        case json::parse_event_t::object_end:
        case json::parse_event_t::array_end:
          if (!open.empty()) open.pop_back();
          break;
        case json::parse_event_t::key:
          if (!open.empty() && open.back().object) {
            Open& object = open.back();
            object.key = parsed.get<std::string>();
            if (!object.keys.insert(object.key).second) {
              throw InputError(source + ": " + Join(object.path, object.key), "given twice",
                               "a key appears once in its object (the second value would "
                               "silently replace the first): keep one");
            }
          }
          break;
        case json::parse_event_t::value:
          break;
      }
      return true;
    });
  } catch (const json::exception& error) {  // syntax, bad UTF-8, a number out of range
    throw InputError(source, "not a valid JSON file", error.what());
  }
}

}  // namespace filmdyn::io
