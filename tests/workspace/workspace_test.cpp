// The workspace over one database: label edits undone and redone exactly, training from a stored
// label set (group skipping, the run splits, provenance, taken names), sweeps stored cell by cell
// (also when cancelled), classification of stored runs, and labels bound to runs by id.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "analysis/features.h"
#include "analysis/report.h"
#include "analysis/training.h"
#include "run/run_csv.h"
#include "tests/analysis/learn_test_data.h"
#include "tests/storage/storage_test_util.h"
#include "workspace/workspace.h"

namespace tactile::workspace {
namespace {

using nlohmann::json;
using storage::LabelSegment;
using storage::test::TempDir;

constexpr std::size_t kSteps = 400;

RunData labelledRun(std::uint64_t seed, std::size_t steps = kSteps) {
  RunData run = testdata::makeLabelledRun(steps, seed);
  run.metadata = {{"format", "tactile-run 1"}, {"subject", "sim"}, {"dt", "0.1"}};
  return run;
}

std::unique_ptr<Workspace> openWorkspace(const TempDir& dir) {
  auto ws = Workspace::open(dir / "w.db");
  EXPECT_TRUE(ws.ok()) << (ws.ok() ? "" : ws.errorText());
  return ws.ok() ? std::move(ws.value()) : nullptr;
}

// Stores a run and labels it from its truth columns into `set`; returns the run id.
std::int64_t addRun(Workspace& ws, const std::string& name, std::uint64_t seed,
                    const std::string& set = "truth") {
  const RunData run = labelledRun(seed);
  const storage::ImportOutcome out = ws.runStore().importRun(run, name);
  EXPECT_EQ(out.status, storage::ImportStatus::Imported) << out.message;
  if (!set.empty()) {
    auto n = ws.labelStore().autolabel(out.runId, set);
    EXPECT_TRUE(n.ok()) << (n.ok() ? "" : n.errorText());
  }
  return out.runId;
}

// One quick setting for every group.
analysis::GroupSettings quickSettings() {
  analysis::TrainSettings s;
  s.classifier.gmm.components = 1;
  s.classifier.gmm.varianceFloor = 0.01;
  s.classifier.gmm.maxIterations = 20;
  return analysis::GroupSettings::same(s);
}

// A segment as undo must give it back: range, class and annotator (ids may change).
using SegmentKey = std::tuple<std::int64_t, std::int64_t, ContactClass, std::string>;
std::vector<SegmentKey> keys(const std::vector<LabelSegment>& segments, SensorGroup group) {
  std::vector<SegmentKey> out;
  for (const LabelSegment& s : segments)
    if (s.group == group) out.emplace_back(s.firstStep, s.lastStep, s.cls, s.annotator);
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<SegmentKey> groupSegments(Workspace& ws, std::int64_t setId, std::int64_t runId,
                                      SensorGroup group) {
  auto segments = ws.labelStore().segments(setId, runId);
  EXPECT_TRUE(segments.ok()) << (segments.ok() ? "" : segments.errorText());
  return segments.ok() ? keys(segments.value(), group) : std::vector<SegmentKey>{};
}

// Applies an edit, then checks that undo gives exactly the group's segments before it and redo
// those after it (the whole group of the run, not only the edit's range).
template <typename Edit>
LabelEdit checkUndoRedo(Workspace& ws, std::int64_t setId, std::int64_t runId, SensorGroup group,
                        Edit&& edit) {
  const std::vector<SegmentKey> before = groupSegments(ws, setId, runId, group);
  Result<LabelEdit> applied = edit();
  EXPECT_TRUE(applied.ok()) << (applied.ok() ? "" : applied.errorText());
  if (!applied) return {};
  const std::vector<SegmentKey> after = groupSegments(ws, setId, runId, group);
  EXPECT_NE(before, after) << "the edit changed nothing";
  EXPECT_EQ(applied->runId, runId);
  EXPECT_EQ(applied->group, group);
  if (Status s = ws.undo(applied.value()); !s) ADD_FAILURE() << s.errorText();
  EXPECT_EQ(groupSegments(ws, setId, runId, group), before) << "undo";
  if (Status s = ws.redo(applied.value()); !s) ADD_FAILURE() << s.errorText();
  EXPECT_EQ(groupSegments(ws, setId, runId, group), after) << "redo";
  // And undo again after the redo.
  if (Status s = ws.undo(applied.value()); !s) ADD_FAILURE() << s.errorText();
  EXPECT_EQ(groupSegments(ws, setId, runId, group), before) << "undo after redo";
  if (Status s = ws.redo(applied.value()); !s) ADD_FAILURE() << s.errorText();
  return applied.value();
}

// ---- label edits --------------------------------------------------------------------------------

TEST(WorkspaceLabels, EditsAreUndoneAndRedoneExactly) {
  TempDir dir;
  auto ws = openWorkspace(dir);
  ASSERT_TRUE(ws);
  const std::int64_t runId = addRun(*ws, "edit_run", 5, "edits");
  const std::int64_t other = addRun(*ws, "other_run", 6, "edits");
  auto set = ws->labelStore().find("edits");
  ASSERT_TRUE(set.ok());
  const std::int64_t setId = set->id;
  const SensorGroup g = SensorGroup::Left;
  const std::vector<SegmentKey> otherBefore = groupSegments(*ws, setId, other, g);
  const std::vector<SegmentKey> otherGroupBefore =
      groupSegments(*ws, setId, runId, SensorGroup::Right);

  auto all = ws->labelStore().segments(setId, runId);
  ASSERT_TRUE(all.ok());
  std::vector<LabelSegment> segs;
  for (const LabelSegment& s : all.value())
    if (s.group == g) segs.push_back(s);
  ASSERT_GE(segs.size(), 4u);
  // A segment long enough to split.
  auto longOne = std::find_if(segs.begin(), segs.end(),
                              [](const LabelSegment& s) { return s.lastStep - s.firstStep >= 6; });
  ASSERT_NE(longOne, segs.end());
  const LabelSegment target = *longOne;

  // 1. A segment inside another splits it into three.
  LabelSegment inner;
  inner.run = "edit_run";
  inner.group = g;
  inner.firstStep = target.firstStep + 2;
  inner.lastStep = target.firstStep + 4;
  inner.cls = target.cls == ContactClass::DeadPath ? ContactClass::Wall : ContactClass::DeadPath;
  inner.annotator = "alice";
  const LabelEdit added =
      checkUndoRedo(*ws, setId, runId, g, [&] { return ws->addSegment(setId, inner); });
  ASSERT_EQ(added.before.size(), 1u);
  EXPECT_EQ(added.before[0].firstStep, target.firstStep);
  EXPECT_EQ(added.before[0].lastStep, target.lastStep);
  EXPECT_EQ(added.after.size(), 3u);
  ASSERT_NE(added.segmentId, 0);

  // 2. Changing it: class and range (now reaching into the rest of the split segment).
  auto current = ws->labelStore().segment(setId, added.segmentId);
  ASSERT_TRUE(current.ok());
  LabelSegment changed = current.value();
  changed.lastStep = target.lastStep - 1;
  changed.cls = ContactClass::Corner;
  changed.annotator = "bob";
  checkUndoRedo(*ws, setId, runId, g,
                [&] { return ws->changeSegment(setId, added.segmentId, changed); });

  // 3. Removing one.
  auto now = ws->labelStore().segments(setId, runId);
  ASSERT_TRUE(now.ok());
  std::int64_t removeId = 0;
  for (const LabelSegment& s : now.value())
    if (s.group == g && s.firstStep == segs.back().firstStep) removeId = s.id;
  ASSERT_NE(removeId, 0);
  const LabelEdit removed =
      checkUndoRedo(*ws, setId, runId, g, [&] { return ws->removeSegment(setId, removeId); });
  EXPECT_EQ(removed.before.size(), 1u);
  EXPECT_TRUE(removed.after.empty());

  // 4. A range over the boundary of two neighbouring segments trims both.
  now = ws->labelStore().segments(setId, runId);
  ASSERT_TRUE(now.ok());
  std::vector<LabelSegment> current2;
  for (const LabelSegment& s : now.value())
    if (s.group == g) current2.push_back(s);
  std::sort(current2.begin(), current2.end(),
            [](const LabelSegment& a, const LabelSegment& b) { return a.firstStep < b.firstStep; });
  std::size_t k = 0;
  while (k + 1 < current2.size() && !(current2[k].lastStep + 1 == current2[k + 1].firstStep &&
                                      current2[k].lastStep > current2[k].firstStep &&
                                      current2[k + 1].lastStep > current2[k + 1].firstStep)) {
    ++k;
  }
  ASSERT_LT(k + 1, current2.size()) << "no two neighbouring segments of two steps or more";
  LabelSegment across;
  across.runId = runId;
  across.group = g;
  across.firstStep = current2[k].lastStep;
  across.lastStep = current2[k + 1].firstStep;
  across.cls = ContactClass::LeavingWall;
  across.annotator = "carol";
  const LabelEdit spanning =
      checkUndoRedo(*ws, setId, runId, g, [&] { return ws->addSegment(setId, across); });
  EXPECT_EQ(spanning.before.size(), 2u);
  EXPECT_EQ(spanning.after.size(), 3u);

  // Nothing else moved: the other run and the other groups.
  EXPECT_EQ(groupSegments(*ws, setId, other, g), otherBefore);
  EXPECT_EQ(groupSegments(*ws, setId, runId, SensorGroup::Right), otherGroupBefore);
}

// An undo stack: overlapping edits undone newest first give back the start, redone oldest first
// the end; a change that moves a segment elsewhere is undone too.
TEST(WorkspaceLabels, OverlappingEditsUndoneAsAStack) {
  TempDir dir;
  auto ws = openWorkspace(dir);
  ASSERT_TRUE(ws);
  const std::int64_t runId = addRun(*ws, "stack_run", 8, "stack");
  auto set = ws->labelStore().find("stack");
  ASSERT_TRUE(set.ok());
  const std::int64_t setId = set->id;
  const SensorGroup g = SensorGroup::Front;
  const std::vector<SegmentKey> start = groupSegments(*ws, setId, runId, g);

  std::vector<LabelEdit> stack;
  std::vector<std::vector<SegmentKey>> states{start};
  auto push = [&](Result<LabelEdit> edit) {
    ASSERT_TRUE(edit.ok()) << edit.errorText();
    stack.push_back(edit.value());
    states.push_back(groupSegments(*ws, setId, runId, g));
  };
  LabelSegment s;
  s.runId = runId;
  s.group = g;
  s.annotator = "ann";
  s.firstStep = 30;
  s.lastStep = 90;
  s.cls = ContactClass::DeadPath;
  push(ws->addSegment(setId, s));
  s.firstStep = 80;
  s.lastStep = 150;
  s.cls = ContactClass::Corner;
  push(ws->addSegment(setId, s));
  const std::int64_t moved = stack.back().segmentId;
  // Moved far away: the old place is left unlabelled, the new one taken over.
  s.firstStep = 300;
  s.lastStep = 320;
  push(ws->changeSegment(setId, moved, s));
  push(ws->removeSegment(setId, stack.front().segmentId));
  for (std::size_t i = 1; i < states.size(); ++i)
    EXPECT_NE(states[i], states[i - 1]) << "edit " << i << " changed nothing";

  for (std::size_t i = stack.size(); i-- > 0;) {
    ASSERT_TRUE(ws->undo(stack[i]).ok());
    EXPECT_EQ(groupSegments(*ws, setId, runId, g), states[i]) << "undo of edit " << i;
  }
  EXPECT_EQ(groupSegments(*ws, setId, runId, g), start);
  for (std::size_t i = 0; i < stack.size(); ++i) {
    ASSERT_TRUE(ws->redo(stack[i]).ok());
    EXPECT_EQ(groupSegments(*ws, setId, runId, g), states[i + 1]) << "redo of edit " << i;
  }
}

// ---- training -----------------------------------------------------------------------------------

// Five runs whose names sort differently from the order they are stored in.
struct TrainFixture {
  TempDir dir;
  std::unique_ptr<Workspace> ws;
  std::vector<std::string> names{"run_e", "run_a", "run_d", "run_b", "run_c"};
  TrainFixture() {
    ws = openWorkspace(dir);
    std::uint64_t seed = 40;
    for (const std::string& n : names)
      addRun(*ws, n, ++seed);
  }
};

std::vector<std::string> sortedNames(std::vector<std::string> v) {
  std::sort(v.begin(), v.end());
  return v;
}

TEST(WorkspaceTrain, GroupWithTooFewRowsIsSkippedOthersTrain) {
  TrainFixture f;
  ASSERT_TRUE(f.ws);
  workspace::Workspace& db = *f.ws;
  auto truth = db.labelStore().find("truth");
  ASSERT_TRUE(truth.ok());
  auto sparse = db.labelStore().copy(truth->id, "sparse");
  ASSERT_TRUE(sparse.ok());
  // Group Left keeps only five labelled Wall steps of one run.
  const SensorGroup thin = SensorGroup::Left;
  for (const std::string& n : f.names) {
    auto info = db.runStore().find(n);
    ASSERT_TRUE(info.ok());
    std::vector<LabelSegment> keep;
    if (n == "run_a") {
      auto run = f.ws->loadRun(n);
      ASSERT_TRUE(run.ok());
      std::size_t t = 0;
      while (t < run->stepCount() && run->truthAt(t, thin) != ContactClass::Wall)
        ++t;
      ASSERT_LT(t + 5, run->stepCount());
      LabelSegment s;
      s.group = thin;
      s.firstStep = static_cast<std::int64_t>(t);
      s.lastStep = static_cast<std::int64_t>(t + 4);
      s.cls = ContactClass::Wall;
      keep.push_back(s);
    }
    ASSERT_TRUE(
        db.labelStore()
            .replaceSegmentsInRange(sparse.value(), info->id, thin, 0, info->stepCount - 1, keep)
            .ok());
  }
  TrainRequest request;
  request.labelSet = "sparse";
  request.groups = {SensorGroup::Front, thin, SensorGroup::Right};
  request.settings = quickSettings();
  auto outcome = f.ws->train(request);
  ASSERT_TRUE(outcome.ok()) << outcome.errorText();
  ASSERT_EQ(outcome->groups.size(), 3u);
  const GroupTrainReport& skipped = outcome->groups[1];
  EXPECT_EQ(skipped.group, thin);
  EXPECT_FALSE(skipped.trained);
  // Five steps of run_a, unless run_a was held out for testing (it is not: run_d is).
  EXPECT_EQ(skipped.samplesTrain, 5u);
  EXPECT_NE(skipped.skippedBecause.find("5 labelled contact rows"), std::string::npos)
      << skipped.skippedBecause;
  EXPECT_NE(skipped.skippedBecause.find("20"), std::string::npos) << skipped.skippedBecause;
  for (std::size_t i : {0u, 2u}) {
    EXPECT_TRUE(outcome->groups[i].trained) << outcome->groups[i].skippedBecause;
    EXPECT_GT(outcome->groups[i].samplesTest, 0u);
    ASSERT_TRUE(outcome->groups[i].accuracy.has_value());
    EXPECT_GT(*outcome->groups[i].accuracy, 0.8);
  }
  EXPECT_EQ(outcome->bundle.models.size(), 2u);
  for (const analysis::GroupModel& m : outcome->bundle.models)
    EXPECT_NE(m.group, thin);

  // Below a lower minimum the count is no longer the reason, but five rows of one class still
  // give fewer than two classes to model; with no group left, training is an error naming why.
  request.minRowsPerGroup = 4;
  request.groups = {thin};
  request.modelName = "thin";
  auto low = f.ws->train(request);
  ASSERT_FALSE(low.ok());
  EXPECT_NE(low.errorText().find("L"), std::string::npos) << low.errorText();
  EXPECT_NE(low.errorText().find("fewer than two classes"), std::string::npos) << low.errorText();
  auto models = f.ws->models();
  ASSERT_TRUE(models.ok());
  EXPECT_EQ(models->size(), 1u);
}

TEST(WorkspaceTrain, RequestedTestRunsAreNotTrainedOn) {
  TrainFixture f;
  ASSERT_TRUE(f.ws);
  TrainRequest request;
  request.labelSet = "truth";
  request.testRuns = {"run_b", "run_e"};
  request.groups = {SensorGroup::Front};
  request.settings = quickSettings();
  auto outcome = f.ws->train(request);
  ASSERT_TRUE(outcome.ok()) << outcome.errorText();
  EXPECT_EQ(outcome->trainRuns, (std::vector<std::string>{"run_a", "run_c", "run_d"}));
  EXPECT_EQ(outcome->testRuns, (std::vector<std::string>{"run_b", "run_e"}));
  EXPECT_EQ(outcome->evaluatedOn, "test runs");
  std::set<std::string> trained;
  for (const json& r : outcome->provenance["train_runs"])
    trained.insert(r["name"].get<std::string>());
  EXPECT_EQ(trained.count("run_b"), 0u);
  EXPECT_EQ(trained.count("run_e"), 0u);
  EXPECT_EQ(trained.size(), 3u);

  // Test rows are exactly the contact rows of the test runs.
  std::size_t testRows = 0, trainRows = 0;
  for (const std::string& n : f.names) {
    auto run = f.ws->loadRun(n);
    ASSERT_TRUE(run.ok());
    for (std::size_t t = 0; t < run->stepCount(); ++t) {
      if (analysis::groupIsZero(run.value(), t, SensorGroup::Front)) continue;
      (n == "run_b" || n == "run_e" ? testRows : trainRows) += 1;
    }
  }
  EXPECT_EQ(outcome->groups[0].samplesTest, testRows);
  EXPECT_EQ(outcome->groups[0].samplesTrain, trainRows);

  // A run given both ways is refused.
  request.trainRuns = {"run_a", "run_b"};
  request.testRuns = {"run_b"};
  EXPECT_FALSE(f.ws->train(request).ok());
}

TEST(WorkspaceTrain, AutomaticSplitHoldsOutEveryFourthRunByName) {
  TrainFixture f;
  ASSERT_TRUE(f.ws);
  TrainRequest request;
  request.labelSet = "truth";
  request.groups = {SensorGroup::Right};
  request.settings = quickSettings();
  auto outcome = f.ws->train(request);
  ASSERT_TRUE(outcome.ok()) << outcome.errorText();
  // Sorted by name: run_a run_b run_c run_d run_e; the fourth is held out.
  EXPECT_EQ(outcome->testRuns, (std::vector<std::string>{"run_d"}));
  EXPECT_EQ(outcome->trainRuns, (std::vector<std::string>{"run_a", "run_b", "run_c", "run_e"}));
  EXPECT_EQ(outcome->evaluatedOn, "test runs");

  // Eight runs: the fourth and the eighth.
  std::uint64_t seed = 60;
  for (const char* n : {"run_f", "run_g", "run_h"})
    addRun(*f.ws, n, ++seed);
  auto eight = f.ws->train(request);
  ASSERT_TRUE(eight.ok()) << eight.errorText();
  EXPECT_EQ(eight->testRuns, (std::vector<std::string>{"run_d", "run_h"}));
  EXPECT_EQ(eight->trainRuns.size(), 6u);

  // Two runs: at least one is held out (the last by name).
  for (const char* n : {"run_e", "run_a"}) {
    auto info = f.ws->runStore().find(n);
    ASSERT_TRUE(info.ok());
    ASSERT_TRUE(f.ws->labelStore().autolabel(info->id, "pair").ok());
  }
  request.labelSet = "pair";
  auto two = f.ws->train(request);
  ASSERT_TRUE(two.ok()) << two.errorText();
  EXPECT_EQ(two->trainRuns, (std::vector<std::string>{"run_a"}));
  EXPECT_EQ(two->testRuns, (std::vector<std::string>{"run_e"}));
}

TEST(WorkspaceTrain, LeaveOneRunOutScoresEveryLabelledContactRow) {
  TrainFixture f;
  ASSERT_TRUE(f.ws);
  TrainRequest request;
  request.labelSet = "truth";
  request.split = SplitMode::LeaveOneRunOut;
  request.groups = {SensorGroup::Front, SensorGroup::RearRightCorner};
  request.settings = quickSettings();
  auto outcome = f.ws->train(request);
  ASSERT_TRUE(outcome.ok()) << outcome.errorText();
  EXPECT_EQ(outcome->evaluatedOn, "leave-one-run-out");
  EXPECT_TRUE(outcome->testRuns.empty());
  EXPECT_EQ(outcome->trainRuns, sortedNames(f.names));
  ASSERT_EQ(outcome->groups.size(), 2u);
  for (const GroupTrainReport& r : outcome->groups) {
    std::size_t contactRows = 0;
    for (const std::string& n : f.names) {
      auto run = f.ws->loadRun(n);
      ASSERT_TRUE(run.ok());
      for (std::size_t t = 0; t < run->stepCount(); ++t)
        contactRows += analysis::groupIsZero(run.value(), t, r.group) ? 0 : 1;
    }
    ASSERT_TRUE(r.trained) << r.skippedBecause;
    EXPECT_GT(contactRows, 0u);
    EXPECT_EQ(r.samplesTest, contactRows) << groupInfo(r.group).shortName;
    EXPECT_EQ(r.samplesTrain, contactRows);
    ASSERT_TRUE(r.accuracy.has_value());
    EXPECT_GT(*r.accuracy, 0.8);
  }
  // The stored model is trained on every run.
  EXPECT_EQ(outcome->provenance["train_runs"].size(), f.names.size());
  EXPECT_TRUE(outcome->provenance["test_runs"].empty());
  EXPECT_EQ(outcome->provenance["split"], "leave-one-run-out");
  // Test runs with leave-one-run-out are refused.
  request.testRuns = {"run_a"};
  EXPECT_FALSE(f.ws->train(request).ok());
}

// Labels from a model: each run and group takes the model's offline decision, marked
// "model:NAME" in the segments and the history; a range replaces only its steps, and undo
// restores exactly.
TEST(WorkspaceLabels, ModelLabelsAreTheOfflineDecisionAndUndoable) {
  TrainFixture f;
  ASSERT_TRUE(f.ws);
  TrainRequest request;
  request.labelSet = "truth";
  request.groups = {SensorGroup::Back, SensorGroup::Front};
  request.settings = quickSettings();
  request.modelName = "m";
  auto trained = f.ws->train(request);
  ASSERT_TRUE(trained.ok()) << trained.errorText();

  auto done = f.ws->labelFromModel("auto", "m", {"run_a", "run_b"}, {});
  ASSERT_TRUE(done.ok()) << done.errorText();
  EXPECT_EQ(done->runs, 2);
  EXPECT_EQ(done->groups, 4);  // the two groups the model covers, in each run
  EXPECT_TRUE(done->warnings.empty());
  const auto set = f.ws->labelStore().find("auto");
  ASSERT_TRUE(set.ok());
  analysis::ClassifyOptions offline;
  offline.decision = analysis::DecisionMode::Offline;
  auto classified = f.ws->classify("m", "run_a", offline);
  ASSERT_TRUE(classified.ok()) << classified.errorText();
  const std::int64_t run = f.ws->runStore().find("run_a")->id;
  const auto stored = f.ws->labelStore().segments(set->id, run).value();
  std::size_t checked = 0;
  for (const LabelSegment& seg : stored) {
    EXPECT_EQ(seg.annotator, "model:m");
    EXPECT_TRUE(seg.group == SensorGroup::Back || seg.group == SensorGroup::Front);
    const auto& g = classified->result.groups[static_cast<std::size_t>(groupIndex(seg.group))];
    for (std::int64_t k = seg.firstStep; k <= seg.lastStep; ++k, ++checked) {
      ASSERT_EQ(g.className(static_cast<std::size_t>(k)), contactClassName(seg.cls)) << k;
    }
  }
  EXPECT_EQ(checked, 2 * kSteps);  // every step of both groups was decided
  const auto history = f.ws->labelStore().history(set->id, run).value();
  ASSERT_EQ(history.size(), 2u);
  EXPECT_EQ(history[0].annotator, "model:m");
  EXPECT_EQ(history[0].action, "model");

  // A range: only its steps change; undo and redo exactly.
  std::vector<LabelSegment> corner(1);
  corner[0].group = SensorGroup::Front;
  corner[0].firstStep = 100;
  corner[0].lastStep = 149;
  corner[0].cls = ContactClass::Corner;
  corner[0].annotator = "model:m";
  const auto outside = groupSegments(*f.ws, set->id, run, SensorGroup::Front);
  const LabelEdit edit = checkUndoRedo(*f.ws, set->id, run, SensorGroup::Front, [&] {
    return f.ws->replaceLabels(set->id, run, SensorGroup::Front, 100, 149, corner);
  });
  for (const SegmentKey& k : groupSegments(*f.ws, set->id, run, SensorGroup::Front)) {
    if (std::get<1>(k) < 100 || std::get<0>(k) > 149) {
      // Outside the range: a piece of what was there before.
      EXPECT_TRUE(std::any_of(outside.begin(), outside.end(), [&](const SegmentKey& o) {
        return std::get<0>(o) <= std::get<0>(k) && std::get<1>(k) <= std::get<1>(o) &&
               std::get<2>(o) == std::get<2>(k);
      }));
    } else {
      EXPECT_EQ(std::get<2>(k), ContactClass::Corner);
    }
  }
  EXPECT_GT(edit.revision, history.back().revision);
  // A group the model lacks is named, and an unknown model changes nothing.
  auto lacking = f.ws->labelFromModel("auto", "m", {"run_a"}, {SensorGroup::Left});
  ASSERT_TRUE(lacking.ok());
  ASSERT_EQ(lacking->warnings.size(), 1u);
  EXPECT_EQ(lacking->groups, 0);
  EXPECT_FALSE(f.ws->labelFromModel("auto", "nope", {}, {}).ok());
}

TEST(WorkspaceTrain, StoredModelNamesItsProvenance) {
  TrainFixture f;
  ASSERT_TRUE(f.ws);
  TrainRequest request;
  request.labelSet = "truth";
  request.groups = {SensorGroup::Back};
  request.settings = quickSettings();
  request.settings.of(SensorGroup::Back).classifier.gmm.seed = 77;
  auto outcome = f.ws->train(request);
  ASSERT_TRUE(outcome.ok()) << outcome.errorText();
  EXPECT_EQ(outcome->modelName, "truth-1");
  auto models = f.ws->models();
  ASSERT_TRUE(models.ok());
  ASSERT_EQ(models->size(), 1u);
  const storage::ModelInfo& m = models->front();
  EXPECT_EQ(m.name, "truth-1");
  EXPECT_EQ(m.id, outcome->modelId);
  const json p = json::parse(m.trainedOnJson);
  EXPECT_EQ(p["label_set"], "truth");
  EXPECT_EQ(p["split"], "by-run");
  EXPECT_EQ(p["program_version"], std::string(programVersion()));
  EXPECT_FALSE(std::string(programVersion()).empty());
  // The bundle's provenance holds each trained group's settings; each model its own.
  ASSERT_TRUE(p["settings"].is_object());
  EXPECT_EQ(p["settings"].size(), 1u);
  EXPECT_EQ(p["settings"]["B"]["seed"], 77);
  EXPECT_EQ(p["settings"]["B"]["method"], "gmm");
  EXPECT_EQ(p["settings"]["B"]["order"], 1);
  EXPECT_EQ(p["settings"]["B"]["features"], "normal");
  ASSERT_EQ(outcome->bundle.models.size(), 1u);
  EXPECT_EQ(provenanceToJson(outcome->bundle.models.front())["settings"], p["settings"]["B"]);
  std::set<std::string> named;
  for (const char* key : {"train_runs", "test_runs"}) {
    ASSERT_TRUE(p[key].is_array()) << key;
    for (const json& r : p[key]) {
      const std::string name = r["name"].get<std::string>();
      named.insert(name);
      auto info = f.ws->runStore().find(name);
      ASSERT_TRUE(info.ok()) << name;
      EXPECT_EQ(r["steps"], info->stepCount);
      EXPECT_EQ(r["steps"], static_cast<std::int64_t>(kSteps));
      EXPECT_EQ(r["checksum"], info->checksum);
      EXPECT_EQ(r["checksum"].get<std::string>().size(), 16u);
    }
  }
  EXPECT_EQ(named, std::set<std::string>(f.names.begin(), f.names.end()));
  EXPECT_EQ(p["test_runs"].size(), 1u);
  // The metrics are stored too, and the bundle's models carry the same provenance with their own
  // group's settings.
  const json metrics = json::parse(m.metricsJson);
  EXPECT_TRUE(metrics.contains("B")) << m.metricsJson;
  auto bundle = f.ws->loadModel("truth-1");
  ASSERT_TRUE(bundle.ok()) << bundle.errorText();
  ASSERT_EQ(bundle->models.size(), 1u);
  const json own = provenanceToJson(bundle->models[0]);
  for (const char* key : {"label_set", "split", "program_version", "train_runs", "test_runs"})
    EXPECT_EQ(own[key], p[key]) << key;
  EXPECT_EQ(own["settings"], p["settings"]["B"]);
  // The next automatic name is the next free number.
  auto second = f.ws->train(request);
  ASSERT_TRUE(second.ok());
  EXPECT_EQ(second->modelName, "truth-2");
}

// One training recipe: the same runs and labels trained from files (the core function the file
// form of `tactile train` calls) and from the database give the same model and the same scores,
// and the model exported from the database reports them.
void filesAndDatabaseAgree(analysis::ClassifierMethod method) {
  TrainFixture f;
  ASSERT_TRUE(f.ws);
  TrainRequest request;
  request.labelSet = "truth";
  request.trainRuns = {"run_a", "run_b", "run_c"};
  request.testRuns = {"run_d"};
  request.groups = {SensorGroup::Front, SensorGroup::Right};
  request.settings = quickSettings();
  for (analysis::TrainSettings& s : request.settings.byGroup) {
    s.classifier.method = method;
    s.classifier.gbt.trees = 15;
  }
  auto stored = f.ws->train(request);
  ASSERT_TRUE(stored.ok()) << stored.errorText();

  // The same runs as files would give them: the generator's runs with labels from their truth.
  std::vector<RunData> runs;
  for (std::uint64_t seed : {42u, 44u, 45u, 43u})
    runs.push_back(labelledRun(seed));  // a,b,c,d
  analysis::TrainJob job;
  for (std::size_t i = 0; i < 3; ++i)
    job.runs.push_back({&runs[i], analysis::labelsFromTruth(runs[i])});
  job.testRuns = {{&runs[3], analysis::labelsFromTruth(runs[3])}};
  job.groups = request.groups;
  job.settings = request.settings;
  auto files = analysis::trainAndEvaluate(job);
  ASSERT_TRUE(files.ok()) << files.errorText();

  ASSERT_EQ(files->bundle.models.size(), stored->bundle.models.size());
  auto exported = f.ws->loadModel(stored->modelName);
  ASSERT_TRUE(exported.ok());
  for (std::size_t i = 0; i < files->bundle.models.size(); ++i) {
    const analysis::GroupModel& a = files->bundle.models[i];
    const analysis::GroupModel& b = exported->models[i];
    EXPECT_EQ(a.group, b.group);
    EXPECT_EQ(a.classifier.trees() != nullptr, method == analysis::ClassifierMethod::Gbt);
    EXPECT_EQ(analysis::modelToJson(a)["components"], analysis::modelToJson(b)["components"]);
    EXPECT_EQ(analysis::modelToJson(a)["gbt"], analysis::modelToJson(b)["gbt"]);
    EXPECT_EQ(analysis::modelToJson(a)["transitions"], analysis::modelToJson(b)["transitions"]);
    EXPECT_GT(a.evaluation.samplesTest(), 0u);
    EXPECT_EQ(a.evaluation.byDecision, b.evaluation.byDecision);
    for (analysis::DecisionMode d : analysis::kDecisionModes)
      EXPECT_EQ(a.evaluation.balancedAccuracy(d), b.evaluation.balancedAccuracy(d));
  }
  // The report of the exported bundle shows the scores (not blanks).
  const std::string report = analysis::modelReport(exported.value(), analysis::TableStyle::Csv);
  const double ba =
      *exported->models[0].evaluation.balancedAccuracy(analysis::DecisionMode::Online);
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", 100.0 * ba);
  EXPECT_NE(report.find(text), std::string::npos) << report;
  EXPECT_EQ(report.find("no test data"), std::string::npos) << report;
}

TEST(WorkspaceTrain, FilesAndDatabaseGiveTheSameModelAndScores) {
  filesAndDatabaseAgree(analysis::ClassifierMethod::Gmm);
}

TEST(WorkspaceTrain, FilesAndDatabaseGiveTheSameTreesAndScores) {
  filesAndDatabaseAgree(analysis::ClassifierMethod::Gbt);
}

// By scene: runs of two scenes, each scored by a model trained on the other.
TEST(WorkspaceTrain, BySceneScoresEachSceneWithoutIt) {
  TempDir dir;
  auto ws = openWorkspace(dir);
  ASSERT_TRUE(ws);
  std::uint64_t seed = 70;
  for (const char* scene : {"room1", "room1", "room2", "room2"}) {
    RunData run = labelledRun(++seed);
    run.setMeta("scene", scene);
    const storage::ImportOutcome out =
        ws->runStore().importRun(run, std::string(scene) + "_" + std::to_string(seed));
    ASSERT_EQ(out.status, storage::ImportStatus::Imported) << out.message;
    ASSERT_TRUE(ws->labelStore().autolabel(out.runId, "truth").ok());
  }
  TrainRequest request;
  request.labelSet = "truth";
  request.split = SplitMode::ByScene;
  request.groups = {SensorGroup::Left};
  request.settings = quickSettings();
  auto outcome = ws->train(request);
  ASSERT_TRUE(outcome.ok()) << outcome.errorText();
  const analysis::ModelEvaluation& e = outcome->bundle.models.front().evaluation;
  ASSERT_EQ(e.scenes.size(), 2u);
  EXPECT_EQ(e.evaluatedOn, "leave-one-scene-out");
  EXPECT_GT(e.scenes[0].byDecision[0].total(), 0u);
  EXPECT_EQ(e.scenes[0].byDecision[0].total() + e.scenes[1].byDecision[0].total(), e.samplesTest());
  ASSERT_TRUE(outcome->groups.front().sceneMean.has_value());
  // Test runs are refused with by-scene.
  request.testRuns = {"room1_71"};
  EXPECT_FALSE(ws->train(request).ok());
}

TEST(WorkspaceTrain, TakenModelNameFailsBeforeTraining) {
  TrainFixture f;
  ASSERT_TRUE(f.ws);
  TrainRequest request;
  request.labelSet = "truth";
  request.groups = {SensorGroup::Front};
  request.settings = quickSettings();
  request.modelName = "mine";
  ASSERT_TRUE(f.ws->train(request).ok());
  auto before = f.ws->models();
  ASSERT_TRUE(before.ok());
  ASSERT_EQ(before->size(), 1u);

  std::size_t progressCalls = 0;
  auto again = f.ws->train(request, [&](std::size_t, std::size_t) {
    ++progressCalls;
    return true;
  });
  ASSERT_FALSE(again.ok());
  EXPECT_NE(again.errorText().find("'mine'"), std::string::npos) << again.errorText();
  EXPECT_NE(again.errorText().find("already"), std::string::npos) << again.errorText();
  EXPECT_EQ(progressCalls, 0u) << "training started before the name was checked";
  auto after = f.ws->models();
  ASSERT_TRUE(after.ok());
  ASSERT_EQ(after->size(), 1u);
  EXPECT_EQ(after->front().id, before->front().id);
  EXPECT_EQ(after->front().createdAt, before->front().createdAt);
  EXPECT_EQ(after->front().trainedOnJson, before->front().trainedOnJson);
}

// Training cancelled through the progress callback stores no model.
TEST(WorkspaceTrain, CancelledTrainingStoresNothing) {
  TrainFixture f;
  ASSERT_TRUE(f.ws);
  TrainRequest request;
  request.labelSet = "truth";
  request.groups = {SensorGroup::Front, SensorGroup::Right};
  request.settings = quickSettings();
  std::size_t calls = 0;
  auto outcome = f.ws->train(request, [&](std::size_t, std::size_t) { return ++calls < 2; });
  ASSERT_FALSE(outcome.ok());
  EXPECT_NE(outcome.errorText().find("cancelled"), std::string::npos) << outcome.errorText();
  EXPECT_EQ(calls, 2u);
  auto models = f.ws->models();
  ASSERT_TRUE(models.ok());
  EXPECT_TRUE(models->empty());
}

// Deleting models: all named or none; a name given twice is one model, not an unknown name.
TEST(WorkspaceTrain, ModelsDeletedByNameAllOrNone) {
  TrainFixture f;
  ASSERT_TRUE(f.ws);
  TrainRequest request;
  request.labelSet = "truth";
  request.groups = {SensorGroup::Front};
  request.settings = quickSettings();
  for (const char* name : {"m1", "m2"}) {
    request.modelName = name;
    ASSERT_TRUE(f.ws->train(request).ok());
  }
  workspace::Workspace& db = *f.ws;
  const Status unknown = db.modelStore().remove({"m1", "nope"});
  ASSERT_FALSE(unknown.ok());
  EXPECT_NE(unknown.errorText().find("'nope'"), std::string::npos) << unknown.errorText();
  auto models = f.ws->models();
  ASSERT_TRUE(models.ok());
  EXPECT_EQ(models->size(), 2u) << "a failed delete removed a model";
  const Status twice = db.modelStore().remove({"m1", "m1"});
  EXPECT_TRUE(twice.ok()) << twice.errorText();
  models = f.ws->models();
  ASSERT_TRUE(models.ok());
  ASSERT_EQ(models->size(), 1u);
  EXPECT_EQ(models->front().name, "m2");
}

// ---- sweeps -------------------------------------------------------------------------------------

SweepRequest smallSweep() {
  SweepRequest r;
  r.labelSet = "truth";
  r.trainRuns = {"run_a", "run_b", "run_c"};
  r.testRuns = {"run_d", "run_e"};
  r.grid.groups = {SensorGroup::Front, SensorGroup::Right};
  r.grid.orders = {1, 2};
  r.grid.forms = {analysis::CovarianceForm::NodalDiag};
  r.grid.varianceFloors = {0.01, 0.1};
  r.grid.maxIterations = 20;
  r.threads = 1;
  return r;
}

using CellKey = std::tuple<int, int, int, double>;
CellKey cellKey(const analysis::SweepCell& c) {
  return {static_cast<int>(c.group), c.order, static_cast<int>(c.form), c.varianceFloor};
}

TEST(WorkspaceSweep, CellsAreStoredAndReadBack) {
  TrainFixture f;
  ASSERT_TRUE(f.ws);
  std::size_t seen = 0;
  std::size_t storedWhenSeen = 0;
  SweepRequest request = smallSweep();
  request.name = "small";
  // Each cell is stored before onCell sees it, i.e. as it finishes (read on a second connection).
  auto reader = storage::RunDatabase::open(f.dir / "w.db", storage::OpenMode::ReadWrite);
  ASSERT_TRUE(reader.ok());
  std::int64_t sweepId = 0;
  auto outcome = f.ws->sweep(request, [&](const analysis::SweepCellResult&) {
    ++seen;
    if (sweepId == 0) {
      auto list = reader.value()->sweeps().list();
      if (list.ok() && !list->empty()) sweepId = list->back().id;
    }
    auto cells = reader.value()->sweeps().cells(sweepId);
    if (cells.ok() && cells->size() == seen) ++storedWhenSeen;
  });
  ASSERT_TRUE(outcome.ok()) << outcome.errorText();
  const analysis::SweepResult& result = outcome->result;
  EXPECT_EQ(result.cells.size(), 8u);
  EXPECT_FALSE(result.cancelled);
  EXPECT_EQ(seen, 8u);
  EXPECT_EQ(storedWhenSeen, 8u);
  EXPECT_EQ(sweepId, outcome->sweepId);

  auto cells = f.ws->sweepStore().cells(outcome->sweepId);
  ASSERT_TRUE(cells.ok());
  EXPECT_EQ(cells->size(), result.cells.size());
  auto sweeps = f.ws->sweeps();
  ASSERT_TRUE(sweeps.ok());
  ASSERT_EQ(sweeps->size(), 1u);
  EXPECT_EQ(sweeps->front().name, "small");
  EXPECT_EQ(sweeps->front().cellCount, 8);
  const json config = json::parse(sweeps->front().configurationJson);
  EXPECT_EQ(config["state"], "finished");
  EXPECT_EQ(config["label_set"], "truth");
  EXPECT_EQ(config["train_runs"].size(), 3u);
  EXPECT_EQ(config["test_runs"].size(), 2u);

  auto loaded = f.ws->loadSweep(outcome->sweepId);
  ASSERT_TRUE(loaded.ok()) << loaded.errorText();
  ASSERT_EQ(loaded->cells.size(), result.cells.size());
  std::map<CellKey, const analysis::SweepCellResult*> byKey;
  for (const analysis::SweepCellResult& c : result.cells)
    byKey[cellKey(c.cell)] = &c;
  EXPECT_EQ(byKey.size(), result.cells.size());
  std::size_t fitted = 0;
  for (const analysis::SweepCellResult& c : loaded->cells) {
    auto it = byKey.find(cellKey(c.cell));
    ASSERT_NE(it, byKey.end());
    const analysis::SweepCellResult& r = *it->second;
    EXPECT_EQ(c.ok, r.ok);
    fitted += c.ok ? 1 : 0;
    EXPECT_EQ(c.trainRows, r.trainRows);
    EXPECT_EQ(c.testRows, r.testRows);
    EXPECT_DOUBLE_EQ(c.metrics.accuracy, r.metrics.accuracy);
    EXPECT_DOUBLE_EQ(c.metrics.balancedAccuracy, r.metrics.balancedAccuracy);
    EXPECT_EQ(c.metrics.total, r.metrics.total);
    EXPECT_EQ(c.confusion.total(), r.confusion.total());
    byKey.erase(it);
  }
  EXPECT_EQ(fitted, 8u);
  EXPECT_EQ(loaded->grid.orders, request.grid.orders);
  EXPECT_EQ(loaded->data.size(), result.data.size());

  // Deleting it takes its cells along; an id given twice is one sweep.
  ASSERT_TRUE(f.ws->sweepStore().remove({outcome->sweepId, outcome->sweepId}).ok());
  sweeps = f.ws->sweeps();
  ASSERT_TRUE(sweeps.ok());
  EXPECT_TRUE(sweeps->empty());
  cells = f.ws->sweepStore().cells(outcome->sweepId);
  ASSERT_TRUE(cells.ok());
  EXPECT_TRUE(cells->empty());
}

// Cells are stored as they finish, which on several threads is not the grid order; a loaded sweep
// lists them in grid order like the SweepResult, cell for cell the same JSON as the sweep file.
TEST(WorkspaceSweep, LoadedSweepListsCellsInGridOrder) {
  TrainFixture f;
  ASSERT_TRUE(f.ws);
  SweepRequest request = smallSweep();
  request.threads = 2;
  // Big orders first in the grid, so that small later cells finish before them.
  request.grid.orders = {8, 4, 1, 2};
  request.grid.forms = {analysis::CovarianceForm::NodalFull, analysis::CovarianceForm::GrandDiag};
  request.grid.groups = {SensorGroup::Front, SensorGroup::Right, SensorGroup::Left};
  auto outcome = f.ws->sweep(request);
  ASSERT_TRUE(outcome.ok()) << outcome.errorText();
  const std::vector<analysis::SweepCell> grid = analysis::expandGrid(request.grid);
  ASSERT_EQ(outcome->result.cells.size(), grid.size());
  auto loaded = f.ws->loadSweep(outcome->sweepId);
  ASSERT_TRUE(loaded.ok()) << loaded.errorText();
  ASSERT_EQ(loaded->cells.size(), grid.size());
  for (std::size_t i = 0; i < grid.size(); ++i) {
    EXPECT_EQ(cellKey(outcome->result.cells[i].cell), cellKey(grid[i])) << i;
    EXPECT_EQ(cellKey(loaded->cells[i].cell), cellKey(grid[i])) << i;
  }
  EXPECT_EQ(analysis::sweepToJson(loaded.value())["cells"],
            analysis::sweepToJson(outcome->result)["cells"]);
  EXPECT_EQ(analysis::sweepReport(loaded.value(), analysis::TableStyle::Csv),
            analysis::sweepReport(outcome->result, analysis::TableStyle::Csv));
}

TEST(WorkspaceSweep, CancelledSweepKeepsItsFinishedCells) {
  TrainFixture f;
  ASSERT_TRUE(f.ws);
  SweepRequest request = smallSweep();
  std::size_t finished = 0;
  auto outcome = f.ws->sweep(
      request, [&](const analysis::SweepCellResult&) { ++finished; },
      [&](std::size_t, std::size_t) { return finished < 3; });
  ASSERT_TRUE(outcome.ok()) << outcome.errorText();
  const analysis::SweepResult& result = outcome->result;
  EXPECT_TRUE(result.cancelled);
  EXPECT_EQ(result.cells.size(), 3u);
  EXPECT_EQ(finished, 3u);
  auto cells = f.ws->sweepStore().cells(outcome->sweepId);
  ASSERT_TRUE(cells.ok());
  EXPECT_EQ(cells->size(), 3u);
  auto info = f.ws->sweepStore().info(outcome->sweepId);
  ASSERT_TRUE(info.ok());
  EXPECT_EQ(info->cellCount, 3);
  EXPECT_EQ(json::parse(info->configurationJson)["state"], "cancelled");
  auto loaded = f.ws->loadSweep(outcome->sweepId);
  ASSERT_TRUE(loaded.ok()) << loaded.errorText();
  EXPECT_EQ(loaded->cells.size(), 3u);
  EXPECT_TRUE(loaded->cancelled);
}

TEST(WorkspaceSweep, CancelledOnTwoThreadsStoresExactlyTheResultCells) {
  TrainFixture f;
  ASSERT_TRUE(f.ws);
  SweepRequest request = smallSweep();
  request.threads = 2;
  request.grid.orders = {1, 2, 4};
  std::size_t finished = 0;
  auto outcome = f.ws->sweep(
      request, [&](const analysis::SweepCellResult&) { ++finished; },
      [&](std::size_t, std::size_t) { return finished < 2; });
  ASSERT_TRUE(outcome.ok()) << outcome.errorText();
  EXPECT_TRUE(outcome->result.cancelled);
  EXPECT_GE(outcome->result.cells.size(), 2u);
  EXPECT_LT(outcome->result.cells.size(), 12u);
  auto cells = f.ws->sweepStore().cells(outcome->sweepId);
  ASSERT_TRUE(cells.ok());
  EXPECT_EQ(cells->size(), outcome->result.cells.size());
  EXPECT_EQ(cells->size(), finished);

  // Cancelled before the first cell: the sweep is kept, empty and marked cancelled.
  auto none = f.ws->sweep(request, {}, [](std::size_t, std::size_t) { return false; });
  ASSERT_TRUE(none.ok()) << none.errorText();
  EXPECT_TRUE(none->result.cells.empty());
  auto info = f.ws->sweepStore().info(none->sweepId);
  ASSERT_TRUE(info.ok());
  EXPECT_EQ(info->cellCount, 0);
  EXPECT_EQ(json::parse(info->configurationJson)["state"], "cancelled");
  auto loaded = f.ws->loadSweep(none->sweepId);
  ASSERT_TRUE(loaded.ok()) << loaded.errorText();
  EXPECT_TRUE(loaded->cells.empty());
}

// A sweep that stops on an error (here out of memory, thrown where the sweep reports progress)
// is stored as "failed" with the error; it once stayed "running" for ever.
TEST(WorkspaceSweep, ASweepStoppedByAnErrorIsStoredAsFailedWithIt) {
  TrainFixture f;
  ASSERT_TRUE(f.ws);
  SweepRequest request = smallSweep();
  request.threads = 1;
  std::size_t finished = 0;
  auto outcome = f.ws->sweep(
      request, [&](const analysis::SweepCellResult&) { ++finished; },
      [&](std::size_t, std::size_t) -> bool {
        if (finished >= 2) throw std::bad_alloc();
        return true;
      });
  ASSERT_FALSE(outcome.ok());
  EXPECT_NE(outcome.errorText().find("out of memory"), std::string::npos) << outcome.errorText();
  auto sweeps = f.ws->sweepStore().list();
  ASSERT_TRUE(sweeps.ok());
  ASSERT_EQ(sweeps->size(), 1u);
  const json stored = json::parse(sweeps->front().configurationJson);
  EXPECT_EQ(stored["state"], "failed");
  EXPECT_EQ(stored.value("error", ""), "out of memory");
  auto cells = f.ws->sweepStore().cells(sweeps->front().id);
  ASSERT_TRUE(cells.ok());
  EXPECT_EQ(cells->size(), finished) << "the cells finished before the error are kept";
}

// Whole runs are held out: a run both trained and scored on would score the cells on their own
// training rows, so it is refused like in train (and nothing is stored).
TEST(WorkspaceSweep, RunGivenForTrainingAndTestingIsRefused) {
  TrainFixture f;
  ASSERT_TRUE(f.ws);
  SweepRequest request = smallSweep();
  request.testRuns = {"run_d", "run_a"};
  auto outcome = f.ws->sweep(request);
  ASSERT_FALSE(outcome.ok());
  EXPECT_NE(outcome.errorText().find("'run_a'"), std::string::npos) << outcome.errorText();
  auto sweeps = f.ws->sweeps();
  ASSERT_TRUE(sweeps.ok());
  EXPECT_TRUE(sweeps->empty());
}

TEST(WorkspaceSweep, UnknownRunIsAnErrorAndStoresNothing) {
  TrainFixture f;
  ASSERT_TRUE(f.ws);
  SweepRequest request = smallSweep();
  request.testRuns = {"no_such_run"};
  auto outcome = f.ws->sweep(request);
  ASSERT_FALSE(outcome.ok());
  EXPECT_NE(outcome.errorText().find("no_such_run"), std::string::npos) << outcome.errorText();
  auto sweeps = f.ws->sweeps();
  ASSERT_TRUE(sweeps.ok());
  EXPECT_TRUE(sweeps->empty());
}

// ---- classification -----------------------------------------------------------------------------

TEST(WorkspaceClassify, StoredModelOnStoredRun) {
  TrainFixture f;
  ASSERT_TRUE(f.ws);
  TrainRequest request;
  request.labelSet = "truth";
  request.groups = {SensorGroup::Front, SensorGroup::FrontLeftCorner};
  request.settings = quickSettings();
  request.modelName = "clf";
  auto trained = f.ws->train(request);
  ASSERT_TRUE(trained.ok()) << trained.errorText();

  auto classified = f.ws->classify("clf", "run_d");
  ASSERT_TRUE(classified.ok()) << classified.errorText();
  const analysis::RunClassification& result = classified->result;
  auto run = f.ws->loadRun("run_d");
  ASSERT_TRUE(run.ok());
  EXPECT_EQ(result.steps, run->stepCount());
  std::size_t zeroSteps = 0, contactSteps = 0, correct = 0;
  for (const GroupInfo& info : kSensorGroups) {
    const analysis::GroupClassification& gc =
        result.groups[static_cast<std::size_t>(groupIndex(info.group))];
    const bool modelled =
        info.group == SensorGroup::Front || info.group == SensorGroup::FrontLeftCorner;
    EXPECT_EQ(gc.model != nullptr, modelled) << info.shortName;
    if (!modelled) continue;
    std::set<std::string> classes;
    for (ContactClass c : gc.model->classes)
      classes.insert(std::string(contactClassName(c)));
    for (std::size_t t = 0; t < result.steps; ++t) {
      const std::string name = gc.className(t);
      if (analysis::groupIsZero(run.value(), t, info.group)) {
        ++zeroSteps;
        EXPECT_EQ(name, "NoContact") << info.shortName << " step " << t;
      } else {
        ++contactSteps;
        EXPECT_EQ(classes.count(name), 1u) << info.shortName << " step " << t << ": " << name;
        correct += name == contactClassName(run->truthAt(t, info.group)) ? 1 : 0;
      }
    }
  }
  EXPECT_GT(zeroSteps, 0u);
  EXPECT_GT(contactSteps, 0u);
  EXPECT_GT(correct, contactSteps * 8 / 10);

  // The same as classifying the run loaded from the database with the loaded bundle.
  auto bundle = f.ws->loadModel("clf");
  ASSERT_TRUE(bundle.ok());
  const analysis::RunClassification direct = analysis::classifyRun(run.value(), bundle.value());
  ASSERT_EQ(direct.steps, result.steps);
  for (std::size_t g = 0; g < kGroupCount; ++g) {
    EXPECT_EQ(direct.groups[g].predicted, result.groups[g].predicted) << g;
    EXPECT_EQ(direct.groups[g].noContactRule, result.groups[g].noContactRule) << g;
    for (std::size_t t = 0; t < result.steps; ++t)
      ASSERT_EQ(direct.groups[g].className(t), result.groups[g].className(t)) << g << " " << t;
  }

  EXPECT_FALSE(f.ws->classify("no-model", "run_d").ok());
  EXPECT_FALSE(f.ws->classify("clf", "no_run").ok());
}

// ---- labels belong to runs by id ----------------------------------------------------------------

TEST(WorkspaceRuns, SameStemUnderTwoPrefixesKeepsItsOwnLabels) {
  TempDir dir;
  std::filesystem::create_directories(dir / "a");
  std::filesystem::create_directories(dir / "b");
  ASSERT_TRUE(writeRunCsv(labelledRun(1), dir / "a" / "run_0000.csv").ok());
  ASSERT_TRUE(writeRunCsv(labelledRun(2), dir / "b" / "run_0000.csv").ok());
  auto ws = openWorkspace(dir);
  ASSERT_TRUE(ws);
  workspace::Workspace& db = *ws;
  for (const char* prefix : {"a", "b"}) {
    storage::ImportOptions options;
    options.namePrefix = prefix;
    const auto out = db.runStore().importFiles({dir / prefix / "run_0000.csv"}, options);
    ASSERT_EQ(out.size(), 1u);
    ASSERT_EQ(out[0].status, storage::ImportStatus::Imported) << out[0].message;
    EXPECT_EQ(out[0].runName, std::string(prefix) + "_run_0000");
  }
  auto a = db.runStore().find("a_run_0000");
  auto b = db.runStore().find("b_run_0000");
  ASSERT_TRUE(a.ok() && b.ok());
  ASSERT_NE(a->id, b->id);

  // A set on one run does not apply to the other.
  ASSERT_TRUE(db.labelStore().autolabel(a->id, "only-a").ok());
  auto onlyA = db.labelStore().find("only-a");
  ASSERT_TRUE(onlyA.ok());
  auto onB = db.labelStore().segments(onlyA->id, b->id);
  ASSERT_TRUE(onB.ok());
  EXPECT_TRUE(onB->empty());
  auto catalog = ws->labelSets();
  ASSERT_TRUE(catalog.ok());
  ASSERT_EQ(catalog->size(), 1u);
  EXPECT_EQ(catalog->front().runs, (std::vector<std::string>{"a_run_0000"}));
  auto runs = ws->runs();
  ASSERT_TRUE(runs.ok());
  for (const storage::RunCatalogEntry& e : runs.value()) {
    EXPECT_EQ(e.labelSets.empty(), e.run.name == "b_run_0000") << e.run.name;
  }

  // Training on b with a's set finds no labels on b: every group is skipped for want of rows.
  TrainRequest bOnly;
  bOnly.labelSet = "only-a";
  bOnly.trainRuns = {"b_run_0000"};
  bOnly.groups = {SensorGroup::Back, SensorGroup::Front};
  bOnly.settings = quickSettings();
  auto unlabelled = ws->train(bOnly);
  ASSERT_FALSE(unlabelled.ok()) << "run a's labels were applied to run b";
  EXPECT_NE(unlabelled.errorText().find("0 labelled contact rows"), std::string::npos)
      << unlabelled.errorText();

  // Both labelled into one set: an edit on a's segments leaves b's as they were.
  ASSERT_TRUE(db.labelStore().autolabel(b->id, "only-a").ok());
  const std::vector<SegmentKey> bBefore = groupSegments(*ws, onlyA->id, b->id, SensorGroup::Back);
  const std::vector<SegmentKey> aBefore = groupSegments(*ws, onlyA->id, a->id, SensorGroup::Back);
  LabelSegment s;
  s.run = "a_run_0000";
  s.group = SensorGroup::Back;
  s.firstStep = 10;
  s.lastStep = 200;
  s.cls = ContactClass::DeadPath;
  auto edit = ws->addSegment(onlyA->id, s);
  ASSERT_TRUE(edit.ok()) << edit.errorText();
  EXPECT_EQ(edit->runId, a->id);
  EXPECT_NE(groupSegments(*ws, onlyA->id, a->id, SensorGroup::Back), aBefore);
  EXPECT_EQ(groupSegments(*ws, onlyA->id, b->id, SensorGroup::Back), bBefore);

  // Training on the set loads each run's own labels: b's labels match b's truth.
  TrainRequest request;
  request.labelSet = "only-a";
  request.trainRuns = {"b_run_0000"};
  request.groups = {SensorGroup::Back};
  request.settings = quickSettings();
  auto trained = ws->train(request);
  ASSERT_TRUE(trained.ok()) << trained.errorText();
  EXPECT_EQ(trained->evaluatedOn, "training runs");
  EXPECT_EQ(trained->trainRuns, (std::vector<std::string>{"b_run_0000"}));
  EXPECT_EQ(trained->bundle.models[0].classes.size(), 3u) << "DeadPath of run a leaked into b";
}

}  // namespace
}  // namespace tactile::workspace

// ---- models from sweep cells, model files ------------------------------------------------------

namespace tactile::workspace {
namespace {

TEST(WorkspaceCellModel, ModelOfACellScoresExactlyAsTheCell) {
  TrainFixture f;
  ASSERT_TRUE(f.ws);
  // Per-step and online cells: the online score depends on the class chain and its evidence
  // weight (the group's default), which the cell's model must share.
  SweepRequest request = smallSweep();
  request.grid.decisions = {analysis::DecisionMode::Step, analysis::DecisionMode::Online};
  auto sweep = f.ws->sweep(request);
  ASSERT_TRUE(sweep.ok()) << sweep.errorText();
  auto stored = f.ws->loadSweep(sweep->sweepId);
  ASSERT_TRUE(stored.ok());
  std::size_t checked = 0;
  for (std::size_t i = 0; i < stored->cells.size(); ++i) {
    const analysis::SweepCellResult& cell = stored->cells[i];
    if (!cell.ok) continue;
    auto trained = f.ws->trainSweepCell(sweep->sweepId, i);
    ASSERT_TRUE(trained.ok()) << trained.errorText();
    ASSERT_EQ(trained->groups.size(), 1u);
    const GroupTrainReport& g = trained->groups.front();
    EXPECT_EQ(g.group, cell.cell.group);
    EXPECT_TRUE(g.trained);
    EXPECT_EQ(g.samplesTrain, cell.trainRows);
    EXPECT_EQ(g.samplesTest, cell.testRows);
    ASSERT_TRUE(g.balancedAccuracy.has_value() && g.accuracy.has_value());
    EXPECT_DOUBLE_EQ(*g.balancedAccuracy, cell.metrics.balancedAccuracy);
    EXPECT_DOUBLE_EQ(*g.accuracy, cell.metrics.accuracy);
    // Stored under a short name that says where it came from, distinct for every cell, within
    // the name rule (it once was a sentence).
    EXPECT_EQ(trained->modelName, "sweep" + std::to_string(sweep->sweepId) + "-" +
                                      std::string(groupInfo(cell.cell.group).shortName) + "-cell" +
                                      std::to_string(i));
    EXPECT_LE(trained->modelName.size(), 40u);
    EXPECT_EQ(trained->modelName.find(','), std::string::npos);
    const analysis::GroupModel* m = trained->bundle.find(cell.cell.group);
    ASSERT_NE(m, nullptr);
    EXPECT_EQ(m->varianceFloor, cell.cell.varianceFloor);
    EXPECT_EQ(m->classifier.models().front().components(), cell.cell.order);
    EXPECT_EQ(m->decision, cell.cell.decision);
    EXPECT_EQ(m->transitions.emissionWeight,
              analysis::defaultEmissionWeight(cell.cell.group, cell.cell.method));
    ++checked;
  }
  EXPECT_GE(checked, 2u);
  auto models = f.ws->models();
  ASSERT_TRUE(models.ok());
  EXPECT_EQ(models->size(), checked);
  // Not stored when asked not to (a model for a file only): the bundle is there, no model more.
  for (std::size_t i = 0; i < stored->cells.size(); ++i) {
    if (!stored->cells[i].ok) continue;
    auto fileOnly = f.ws->trainSweepCell(sweep->sweepId, i, {}, {}, /*store=*/false);
    ASSERT_TRUE(fileOnly.ok()) << fileOnly.errorText();
    EXPECT_EQ(fileOnly->modelId, 0);
    EXPECT_NE(fileOnly->bundle.find(stored->cells[i].cell.group), nullptr);
    break;
  }
  auto after = f.ws->models();
  ASSERT_TRUE(after.ok());
  EXPECT_EQ(after->size(), checked);
}

TEST(WorkspaceCellModel, MissingCellAndSweepAreErrors) {
  TrainFixture f;
  ASSERT_TRUE(f.ws);
  auto sweep = f.ws->sweep(smallSweep());
  ASSERT_TRUE(sweep.ok());
  auto noCell = f.ws->trainSweepCell(sweep->sweepId, 1000);
  ASSERT_FALSE(noCell.ok());
  EXPECT_NE(noCell.errorText().find("no cell 1000"), std::string::npos) << noCell.errorText();
  EXPECT_FALSE(f.ws->trainSweepCell(sweep->sweepId + 99, 0).ok());
  auto models = f.ws->models();
  ASSERT_TRUE(models.ok());
  EXPECT_TRUE(models->empty());
}

TEST(WorkspaceModelFiles, ExportThenImportGivesTheSameBundle) {
  TrainFixture f;
  ASSERT_TRUE(f.ws);
  TrainRequest request;
  request.labelSet = "truth";
  request.settings = quickSettings();
  request.modelName = "m";
  ASSERT_TRUE(f.ws->train(request).ok());
  const std::filesystem::path file = f.dir / "m.json";
  ASSERT_TRUE(f.ws->exportModel("m", file).ok());
  EXPECT_FALSE(std::filesystem::exists(f.dir / "m.json.partial"));
  auto imported = f.ws->importModel(file);
  // The file's stem is the default name, and it is taken by the original.
  ASSERT_FALSE(imported.ok());
  imported = f.ws->importModel(file, "copy");
  ASSERT_TRUE(imported.ok()) << imported.errorText();
  EXPECT_EQ(imported.value(), "copy");
  auto a = f.ws->loadModel("m");
  auto b = f.ws->loadModel("copy");
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_EQ(analysis::bundleToJson(a.value()).dump(), analysis::bundleToJson(b.value()).dump());
}

TEST(WorkspaceModelFiles, FailedExportLeavesNoFileAndBadImportStoresNothing) {
  TrainFixture f;
  ASSERT_TRUE(f.ws);
  EXPECT_FALSE(f.ws->exportModel("absent", f.dir / "absent.json").ok());
  EXPECT_FALSE(std::filesystem::exists(f.dir / "absent.json"));
  const std::filesystem::path bad = f.dir / "bad.json";
  std::ofstream(bad) << "{\"format\":\"tactile-model\",\"version\":1,\"group\":\"F\"}";
  auto imported = f.ws->importModel(bad);
  ASSERT_FALSE(imported.ok());
  EXPECT_NE(imported.errorText().find("bad.json"), std::string::npos) << imported.errorText();
  auto models = f.ws->models();
  ASSERT_TRUE(models.ok());
  EXPECT_TRUE(models->empty());
}

TEST(WorkspaceSplit, HoldOutEveryFourthRunByName) {
  const RunSplit five = holdOutEveryFourth({"e", "a", "d", "b", "c"});
  EXPECT_EQ(five.train, (std::vector<std::string>{"a", "b", "c", "e"}));
  EXPECT_EQ(five.test, (std::vector<std::string>{"d"}));
  const RunSplit two = holdOutEveryFourth({"b", "a"});
  EXPECT_EQ(two.train, (std::vector<std::string>{"a"}));
  EXPECT_EQ(two.test, (std::vector<std::string>{"b"}));
  const RunSplit one = holdOutEveryFourth({"a"});
  EXPECT_EQ(one.train, (std::vector<std::string>{"a"}));
  EXPECT_TRUE(one.test.empty());
}

}  // namespace
}  // namespace tactile::workspace
