// A run stored in the workspace's database while it is recorded (the workbench's simulator window
// records this way): begun with its metadata, its new steps written in chunks as they come, and
// finished with the outcome and the rest of the final metadata. Each write is one committed
// transaction, so a recorder that dies keeps the steps written so far as a readable run (outcome
// `unknown`). No Qt; the storage calls are RunDatabase::beginRun, appendSteps and finishRun.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "base/error.h"
#include "run/run.h"
#include "storage/run_database.h"

namespace tactile::workspace {

class Workspace;

// `base` if no run has that name, else `base_<n>` with the first free n >= 2.
Result<std::string> freeRunName(Workspace& workspace, const std::string& base);

class RunRecording {
 public:
  // Stores run `name` (must be free) with `header`'s metadata and no steps. `resolver` gives the
  // scene JSON for a scene value that is neither built in nor a file (e.g. a scene opened from a
  // file by the caller). The workspace must outlive the recording.
  static Result<std::unique_ptr<RunRecording>> begin(Workspace& workspace, const std::string& name,
                                                     const RunData& header, bool withTruth,
                                                     const storage::SceneResolver& resolver = {});

  // Writes the steps of `run` (the run so far; its first storedSteps() steps are the ones stored)
  // that are not stored yet, when at least `minSteps` of them wait (0: whatever waits).
  Status append(const RunData& run, std::size_t minSteps = 0);
  // Completes the run: the remaining steps, `run`'s metadata (outcome, subject, ...) and its final
  // truth. Nothing may be appended after.
  Status finish(const RunData& run);

  const std::string& name() const { return name_; }
  std::int64_t runId() const { return runId_; }
  std::size_t storedSteps() const { return stored_; }
  bool finished() const { return finished_; }

 private:
  RunRecording(Workspace& workspace, std::string name, std::int64_t runId)
      : workspace_(workspace), name_(std::move(name)), runId_(runId) {}

  Workspace& workspace_;
  std::string name_;
  std::int64_t runId_ = 0;
  std::size_t stored_ = 0;
  bool finished_ = false;
};

}  // namespace tactile::workspace
