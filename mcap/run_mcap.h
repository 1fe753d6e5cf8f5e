// A run as an MCAP file for Foxglove and Lichtblick (docs/interop.md), and back.
//
// Export: one message per step on JSON channels (`jsonschema` schemas, `json` messages): the
// tactile readings by group (/tactile), pose, command and blocked flag (/robot/state), the truth
// classes (/truth), each label set (/labels/SET), a model's online decisions
// (/decisions/MODEL), the x_ columns (/extra); the pose also as foxglove.PoseInFrame
// (/robot/pose, in metres, rounded to the micrometre) so the 3D panel draws the route, and the
// scene's walls as one foxglove.SceneUpdate (/scene). The run's metadata lines are the Metadata
// record `tactile.run`, in order; the record `tactile.export` says what the file is. Log times are
// step * dt.
//
// Import of such a file gives back the run value for value (numbers are written as the shortest
// text that reads back to the same double), so export -> import -> export-run reproduces the
// original run file byte for byte.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "base/error.h"
#include "mcap/writer.h"
#include "run/run.h"

namespace tactile::mcap {

inline constexpr std::string_view kRunMcapFormat = "tactile-mcap 1";
// Log times of a run without `dt` metadata use this step length (seconds).
inline constexpr double kDefaultExportDt = 0.1;
// The Foxglove topics (/robot/pose, /scene) are in metres; scene units are read as mm.
inline constexpr double kSceneUnitsPerMetre = 1000.0;

// One label set's classes on the run: classes[step * kGroupCount + group] is a ContactClass or
// -1 where the set has no segment; annotator[...] indexes `annotators` ("" for none).
struct LabelTrack {
  std::string set;
  std::vector<std::int8_t> classes;
  std::vector<std::uint16_t> annotator;
  std::vector<std::string> annotators;
};

// A model's decisions on the run, same layout as LabelTrack::classes (-1: undecided).
struct DecisionTrack {
  std::string model;
  std::string decision;  // "online", or the model's own decision when it has no online one
  std::vector<std::int8_t> classes;
};

struct RunExport {
  // The whole run; or, with `window`, its metadata and extra column names (its steps unused).
  const RunData* run = nullptr;
  // Optional: the steps a window at a time (a run of a million steps is never whole in memory).
  // Called with the first step not yet written; returns a run whose steps are that step and the
  // ones after it (at least one; the same columns). Valid until the next call. May throw.
  std::function<const RunData*(std::size_t first)> window;
  std::size_t steps = 0;  // with `window`: the run's step count
  bool truth = false;     // with `window`: whether the run has truth
  std::string name;
  std::optional<std::string> sceneJson;
  std::vector<LabelTrack> labels;
  std::vector<DecisionTrack> decisions;
  std::string library = "tactile";
};

// The MCAP file's bytes, built in memory. Throws only std::bad_alloc.
std::string writeRunMcap(const RunExport& what, WriterOptions options = {});

// Called every kProgressSteps steps and at the end with the steps written; false cancels.
using ExportProgress = std::function<bool(std::size_t done, std::size_t total)>;
inline constexpr std::size_t kProgressSteps = 8192;

// Streams the file to `sink` as its chunks are finished (the whole file is never in memory).
// Returns false when `progress` cancelled (the sink then holds part of a file). Throws
// std::bad_alloc and whatever the sink throws.
bool writeRunMcap(const RunExport& what, const Sink& sink, WriterOptions options = {},
                  const ExportProgress& progress = {});

// What an import of an MCAP file gives: the run, its name in the file (an export of this program;
// empty for a bag) and notes for the user.
struct McapRun {
  RunData run;
  std::string nameInFile;
  std::vector<std::string> warnings;
};

// Reads an MCAP export of this program (it holds the `tactile.export` Metadata record). Errors
// name the file and the byte offset. The run is not yet checked against the run-file rules
// (the caller imports it through the run-file reader).
Result<McapRun> readRunMcap(std::string_view bytes, const std::string& fileName);

// True when the bytes hold the Metadata record of an export of this program (a cheap look for
// the record at the start of the data section, as the exporter writes it).
bool looksLikeRunMcap(std::string_view bytes);

}  // namespace tactile::mcap
