#include "harness/formats/json_text.h"

#include <algorithm>
#include <set>
#include <vector>

namespace cc::harness {
namespace {

// Where the parser is: each open object (its keys so far, the current one) or array (the
// current element's index).
struct Frame {
  bool array = false;
  std::size_t index = 0;
  std::string key;
  std::set<std::string> keys;
};

std::string pointer_of(const std::vector<Frame>& stack) {
  std::string p;
  for (const Frame& f : stack) p += "/" + (f.array ? std::to_string(f.index) : f.key);
  return p;
}

}  // namespace

std::string line_and_column(const std::string& text, std::size_t offset) {
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < std::min(offset, text.size()); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

Json parse_json_text(const std::string& text) {
  std::vector<Frame> stack;
  const auto element_done = [&stack] {
    if (!stack.empty() && stack.back().array) ++stack.back().index;
  };
  const Json::parser_callback_t limits = [&](int, Json::parse_event_t event, Json& parsed) {
    switch (event) {
      case Json::parse_event_t::object_start:
      case Json::parse_event_t::array_start:
        if (stack.size() >= kMaxJsonDepth) {
          throw JsonTextError(pointer_of(stack).empty() ? "/" : pointer_of(stack),
                              "nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
        }
        stack.push_back({event == Json::parse_event_t::array_start, 0, "", {}});
        break;
      case Json::parse_event_t::key: {
        Frame& f = stack.back();
        f.key = parsed.get<std::string>();
        if (!f.keys.insert(f.key).second) throw JsonTextError(pointer_of(stack), "the key \"" + f.key + "\" is given twice");
        break;
      }
      case Json::parse_event_t::object_end:
      case Json::parse_event_t::array_end:
        stack.pop_back();
        element_done();
        break;
      case Json::parse_event_t::value: element_done(); break;
    }
    return true;
  };
  try {
    return Json::parse(text, limits);
  } catch (const Json::parse_error& e) {
    std::string message = e.what();
    const auto at = message.find("syntax error");
    if (at != std::string::npos) message = message.substr(at);
    throw JsonTextError(line_and_column(text, e.byte == 0 ? 0 : e.byte - 1), message);
  } catch (const Json::out_of_range& e) {  // a number beyond a double's range: where its text is
    const std::string message = e.what();
    const auto open = message.find('\''), close = message.rfind('\'');
    const std::string token = open < close ? message.substr(open + 1, close - open - 1) : "";
    const std::size_t where = token.empty() ? std::string::npos : text.find(token);
    throw JsonTextError(where == std::string::npos ? "" : line_and_column(text, where),
                        "the number " + token + " is beyond the range of a double");
  }
}

}  // namespace cc::harness
