#include "sim/run_csv.h"

namespace tactile {
// Placeholder while the reader is written.
std::string RunCsvError::toString() const { return file + ":" + std::to_string(line) + ": " + message; }
RunCsvResult parseRunCsv(std::string_view, std::string_view f, const ProgressFn&) { return RunCsvError{std::string(f), 0, {}, 0, "not implemented"}; }
RunCsvResult readRunCsv(const std::filesystem::path& p, const ProgressFn&) { return RunCsvError{p.string(), 0, {}, 0, "not implemented"}; }
std::string formatRunCsv(const RunData&) { return {}; }
std::string writeRunCsv(const RunData&, const std::filesystem::path&) { return "not implemented"; }
bool readFileText(const std::filesystem::path&, std::string&, std::string& e) { e = "not implemented"; return false; }
std::string writeFileAtomically(const std::filesystem::path&, std::string_view) { return "not implemented"; }
}  // namespace tactile
