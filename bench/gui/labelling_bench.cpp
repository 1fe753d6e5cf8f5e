// How much work labelling one run takes in the real workbench, by hand from nothing and from a
// model's decisions then fixing what is wrong. A scripted annotator who knows the run's truth (it
// stands in for a person's judgement) drives the real main window on the offscreen platform: it
// presses the real keys (PageDown, Home, Ctrl+L, the class keys), and the selection a person makes
// with a drag in the timeline is set directly and counted as one drag. At the end every step of
// every group must carry the truth's class (full agreement), or the program fails.
//
//   tactile_labelling_bench DB RUN MODEL [DOUBT_THRESHOLD]
//
// It prints one JSON line per way of working: key presses, clicks, drags, decisions (stretches
// labelled), the screens paged through, an estimate of a person's seconds by the keystroke-level
// model (Card, Moran and Newell: K = 0.28 s a key, P + 2B = 1.3 s a click, 2P + 2B = 2.4 s a
// drag, M = 1.35 s to decide each stretch and to look at each screen), and the seconds the
// workbench itself took. For the model's way it also says how many of the wrong stretches Next
// Doubt (D) would have stopped at. bench/gui/labelling.sh builds the demo database and a model.
#include <QApplication>
#include <QElapsedTimer>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>

#include <array>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "app/gui/labels/label_model.h"
#include "app/gui/labels/label_panel_view.h"
#include "app/gui/learning/prediction_model.h"
#include "app/gui/main_window.h"
#include "app/gui/runs/run_session_model.h"
#include "app/gui/runs/timeline_view.h"
#include "run/sensor_layout.h"

namespace {

using tactile::ContactClass;
using tactile::SensorGroup;
using tactile::gui::LabelPanelView;
using tactile::gui::MainWindow;

constexpr double kKeySeconds = 0.28;
constexpr double kClickSeconds = 1.3;
constexpr double kDragSeconds = 2.4;
constexpr double kThinkSeconds = 1.35;
constexpr std::int64_t kWorkingSteps = 300;

struct Effort {
  int keys = 0;
  int clicks = 0;
  int drags = 0;
  int decisions = 0;
  int screens = 0;
  int foundByDoubt = 0;
  double workbenchSeconds = 0.0;
  double personSeconds() const {
    return keys * kKeySeconds + clicks * kClickSeconds + drags * kDragSeconds +
           (decisions + screens) * kThinkSeconds;
  }
};

// A maximal stretch of one group's steps to give one class.
struct Stretch {
  SensorGroup group;
  std::int64_t first;
  std::int64_t last;
  ContactClass cls;
};

using Classes = std::array<std::vector<int>, tactile::kGroupCount>;  // -1: unlabelled

Classes readClasses(const tactile::gui::LabelModel& labels, std::int64_t steps) {
  Classes out;
  for (const tactile::GroupInfo& g : tactile::kSensorGroups) {
    auto& column = out[static_cast<std::size_t>(tactile::groupIndex(g.group))];
    column.resize(static_cast<std::size_t>(steps));
    for (std::int64_t t = 0; t < steps; ++t) {
      const auto c = labels.classAt(g.group, t);
      column[static_cast<std::size_t>(t)] = c ? static_cast<int>(*c) : -1;
    }
  }
  return out;
}

// The stretches where `have` differs from `want`, each a maximal run of steps whose wanted class
// is one and the same, in group order then step order.
std::vector<Stretch> stretchesToFix(const Classes& have, const Classes& want) {
  std::vector<Stretch> out;
  for (const tactile::GroupInfo& g : tactile::kSensorGroups) {
    const auto k = static_cast<std::size_t>(tactile::groupIndex(g.group));
    const std::vector<int>& h = have[k];
    const std::vector<int>& w = want[k];
    for (std::size_t t = 0; t < w.size();) {
      if (h[t] == w[t]) {
        ++t;
        continue;
      }
      std::size_t end = t;
      while (end + 1 < w.size() && w[end + 1] == w[t] && h[end + 1] != w[end + 1])
        ++end;
      out.push_back({g.group, static_cast<std::int64_t>(t), static_cast<std::int64_t>(end),
                     static_cast<ContactClass>(w[t])});
      t = end + 1;
    }
  }
  return out;
}

void settle() {
  QCoreApplication::sendPostedEvents();
  QCoreApplication::processEvents();
}

void press(MainWindow& w, int key, Qt::KeyboardModifiers modifiers, Effort& effort) {
  QTest::keyClick(&w, static_cast<Qt::Key>(key), modifiers);
  settle();
  ++effort.keys;
}

// Fixes the stretches one group at a time, as a person would: the group's row (a click), Home,
// then for each stretch PageDown until it is in view, a drag over it (one more screen for every
// screen it spans) and its class key.
void fixStretches(MainWindow& w, const std::vector<Stretch>& stretches, Effort& effort) {
  tactile::gui::RunSession* session = w.session();
  std::optional<SensorGroup> current;
  for (const Stretch& s : stretches) {
    if (current != s.group) {
      session->setSelectedGroup(s.group);
      ++effort.clicks;
      current = s.group;
      press(w, Qt::Key_Home, Qt::NoModifier, effort);
      ++effort.screens;
    }
    while (w.timeline()->visibleRange().last < s.first) {
      press(w, Qt::Key_PageDown, Qt::NoModifier, effort);
      ++effort.screens;
    }
    const std::int64_t screen = w.timeline()->visibleRange().size();
    const std::int64_t spanned = (s.last - w.timeline()->visibleRange().first) / screen;
    if (spanned > 0) effort.screens += static_cast<int>(spanned);
    session->setSelection(s.first, s.last);
    ++effort.drags;
    press(w, Qt::Key_1 + static_cast<int>(s.cls), Qt::NoModifier, effort);
    ++effort.decisions;
    session->clearSelection();
  }
}

bool agreesEverywhere(const tactile::gui::LabelModel& labels, const Classes& truth,
                      std::int64_t steps, const char* what) {
  const Classes now = readClasses(labels, steps);
  long long wrong = 0;
  for (std::size_t g = 0; g < now.size(); ++g) {
    for (std::size_t t = 0; t < now[g].size(); ++t)
      wrong += now[g][t] != truth[g][t] ? 1 : 0;
  }
  if (wrong != 0) std::fprintf(stderr, "%s: %lld group-steps differ from the truth\n", what, wrong);
  return wrong == 0;
}

void print(const char* way, const Effort& e, std::int64_t steps, std::size_t stretches) {
  std::printf(
      "{\"way\": \"%s\", \"steps\": %lld, \"stretches\": %zu, \"keys\": %d, \"clicks\": %d, "
      "\"drags\": %d, \"decisions\": %d, \"screens\": %d, \"found_by_doubt\": %d, "
      "\"person_seconds_klm\": %.1f, \"workbench_seconds\": %.2f}\n",
      way, static_cast<long long>(steps), stretches, e.keys, e.clicks, e.drags, e.decisions,
      e.screens, e.foundByDoubt, e.personSeconds(), e.workbenchSeconds);
}

}  // namespace

int main(int argc, char** argv) {
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  if (argc < 4) {
    std::fprintf(stderr, "usage: tactile_labelling_bench DB RUN MODEL [DOUBT_THRESHOLD]\n");
    return 2;
  }
  QApplication app(argc, argv);
  QTemporaryDir settingsDir;
  QSettings::setDefaultFormat(QSettings::IniFormat);
  QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settingsDir.path());
  QCoreApplication::setOrganizationName(QStringLiteral("TactileLabellingBench"));
  const double doubt = argc > 4 ? std::atof(argv[4]) : 0.8;

  MainWindow w;
  w.resize(1600, 1000);
  w.show();
  settle();
  const auto fail = [](const std::string& what) {
    std::fprintf(stderr, "tactile_labelling_bench: %s\n", what.c_str());
    return 1;
  };
  if (auto s = w.openDatabase(QString::fromLocal8Bit(argv[1])); !s) return fail(s.errorText());
  if (auto s = w.openRun(QString::fromLocal8Bit(argv[2])); !s) return fail(s.errorText());
  settle();
  const std::int64_t steps = w.session()->stepCount();
  tactile::gui::LabelModel* labels = w.labels();
  if (auto s = labels->openSet("truth"); !s) return fail(s.errorText());
  const Classes truth = readClasses(*labels, steps);
  for (const auto& column : truth) {
    for (int c : column) {
      if (c < 0) return fail("the run's truth does not cover every step");
    }
  }
  LabelPanelView* panel = w.labelPanel();
  panel->setGroupsMode(LabelPanelView::GroupsMode::Selected);
  // The annotator's working zoom: 300 steps across the timelines (about 3 pixels a step at
  // 1600 x 1000, enough to drag over a stretch of one step), set once with the wheel.
  const auto workingZoom = [&w] {
    w.timeline()->setVisibleRange({0, kWorkingSteps - 1});
    settle();
  };

  // ---- by hand, from nothing ----
  {
    Effort e;
    QElapsedTimer clock;
    clock.start();
    if (auto s = labels->createSet("bench_by_hand_" + std::string(argv[2])); !s)
      return fail(s.errorText());
    workingZoom();
    ++e.drags;  // the wheel turn to the working zoom, counted as a gesture
    const std::vector<Stretch> todo = stretchesToFix(readClasses(*labels, steps), truth);
    fixStretches(w, todo, e);
    e.workbenchSeconds = static_cast<double>(clock.nsecsElapsed()) / 1e9;
    if (!agreesEverywhere(*labels, truth, steps, "by hand")) return 1;
    print("by_hand", e, steps, todo.size());
  }

  // ---- from the model, then fixing what it got wrong ----
  {
    Effort e;
    QElapsedTimer clock;
    clock.start();
    if (auto s = labels->createSet("bench_from_model_" + std::string(argv[2])); !s)
      return fail(s.errorText());
    workingZoom();
    ++e.drags;
    // Learn > Show Predictions (Ctrl+P, the model picked, Enter).
    if (auto s = w.showPredictions(QString::fromLocal8Bit(argv[3])); !s) {
      return fail(s.errorText());
    }
    w.waitForPredictions();
    e.keys += 2;
    ++e.clicks;
    // Every group at once: "Checked groups" and its eight boxes, the whole run in view (Ctrl+0),
    // Label from Model (Ctrl+L); then back to "Selected group" and the previous zoom (a wheel
    // turn).
    panel->setGroupsMode(LabelPanelView::GroupsMode::Checked);
    for (const tactile::GroupInfo& g : tactile::kSensorGroups)
      panel->setGroupChecked(g.group, true);
    e.clicks += 1 + static_cast<int>(tactile::kGroupCount);
    const tactile::gui::StepRange zoom = w.timeline()->visibleRange();
    press(w, Qt::Key_0, Qt::ControlModifier, e);
    press(w, Qt::Key_L, Qt::ControlModifier, e);
    panel->setGroupsMode(LabelPanelView::GroupsMode::Selected);
    w.timeline()->setVisibleRange(zoom);
    settle();
    e.clicks += 2;
    const std::vector<Stretch> todo = stretchesToFix(readClasses(*labels, steps), truth);
    // Would Next Doubt have stopped in it? (The model's posterior below the threshold at a step.)
    for (const Stretch& s : todo) {
      for (std::int64_t t = s.first; t <= s.last; ++t) {
        if (w.predictions()->doubtfulGroup(t, doubt)) {
          ++e.foundByDoubt;
          break;
        }
      }
    }
    fixStretches(w, todo, e);
    e.workbenchSeconds = static_cast<double>(clock.nsecsElapsed()) / 1e9;
    if (!agreesEverywhere(*labels, truth, steps, "from the model")) return 1;
    print("from_model", e, steps, todo.size());
  }
  return 0;
}
