#include "run/json_text.h"

#include <new>
#include <utility>

#include "base/text_rules.h"

namespace tactile {
namespace {

using json = nlohmann::json;

// The standard DOM builder, plus where and why parsing stopped.
class LocatingParser {
 public:
  explicit LocatingParser(json& root) : dom_(root, false) {}

  bool null() { return dom_.null(); }
  bool boolean(bool v) { return dom_.boolean(v); }
  bool number_integer(json::number_integer_t v) { return dom_.number_integer(v); }
  bool number_unsigned(json::number_unsigned_t v) { return dom_.number_unsigned(v); }
  bool number_float(json::number_float_t v, const json::string_t& s) {
    return dom_.number_float(v, s);
  }
  bool string(json::string_t& v) { return dom_.string(v); }
  bool binary(json::binary_t& v) { return dom_.binary(v); }
  bool start_object(std::size_t n) { return deeper() && dom_.start_object(n); }
  bool key(json::string_t& v) { return dom_.key(v); }
  bool end_object() {
    --depth_;
    return dom_.end_object();
  }
  bool start_array(std::size_t n) { return deeper() && dom_.start_array(n); }
  bool end_array() {
    --depth_;
    return dom_.end_array();
  }
  template <class Exception>
  bool parse_error(std::size_t position, const std::string& /*token*/, const Exception& e) {
    failed_ = true;
    position_ = position;
    message_ = e.what();
    return false;
  }

  bool tooDeep() const { return tooDeep_; }
  bool failed() const { return failed_; }
  std::size_t position() const { return position_; }
  const std::string& message() const { return message_; }

 private:
  bool deeper() {
    if (++depth_ > kMaxJsonDepth) tooDeep_ = true;
    return !tooDeep_;
  }

  nlohmann::detail::json_sax_dom_parser<json> dom_;
  std::size_t depth_ = 0;
  bool tooDeep_ = false;
  bool failed_ = false;
  std::size_t position_ = 0;
  std::string message_;
};

// Offset of the bracket that opens level kMaxJsonDepth + 1 (strings skipped).
std::size_t tooDeepAt(std::string_view text) {
  std::size_t depth = 0;
  bool inString = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (inString) {
      if (c == '\\') {
        ++i;
      } else if (c == '"') {
        inString = false;
      }
    } else if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth) return i;
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return text.size();
}

// nlohmann's text without its "[json.exception.NAME.ID] " tag and its own position (we give ours).
std::string plainMessage(std::string message) {
  if (message.starts_with("[json.exception.")) {
    const std::size_t end = message.find("] ");
    if (end != std::string::npos) message.erase(0, end + 2);
  }
  if (message.starts_with("parse error at line ")) {
    const std::size_t colon = message.find(": ");
    if (colon != std::string::npos) message.erase(0, colon + 2);
  } else if (message.starts_with("parse error: ")) {
    message.erase(0, 13);
  }
  if (message.starts_with("number overflow parsing ")) {
    message = "number overflow: " + message.substr(24) + " does not fit a double";
  }
  return shownText(message, 300);
}

}  // namespace

Result<json> parseJsonText(std::string_view text, std::string_view fileName) {
  json root;
  LocatingParser parser(root);
  bool ok = false;
  try {
    ok =
        json::sax_parse(text.begin(), text.end(), &parser, json::input_format_t::json, true, false);
  } catch (const std::bad_alloc&) {
    return Error(std::string(fileName), "too large: out of memory while reading the JSON document");
  } catch (const std::exception& e) {
    // Only resource limits get here (the parser reports everything else through parse_error).
    return Error(std::string(fileName), plainMessage(e.what()));
  }
  if (ok) return root;
  std::size_t offset = text.size();
  std::string message;
  if (parser.tooDeep()) {
    offset = tooDeepAt(text);
    message = "nested deeper than " + std::to_string(kMaxJsonDepth) + " arrays and objects";
  } else if (parser.failed()) {
    // The position counts characters read, the offending one included.
    offset = parser.position() == 0 ? 0 : parser.position() - 1;
    message = plainMessage(parser.message());
  } else {
    message = "not valid JSON";
  }
  if (offset > text.size()) offset = text.size();
  std::size_t line = 1;
  std::size_t lineStart = 0;
  for (std::size_t i = 0; i < offset; ++i) {
    if (text[i] == '\n') {
      ++line;
      lineStart = i + 1;
    }
  }
  Error error(std::string(fileName), line, offset - lineStart + 1,
              "column " + std::to_string(offset - lineStart + 1) + ": " + message);
  return error;
}

std::string dumpJson(const json& doc, int indent) {
  return doc.dump(indent, ' ', false, json::error_handler_t::replace);
}

}  // namespace tactile
