#include "run/json_text.h"

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <new>
#include <utility>

#include "base/text_rules.h"

namespace tactile {
namespace {

using json = nlohmann::json;

// A character iterator over the text that remembers the last character the JSON library read, so
// that the parser's callbacks know where in the text they are.
class TrackingIterator {
 public:
  using iterator_category = std::forward_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;

  TrackingIterator() = default;
  TrackingIterator(const char* p, const char** last) : p_(p), last_(last) {}
  reference operator*() const {
    *last_ = p_;
    return *p_;
  }
  TrackingIterator& operator++() {
    ++p_;
    return *this;
  }
  TrackingIterator operator++(int) {
    TrackingIterator old = *this;
    ++p_;
    return old;
  }
  bool operator==(const TrackingIterator& o) const { return p_ == o.p_; }
  bool operator!=(const TrackingIterator& o) const { return p_ != o.p_; }

 private:
  const char* p_ = nullptr;
  const char** last_ = nullptr;
};

// The standard DOM builder, plus where and why parsing stopped, duplicate keys refused, and (when
// asked) the line of every element.
class LocatingParser {
 public:
  LocatingParser(json& root, std::string_view text, JsonLines* lines)
      : dom_(root, false), text_(text), last_(text.data()), lines_(lines) {}

  const char** lastRead() { return &last_; }

  bool null() { return element(offsetNow()) && dom_.null(); }
  bool boolean(bool v) { return element(offsetNow()) && dom_.boolean(v); }
  bool number_integer(json::number_integer_t v) {
    const std::size_t end = numberEnd();
    if (!element(end)) return false;
    if (v == 0 && lines_ != nullptr && writtenNegative(end)) {
      lines_->negativeZeros.push_back(pointer());
    }
    return dom_.number_integer(v);
  }
  bool number_unsigned(json::number_unsigned_t v) {
    return element(numberEnd()) && dom_.number_unsigned(v);
  }
  bool number_float(json::number_float_t v, const json::string_t& s) {
    return element(numberEnd()) && dom_.number_float(v, s);
  }
  bool string(json::string_t& v) { return element(offsetNow()) && dom_.string(v); }
  bool binary(json::binary_t& v) { return dom_.binary(v); }
  bool start_object(std::size_t n) {
    if (!element(offsetNow()) || !deeper()) return false;
    frames_.push_back(Frame{true, kNone, {}, {}});
    return dom_.start_object(n);
  }
  bool key(json::string_t& v) {
    const std::size_t at = offsetNow();
    const std::size_t line = lineAt(at);
    Frame& f = frames_.back();
    if (const auto [it, added] = f.keys.emplace(v, line); !added) {
      failed_ = true;
      position_ = at + 1;
      message_ = "duplicate key " + quotedInput(v) + " (first on line " +
                 std::to_string(it->second) + "): a key may appear once in an object";
      duplicate_ = true;
      return false;
    }
    f.key = v;
    if (lines_ != nullptr) lines_->lines[pointer()] = line;
    return dom_.key(v);
  }
  bool end_object() {
    --depth_;
    frames_.pop_back();
    return dom_.end_object();
  }
  bool start_array(std::size_t n) {
    if (!element(offsetNow()) || !deeper()) return false;
    frames_.push_back(Frame{false, kNone, {}, {}});
    return dom_.start_array(n);
  }
  bool end_array() {
    --depth_;
    frames_.pop_back();
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
  bool duplicate() const { return duplicate_; }
  std::size_t position() const { return position_; }
  const std::string& message() const { return message_; }

 private:
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  struct Frame {
    bool object = false;
    std::size_t index = kNone;                          // arrays: the current element's index
    std::string key;                                    // objects: the current member's key
    std::unordered_map<std::string, std::size_t> keys;  // objects: keys seen, with their lines
  };

  std::size_t offsetNow() const { return static_cast<std::size_t>(last_ - text_.data()); }

  // A number is reported after the character that ends it has been read: the offset of its last
  // character.
  std::size_t numberEnd() const {
    std::size_t at = offsetNow();
    if (at > 0 && at < text_.size() &&
        std::string_view("0123456789.eE+-").find(text_[at]) == std::string_view::npos) {
      --at;
    }
    return at;
  }

  // Whether the integer ending at `end` was written with a minus sign.
  bool writtenNegative(std::size_t end) const {
    std::size_t i = end + 1;
    while (i > 0 && text_[i - 1] >= '0' && text_[i - 1] <= '9')
      --i;
    return i > 0 && text_[i - 1] == '-';
  }

  // A value starts at `at`: records its line (arrays count their elements). Always true.
  bool element(std::size_t at) {
    if (lines_ == nullptr) return true;
    if (frames_.empty()) {
      lines_->lines[""] = 1;
      return true;
    }
    Frame& f = frames_.back();
    if (f.object) return true;
    ++f.index;  // from kNone to 0 for the first element
    lines_->lines[pointer()] = lineAt(at);
    return true;
  }

  // The JSON pointer of the element being read.
  std::string pointer() const {
    std::string out;
    for (const Frame& f : frames_) {
      out += '/';
      if (!f.object) {
        out += std::to_string(f.index);
        continue;
      }
      for (char c : f.key) {
        if (c == '~') {
          out += "~0";
        } else if (c == '/') {
          out += "~1";
        } else {
          out += c;
        }
      }
    }
    return out;
  }

  // 1-based line of `offset`; offsets asked for never decrease by more than a token, so the count
  // moves forward from the last answer.
  std::size_t lineAt(std::size_t offset) {
    offset = std::min(offset, text_.size());
    while (counted_ < offset) {
      if (text_[counted_] == '\n') ++line_;
      ++counted_;
    }
    while (counted_ > offset) {
      --counted_;
      if (text_[counted_] == '\n') --line_;
    }
    return line_;
  }

  bool deeper() {
    if (++depth_ > kMaxJsonDepth) tooDeep_ = true;
    return !tooDeep_;
  }

  nlohmann::detail::json_sax_dom_parser<json> dom_;
  std::string_view text_;
  const char* last_;
  JsonLines* lines_;
  std::vector<Frame> frames_;
  std::size_t counted_ = 0;
  std::size_t line_ = 1;
  std::size_t depth_ = 0;
  bool tooDeep_ = false;
  bool failed_ = false;
  bool duplicate_ = false;
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
  // The text read last, quoted the one way (cut after kMaxQuotedBytes) rather than as it came.
  if (const std::size_t at = message.find("last read: '"); at != std::string::npos) {
    const std::size_t from = at + 12;
    const std::size_t to = message.rfind('\'');
    if (to != std::string::npos && to >= from) {
      message = message.substr(0, at) +
                "last read: " + quotedInput(std::string_view(message).substr(from, to - from));
      return message;
    }
  }
  return shownText(message, 2 * kMaxQuotedBytes);
}

// A JSON library type name in words.
std::string typeWords(std::string_view type) {
  if (type == "null") return "null";
  if (type == "object") return "an object";
  if (type == "array") return "an array";
  if (type == "string") return "a string";
  if (type == "boolean") return "true or false";
  if (type == "number") return "a number";
  return std::string(type);
}

}  // namespace

Result<json> parseJsonText(std::string_view text, std::string_view fileName, JsonLines* lines) {
  json root;
  if (lines != nullptr) *lines = JsonLines();
  LocatingParser parser(root, text, lines);
  bool ok = false;
  try {
    const TrackingIterator begin(text.data(), parser.lastRead());
    const TrackingIterator end(text.data() + text.size(), parser.lastRead());
    ok = json::sax_parse(begin, end, &parser, json::input_format_t::json, true, false);
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
  } else if (parser.duplicate()) {
    offset = parser.position() == 0 ? 0 : parser.position() - 1;
    message = parser.message();
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

std::string plainJsonError(const std::exception& e) {
  std::string message = e.what();
  if (message.starts_with("[json.exception.")) {
    const std::size_t end = message.find("] ");
    if (end != std::string::npos) message.erase(0, end + 2);
  }
  // "type must be number, but is string"
  if (message.starts_with("type must be ")) {
    const std::size_t but = message.find(", but is ");
    if (but != std::string::npos) {
      const std::string_view wanted = std::string_view(message).substr(13, but - 13);
      const std::string_view found = std::string_view(message).substr(but + 9);
      return "expected " + typeWords(wanted) + ", found " + typeWords(found);
    }
  }
  // "key 'cells' not found"
  if (message.starts_with("key '") && message.ends_with("' not found")) {
    return "missing key " + quotedInput(std::string_view(message).substr(5, message.size() - 16));
  }
  if (message.starts_with("cannot use operator[] with a string argument with ")) {
    return "expected an object, found " + typeWords(std::string_view(message).substr(50));
  }
  if (message.starts_with("array index ") && message.ends_with(" is out of range")) {
    return "the array is too short (" + message.substr(0, message.size() - 16) + " is missing)";
  }
  if (message.starts_with("parse error")) return plainMessage(message);
  return "unexpected content (" + shownText(message, kMaxQuotedBytes) + ")";
}

std::string dumpJson(const json& doc, int indent) {
  return doc.dump(indent, ' ', false, json::error_handler_t::replace);
}

}  // namespace tactile
