// A small database for GUI tests: one run simulated in the built-in scene "room1" (wall
// following, with truth), stored with its scene, in a fresh temporary folder.
#pragma once

#include <QTemporaryDir>

#include <memory>
#include <stdexcept>
#include <string>

#include "sim/recorder.h"
#include "sim/scene_source.h"
#include "sim/world.h"
#include "workspace/workspace.h"

namespace tactile::gui::testing {

struct GuiFixture {
  QTemporaryDir dir;
  std::string dbPath;
  std::unique_ptr<workspace::Workspace> workspace;
  std::string runName = "room1_demo";

  explicit GuiFixture(std::size_t steps = 600, const char* scene = "room1") {
    if (!dir.isValid()) throw std::runtime_error("no temporary folder");
    dbPath = dir.filePath(QStringLiteral("gui.db")).toStdString();
    auto opened = workspace::Workspace::open(dbPath);
    if (!opened) throw std::runtime_error(opened.errorText());
    workspace = std::move(opened.value());
    auto loaded = sim::loadScene(scene);
    if (!loaded) throw std::runtime_error(loaded.errorText());
    auto world = std::make_shared<const sim::World>(std::move(loaded.value()));
    sim::RunOptions options;
    options.maxSteps = steps;
    options.stopAtGoal = false;
    auto run = sim::simulateRun(world, scene, options);
    if (!run) throw std::runtime_error(run.errorText());
    const storage::ImportOutcome out = workspace->runStore().importRun(run.value().run, runName);
    if (out.status != storage::ImportStatus::Imported) throw std::runtime_error(out.message);
  }
};

}  // namespace tactile::gui::testing
