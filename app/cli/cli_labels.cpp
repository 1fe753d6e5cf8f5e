#include "app/cli/cli_labels.h"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <stdexcept>

#include "base/file_text.h"
#include "run/run_csv.h"
#include "storage/run_database.h"  // storage::checksumHex, the run-file checksum of label files

namespace tactile::cli {

void readRuns(const std::vector<std::string>& paths, LoadedRuns& out) {
  for (const std::string& path : paths) {
    RunCsvResult r = readRunCsv(path);
    if (!r.ok()) throw std::runtime_error(r.errorText());
    out.runs.push_back(std::move(r.value()));
    out.paths.push_back(path);
  }
}

LabelFile readLabels(const std::string& path) {
  const Result<std::string> read = readFileText(path);
  if (!read) throw std::runtime_error(read.errorText());
  const std::string& text = read.value();
  const bool json = std::filesystem::path(path).extension() == ".json";
  Result<LabelFile> parsed = json ? parseLabelJson(text, path) : parseLabelCsv(text, path);
  if (!parsed) throw std::runtime_error(parsed.errorText());
  return std::move(parsed.value());
}

std::vector<std::string> matchLabelRuns(const LoadedRuns& loaded, const std::string& labelsPath,
                                        const LabelFile& file) {
  std::vector<std::string> names;  // label runs in file order, each once
  auto note = [&](const std::string& name) {
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  };
  for (const LabelRecord& r : file.records)
    note(r.run);
  for (const LabelRunProvenance& p : file.runs)
    note(p.name);
  std::vector<std::string> checksums(loaded.runs.size());  // computed when first needed
  auto checksumOf = [&](std::size_t i) -> const std::string& {
    if (checksums[i].empty()) {
      const Result<std::string> text = readFileText(loaded.paths[i]);
      if (!text) throw std::runtime_error(text.errorText());
      checksums[i] = storage::checksumHex(text.value());
    }
    return checksums[i];
  };
  auto listed = [&](const std::vector<std::size_t>& files) {
    std::string out;
    for (std::size_t k = 0; k < files.size(); ++k) {
      out += (k == 0 ? "" : k + 1 == files.size() ? " and " : ", ") + loaded.paths[files[k]];
    }
    return out;
  };
  std::vector<std::string> nameOf(loaded.runs.size());
  for (const std::string& name : names) {
    std::vector<std::size_t> candidates;
    for (std::size_t i = 0; i < loaded.runs.size(); ++i) {
      const std::filesystem::path p(loaded.paths[i]);
      if (name == loaded.paths[i] || name == p.filename().string() || name == p.stem().string()) {
        candidates.push_back(i);
      }
    }
    if (candidates.empty()) continue;
    std::vector<std::size_t> matches = candidates;
    if (const LabelRunProvenance* p = findProvenance(file, name)) {
      matches.clear();
      std::string found;
      for (const std::size_t i : candidates) {
        const auto steps = static_cast<std::int64_t>(loaded.runs[i].stepCount());
        if (steps == p->steps && checksumOf(i) == p->checksum) matches.push_back(i);
        found += (found.empty() ? "" : "; ") + loaded.paths[i] + " has " + std::to_string(steps) +
                 " steps, checksum " + checksumOf(i);
      }
      if (matches.empty()) {
        throw std::runtime_error(labelsPath + ":" + std::to_string(p->line) + ": label run '" +
                                 name + "' was made for " + std::to_string(p->steps) +
                                 " steps, checksum " + p->checksum + ", but " + found +
                                 " (a different run of the same name)");
      }
    }
    if (matches.size() > 1) {
      throw std::runtime_error(labelsPath + ": label run '" + name + "' matches " +
                               listed(matches) +
                               "; give only one of them, or a label file with provenance lines "
                               "(tactile labels export) so the checksum tells them apart");
    }
    std::string& assigned = nameOf[matches.front()];
    if (!assigned.empty()) {
      throw std::runtime_error(labelsPath + ": run file " + loaded.paths[matches.front()] +
                               " matches two label runs, '" + assigned + "' and '" + name + "'");
    }
    assigned = name;
  }
  return nameOf;
}

}  // namespace tactile::cli
