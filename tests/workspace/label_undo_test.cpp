// Undo and redo of a change that moves a segment's start earlier, over its neighbour: the edit
// touches steps before the segment's old start, so what undo puts back must reach back to the new
// start. Checked step by step against hand-written labels, not against the workspace's own record
// of the edit. (An edit that snapshots only the old range leaves the neighbour cut short on undo
// and the steps between the new and the old start unlabelled.)
#include <gtest/gtest.h>

#include <cstdint>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tests/analysis/learn_test_data.h"
#include "tests/storage/storage_test_util.h"
#include "workspace/workspace.h"

namespace tactile::workspace {
namespace {
namespace label_undo {  // its own names in a unity build

using storage::LabelSegment;
using storage::test::TempDir;

constexpr std::int64_t kSteps = 80;
constexpr SensorGroup kGroup = SensorGroup::Left;
using Labels = std::vector<std::optional<ContactClass>>;  // one per step, empty = unlabelled

// The label of every step of the group, read back from the database.
Labels stepLabels(Workspace& ws, std::int64_t setId, std::int64_t runId) {
  Labels out(kSteps);
  auto segments = ws.labelStore().segments(setId, runId);
  EXPECT_TRUE(segments.ok()) << (segments.ok() ? "" : segments.errorText());
  if (!segments) return out;
  for (const LabelSegment& s : segments.value()) {
    if (s.group != kGroup) continue;
    for (std::int64_t step = s.firstStep; step <= s.lastStep; ++step) {
      EXPECT_FALSE(out[static_cast<std::size_t>(step)]) << "step " << step << " labelled twice";
      out[static_cast<std::size_t>(step)] = s.cls;
    }
  }
  return out;
}

// Labels written by hand: each range [first, last] gets its class, the rest none.
struct Range {
  std::int64_t first, last;
  ContactClass cls;
};
Labels expected(std::initializer_list<Range> ranges) {
  Labels out(kSteps);
  for (const Range& r : ranges)
    for (std::int64_t step = r.first; step <= r.last; ++step)
      out[static_cast<std::size_t>(step)] = r.cls;
  return out;
}

void expectLabels(const Labels& actual, const Labels& want, const std::string& when) {
  for (std::size_t step = 0; step < want.size(); ++step) {
    EXPECT_EQ(actual[step], want[step])
        << when << ": step " << step << " is "
        << (actual[step] ? contactClassName(*actual[step]) : std::string_view("unlabelled"))
        << ", expected "
        << (want[step] ? contactClassName(*want[step]) : std::string_view("unlabelled"));
  }
}

struct Fixture {
  TempDir dir;
  std::unique_ptr<Workspace> ws;
  std::int64_t runId = 0;
  std::int64_t setId = 0;

  Fixture() {
    auto opened = Workspace::open(dir / "w.db");
    EXPECT_TRUE(opened.ok()) << (opened.ok() ? "" : opened.errorText());
    if (!opened) return;
    ws = std::move(opened.value());
    RunData run = testdata::makeLabelledRun(kSteps, 3);
    run.metadata = {{"format", "tactile-run 1"}, {"subject", "sim"}, {"dt", "0.1"}};
    const storage::ImportOutcome out = ws->runStore().importRun(run, "undo_run");
    EXPECT_EQ(out.status, storage::ImportStatus::Imported) << out.message;
    runId = out.runId;
    auto set = ws->labelStore().create("hand");
    EXPECT_TRUE(set.ok()) << (set.ok() ? "" : set.errorText());
    if (set) setId = set.value();
  }

  // Adds a segment and returns its id (0 on failure).
  std::int64_t add(std::int64_t first, std::int64_t last, ContactClass cls) {
    LabelSegment s;
    s.runId = runId;
    s.group = kGroup;
    s.firstStep = first;
    s.lastStep = last;
    s.cls = cls;
    s.annotator = "hand";
    auto id = ws->addSegment(setId, s);
    EXPECT_TRUE(id.ok()) << (id.ok() ? "" : id.errorText());
    return id.ok() ? id->segmentId : 0;
  }
};

// Moves B's start from `newFirst` back over A, then undo, redo, undo, redo; every step's label is
// checked after each.
void moveStartBackOverNeighbour(std::int64_t newFirst, const Labels& wantAfter) {
  Fixture f;
  ASSERT_TRUE(f.ws);
  ASSERT_NE(f.setId, 0);
  // A: 10..19 wall, B: 20..29 corner, C: 40..49 dead path (a bystander).
  ASSERT_NE(f.add(10, 19, ContactClass::Wall), 0);
  const std::int64_t b = f.add(20, 29, ContactClass::Corner);
  ASSERT_NE(b, 0);
  ASSERT_NE(f.add(40, 49, ContactClass::DeadPath), 0);
  const Labels before = expected({{10, 19, ContactClass::Wall},
                                  {20, 29, ContactClass::Corner},
                                  {40, 49, ContactClass::DeadPath}});
  Workspace& ws = *f.ws;
  expectLabels(stepLabels(ws, f.setId, f.runId), before, "before the change");

  auto current = ws.labelStore().segment(f.setId, b);
  ASSERT_TRUE(current.ok()) << current.errorText();
  LabelSegment moved = current.value();
  moved.firstStep = newFirst;
  Result<LabelEdit> edit = ws.changeSegment(f.setId, b, moved);
  ASSERT_TRUE(edit.ok()) << edit.errorText();
  expectLabels(stepLabels(ws, f.setId, f.runId), wantAfter, "after the change");

  for (int round = 1; round <= 2; ++round) {
    const std::string n = " (round " + std::to_string(round) + ")";
    ASSERT_TRUE(ws.undo(edit.value()).ok());
    expectLabels(stepLabels(ws, f.setId, f.runId), before, "after undo" + n);
    ASSERT_TRUE(ws.redo(edit.value()).ok());
    expectLabels(stepLabels(ws, f.setId, f.runId), wantAfter, "after redo" + n);
  }
}

TEST(WorkspaceLabelUndo, StartMovedIntoTheNeighbourIsUndoneAndRedone) {
  // B now starts at 17: A keeps 10..16.
  moveStartBackOverNeighbour(17, expected({{10, 16, ContactClass::Wall},
                                           {17, 29, ContactClass::Corner},
                                           {40, 49, ContactClass::DeadPath}}));
}

TEST(WorkspaceLabelUndo, StartMovedOverTheWholeNeighbourIsUndoneAndRedone) {
  // B now starts at 5: A is covered and gone; steps 5..9, unlabelled before, are B's.
  moveStartBackOverNeighbour(
      5, expected({{5, 29, ContactClass::Corner}, {40, 49, ContactClass::DeadPath}}));
}

}  // namespace label_undo
}  // namespace
}  // namespace tactile::workspace
