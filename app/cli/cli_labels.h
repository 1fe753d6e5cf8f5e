// Run files and the label files that label them, as the learning verbs read them: which label
// run each run file gets (matchLabelRuns). Plain functions of the CLI library, unit-tested.
#pragma once

#include <deque>
#include <string>
#include <vector>

#include "analysis/features.h"
#include "run/label_file.h"
#include "run/run.h"

namespace tactile::cli {

// Runs read from files, kept at stable addresses for LabelledRun pointers.
struct LoadedRuns {
  std::deque<RunData> runs;
  std::vector<std::string> paths;
  std::vector<analysis::LabelledRun> labelled;
};

// Reads every run; the first bad file is an error naming file and line.
void readRuns(const std::vector<std::string>& paths, LoadedRuns& out);

// A label file, CSV or JSON by its extension, through the one label-file reader: its segments
// and the provenance of its runs.
LabelFile readLabels(const std::string& path);

// The label run each loaded run file gets ("" for none; docs/analysis.md#label-files). A label run
// name matches a file by its path as given, its file name or its stem. With a provenance entry
// (step count and checksum of the run file) only files with that step count and that checksum of
// their bytes match, and a file that matches by name but not by content is an error naming both
// values. Two files matching one label run, or one file matching two, is an error naming them.
std::vector<std::string> matchLabelRuns(const LoadedRuns& loaded, const std::string& labelsPath,
                                        const LabelFile& file);

}  // namespace tactile::cli
