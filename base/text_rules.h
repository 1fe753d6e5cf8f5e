// The rules every text that enters the product follows (docs/file-formats.md#names-and-text):
// UTF-8 validity, the one name rule for runs, label sets, models, sweeps and annotators, and how a
// message shows bytes it cannot print.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "base/error.h"

namespace tactile {

// The longest name, in bytes of UTF-8.
inline constexpr std::size_t kMaxNameBytes = 200;

// Offset of the first byte of `text` that does not belong to well-formed UTF-8 (RFC 3629: no
// overlong forms, no surrogates, nothing above U+10FFFF), or npos when it is all valid.
std::size_t invalidUtf8At(std::string_view text);

inline bool isValidUtf8(std::string_view text) {
  return invalidUtf8At(text) == std::string_view::npos;
}

// Why `name` cannot name a run, label set, model, sweep or annotator, or nullopt when it can. The
// rule: not empty, valid UTF-8, no control character (U+0000-U+001F, U+007F-U+009F; so no line
// break or tab), no comma, at most kMaxNameBytes bytes. The text says what is wrong and where
// ("holds a comma at byte 4"), without the name itself.
std::optional<std::string> nameProblem(std::string_view name);

// nameProblem as an error: "a WHAT name must ...: found 'NAME' (...)", the name shown with
// shownText. `what` is "run", "label set", "model", "sweep", "annotator".
Status checkName(std::string_view name, std::string_view what);

// A name made from a file's stem: commas and control characters become '_'. Invalid UTF-8 and
// over-long stems are left as they are (checkName then refuses them, so a file name that cannot
// be shown is never stored under a guess).
std::string nameFromFileStem(std::string_view stem);

// `text` for a message: bytes that are not well-formed UTF-8 and control characters written as
// "\xHH" (a form feed shows as "\x0C", never as nothing), everything else as it is; cut after
// `maxBytes` bytes of input with "...".
std::string shownText(std::string_view text, std::size_t maxBytes = 200);

// The most bytes of input a message quotes: a 10 MB line gives a short message, not a 10 MB one.
inline constexpr std::size_t kMaxQuotedBytes = 200;

// Input quoted in a message, the one way every reader does it: "'" + shownText(text,
// kMaxQuotedBytes) + "'", so at most kMaxQuotedBytes bytes of it, then "...".
std::string quotedInput(std::string_view text);

// `text` with every byte that is not part of well-formed UTF-8 replaced by U+FFFD, so that it can
// go into JSON or a terminal.
std::string validUtf8(std::string_view text);

}  // namespace tactile
