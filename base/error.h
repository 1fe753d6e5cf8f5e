// The one error type of the project and the result template every part returns: a value or an
// error, never both, never an exception across a part's public API.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <variant>

namespace tactile {

// What went wrong and where. `file` names the file the error is about (a run file, a label file,
// a database), empty when none; `line` and `column` are 1-based, 0 when not known. `message` says
// what was expected and what was found, without the file and line; where a column matters it names
// it in words too ("column 'n3' (position 10): ..."), so `column` is there for programs (a view
// that highlights the field), not for the text.
struct Error {
  std::string file;
  std::size_t line = 0;
  std::size_t column = 0;
  std::string message;

  Error() = default;
  explicit Error(std::string message_) : message(std::move(message_)) {}
  Error(std::string file_, std::string message_)
      : file(std::move(file_)), message(std::move(message_)) {}
  Error(std::string file_, std::size_t line_, std::size_t column_, std::string message_)
      : file(std::move(file_)), line(line_), column(column_), message(std::move(message_)) {}

  // "FILE:LINE: message", "FILE: message" or "message", as much as is known.
  std::string text() const {
    std::string out = file;
    if (!file.empty() && line > 0) out += ':' + std::to_string(line);
    if (!out.empty()) out += ": ";
    return out + message;
  }
};

// A value or an Error. Test with ok() (or in a condition), then take value() or error().
template <class T>
class [[nodiscard]] Result {
 public:
  Result(T value) : value_(std::move(value)) {}
  Result(Error error) : value_(std::move(error)) {}
  static Result failure(std::string message) { return Result(Error(std::move(message))); }

  bool ok() const { return value_.index() == 0; }
  explicit operator bool() const { return ok(); }
  T& value() { return std::get<0>(value_); }
  const T& value() const { return std::get<0>(value_); }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }
  const Error& error() const { return std::get<1>(value_); }
  // The error as one line of text ("FILE:LINE: message").
  std::string errorText() const { return error().text(); }

 private:
  std::variant<T, Error> value_;
};

// Success or an Error.
template <>
class [[nodiscard]] Result<void> {
 public:
  Result() = default;
  Result(Error error) : error_(std::move(error)), failed_(true) {}
  static Result success() { return {}; }
  static Result failure(std::string message) { return Result(Error(std::move(message))); }

  bool ok() const { return !failed_; }
  explicit operator bool() const { return ok(); }
  const Error& error() const { return error_; }
  std::string errorText() const { return error_.text(); }

 private:
  Error error_;
  bool failed_ = false;
};

using Status = Result<void>;

}  // namespace tactile
