// The sweep request as options (shared by `tactile sweep` and `tactile sweep plan`), and the verbs
// of sweeps planned for workers: `sweep plan|work|status|submit` and `sweeps export`
// (cli_sweep_jobs.cpp, docs/cluster.md).
#pragma once

#include <CLI/CLI.hpp>

#include "workspace/workspace.h"

namespace tactile::cli {

// Every option of a sweep request but the data files (cli_learn.cpp).
void addSweepRequestOptions(CLI::App* cmd, workspace::SweepRequestText& request);
// The request the options ask for, through the one parser and check; a bad request is a
// UsageError in the check's words.
workspace::SweepRequest sweepRequestOrUsage(const workspace::SweepRequestText& text,
                                            workspace::SweepSource source);

// `sweep plan`, `sweep work`, `sweep status` and `sweep submit` under `sweep`.
void registerSweepJobVerbs(CLI::App& sweep);
// `sweeps export` under `sweeps`.
void registerSweepExportVerb(CLI::App& sweeps);

}  // namespace tactile::cli
