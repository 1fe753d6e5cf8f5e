#include "workspace/run_recording.h"

#include <algorithm>
#include <set>

#include "workspace/workspace.h"

namespace tactile::workspace {

Result<std::string> freeRunName(Workspace& workspace, const std::string& base) {
  Result<std::vector<storage::RunInfo>> runs = workspace.runStore().list();
  if (!runs) return runs.error();
  std::set<std::string> taken;
  for (const storage::RunInfo& info : runs.value())
    taken.insert(info.name);
  if (!taken.contains(base)) return base;
  for (int n = 2;; ++n) {
    std::string name = base + "_" + std::to_string(n);
    if (!taken.contains(name)) return name;
  }
}

Result<std::unique_ptr<RunRecording>> RunRecording::begin(Workspace& workspace,
                                                          const std::string& name,
                                                          const RunData& header, bool withTruth,
                                                          const storage::SceneResolver& resolver) {
  Result<std::int64_t> id = workspace.runStore().beginRun(name, header, withTruth, resolver);
  if (!id) return id.error();
  return std::unique_ptr<RunRecording>(new RunRecording(workspace, name, id.value()));
}

Status RunRecording::append(const RunData& run, std::size_t minSteps) {
  if (finished_) return Error("run '" + name_ + "' is finished; nothing more can be appended");
  const std::size_t steps = run.stepCount();
  if (steps < stored_) return Error("run '" + name_ + "' lost steps it had stored");
  if (steps == stored_ || steps - stored_ < std::max<std::size_t>(minSteps, 1)) {
    return Status::success();
  }
  Status written = workspace_.runStore().appendSteps(runId_, run, stored_);
  if (!written) return written;
  stored_ = steps;
  return Status::success();
}

Status RunRecording::finish(const RunData& run) {
  if (finished_) return Error("run '" + name_ + "' is finished already");
  Status done = workspace_.runStore().finishRun(runId_, run);
  if (!done) return done;
  stored_ = run.stepCount();
  finished_ = true;
  return Status::success();
}

}  // namespace tactile::workspace
