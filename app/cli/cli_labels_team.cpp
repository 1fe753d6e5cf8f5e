// Label verbs for a team: labels set|history|assign|assignments|agreement|from-model
// (docs/team.md#annotators-side-by-side).
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "app/cli/cli_common.h"
#include "run/json_text.h"
#include "storage/run_database.h"
#include "workspace/workspace.h"

namespace tactile::cli {

void registerTeamLabelVerbs(CLI::App& labels);

namespace {

void printJson(const nlohmann::json& doc) {
  std::printf("%s\n", dumpJson(doc).c_str());
}

// The annotator an edit is made under when --annotator is not given: TACTILE_ANNOTATOR, else the
// login name.
std::string defaultAnnotator() {
  for (const char* name : {"TACTILE_ANNOTATOR", "USER", "LOGNAME"}) {
    if (const char* value = std::getenv(name); value != nullptr && *value != '\0') return value;
  }
  return {};
}

std::vector<SensorGroup> parseGroups(const std::vector<std::string>& given,
                                     std::string_view option) {
  std::vector<SensorGroup> groups;
  for (const std::string& name : splitNames(given)) {
    const auto group = parseSensorGroup(name);
    if (!group) {
      throw UsageError(std::string(option) + ": unknown group '" + name +
                       "' (F, FLC, L, RLC, B, RRC, R, FRC)");
    }
    if (std::find(groups.begin(), groups.end(), *group) == groups.end()) groups.push_back(*group);
  }
  return groups;
}

// "A-B" or "A": an inclusive step range.
std::pair<std::int64_t, std::int64_t> parseSteps(const std::string& text) {
  const auto dash = text.find('-', 1);
  auto number = [&](const std::string& part) {
    std::size_t used = 0;
    long long value = -1;
    try {
      value = std::stoll(part, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != part.size() || part.empty() || value < 0) {
      throw UsageError("--steps: expected FIRST-LAST (steps from 0), got '" + text + "'");
    }
    return static_cast<std::int64_t>(value);
  };
  const std::int64_t first = number(text.substr(0, dash));
  const std::int64_t last = dash == std::string::npos ? first : number(text.substr(dash + 1));
  if (last < first) throw UsageError("--steps: the last step comes before the first: " + text);
  return {first, last};
}

nlohmann::json segmentJson(const storage::LabelSegment& s) {
  return {{"first_step", s.firstStep},
          {"last_step", s.lastStep},
          {"class", contactClassName(s.cls)},
          {"annotator", s.annotator}};
}

nlohmann::json revisionJson(const storage::LabelRevision& r) {
  nlohmann::json replaced = nlohmann::json::array();
  for (const storage::LabelSegment& s : r.replaced)
    replaced.push_back(segmentJson(s));
  return {{"revision", r.revision},
          {"annotator", r.annotator},
          {"time", r.time},
          {"group", groupInfo(r.group).shortName},
          {"first_step", r.firstStep},
          {"last_step", r.lastStep},
          {"class", r.cls ? nlohmann::json(contactClassName(*r.cls)) : nlohmann::json(nullptr)},
          {"action", r.action},
          {"replaced", replaced}};
}

// ---- labels set ------------------------------------------------------------------------------

struct SetArgs {
  std::string db, set, run, steps, cls, annotator;
  std::vector<std::string> groups;
  std::optional<std::int64_t> expectRevision;
  bool json = false;
};

int runLabelsSet(const SetArgs& a) {
  const auto [first, last] = parseSteps(a.steps);
  const std::vector<SensorGroup> groups = parseGroups(a.groups, "--groups");
  if (groups.empty()) throw UsageError("--groups: name at least one group");
  const auto cls = parseContactClass(a.cls);
  if (!cls) {
    throw UsageError("--class: unknown class '" + a.cls +
                     "' (NoContact, Wall, Corner, LeavingWall, DeadPath)");
  }
  const std::string annotator = a.annotator.empty() ? defaultAnnotator() : a.annotator;
  if (!annotator.empty()) requireValidName(annotator, "--annotator", "annotator");
  requireValidName(a.set, "--set", "label set");
  auto db = openDatabaseForWrite(a.db);
  auto run = db->runs().find(a.run);
  if (!run) throw std::runtime_error(run.errorText());
  auto set = db->labels().find(a.set);
  std::int64_t setId = 0;
  if (set) {
    setId = set->id;
  } else {
    auto created = db->labels().create(a.set, annotator);
    if (!created) throw std::runtime_error(created.errorText());
    setId = created.value();
  }
  storage::EditOptions options;
  options.annotator = annotator;
  options.expectRevision = a.expectRevision;
  auto revision = db->labels().setRange(setId, run->id, groups, first, last, *cls, options);
  if (!revision) throw std::runtime_error(revision.errorText());
  if (a.json) {
    nlohmann::json names = nlohmann::json::array();
    for (const SensorGroup g : groups)
      names.push_back(groupInfo(g).shortName);
    printJson({{"set", a.set},
               {"run", a.run},
               {"groups", names},
               {"first_step", first},
               {"last_step", last},
               {"class", contactClassName(*cls)},
               {"annotator", annotator},
               {"revision", revision.value()}});
  } else {
    std::printf("labelled steps %lld-%lld of run '%s' as %s in '%s': revision %lld\n",
                static_cast<long long>(first), static_cast<long long>(last), a.run.c_str(),
                std::string(contactClassName(*cls)).c_str(), a.set.c_str(),
                static_cast<long long>(revision.value()));
  }
  return kExitOk;
}

// ---- labels history --------------------------------------------------------------------------

struct HistoryArgs {
  std::string db, set, run;
  bool json = false;
};

int runLabelsHistory(const HistoryArgs& a) {
  auto db = openDatabaseForRead(a.db);
  auto set = db->labels().find(a.set);
  if (!set) throw std::runtime_error(set.errorText());
  auto run = db->runs().find(a.run);
  if (!run) throw std::runtime_error(run.errorText());
  auto history = db->labels().history(set->id, run->id);
  if (!history) throw std::runtime_error(history.errorText());
  const std::int64_t latest = history->empty() ? 0 : history->back().revision;
  if (a.json) {
    nlohmann::json list = nlohmann::json::array();
    for (const storage::LabelRevision& r : history.value())
      list.push_back(revisionJson(r));
    printJson({{"set", a.set}, {"run", a.run}, {"revision", latest}, {"revisions", list}});
    return kExitOk;
  }
  std::printf("%8s  %-20s  %-14s %-4s %-17s %-11s %s\n", "revision", "time", "annotator", "group",
              "steps", "class", "action");
  for (const storage::LabelRevision& r : history.value()) {
    const std::string steps = std::to_string(r.firstStep) + "-" + std::to_string(r.lastStep);
    std::printf("%8lld  %-20s  %-14s %-4s  %-17s %-11s %s\n", static_cast<long long>(r.revision),
                r.time.c_str(), r.annotator.empty() ? "-" : r.annotator.c_str(),
                std::string(groupInfo(r.group).shortName).c_str(), steps.c_str(),
                r.cls ? std::string(contactClassName(*r.cls)).c_str() : "-", r.action.c_str());
  }
  return kExitOk;
}

// ---- labels assign / assignments -------------------------------------------------------------

struct AssignArgs {
  std::string db, to, set, state = "todo";
  std::vector<std::string> runs;
  std::string group;
  bool remove = false;
  bool json = false;
};

int runLabelsAssign(const AssignArgs& a) {
  const std::vector<std::string> runs = splitNames(a.runs);
  if (runs.empty()) throw UsageError("--runs: name at least one run");
  requireValidName(a.to, "--to", "annotator");
  std::optional<SensorGroup> group;
  if (!a.group.empty()) {
    group = parseSensorGroup(a.group);
    if (!group) throw UsageError("--group: unknown group '" + a.group + "'");
  }
  const auto state = storage::parseAssignmentState(a.state);
  if (!state)
    throw UsageError("--state: expected todo, labelled or reviewed, got '" + a.state + "'");
  auto db = openDatabaseForWrite(a.db);
  const Status done =
      a.remove ? db->labels().unassign(runs, group, a.to)
               : db->labels().assign(runs, group, a.to, a.set, *state, defaultAnnotator());
  if (!done) throw std::runtime_error(done.errorText());
  if (a.json) {
    printJson({{"runs", runs},
               {"group", group ? nlohmann::json(groupInfo(*group).shortName) : nullptr},
               {"annotator", a.to},
               {"state", a.remove ? nlohmann::json(nullptr) : nlohmann::json(a.state)}});
  } else {
    std::printf("%s %zu run%s %s %s\n", a.remove ? "unassigned" : "assigned", runs.size(),
                runs.size() == 1 ? "" : "s", a.remove ? "from" : "to", a.to.c_str());
  }
  return kExitOk;
}

struct AssignmentsArgs {
  std::string db, annotator;
  bool json = false;
};

int runLabelsAssignments(const AssignmentsArgs& a) {
  auto db = openDatabaseForRead(a.db);
  auto list = db->labels().assignments(a.annotator);
  if (!list) throw std::runtime_error(list.errorText());
  if (a.json) {
    nlohmann::json out = nlohmann::json::array();
    for (const storage::Assignment& x : list.value()) {
      out.push_back({{"run", x.run},
                     {"group", x.group ? nlohmann::json(groupInfo(*x.group).shortName) : nullptr},
                     {"annotator", x.annotator},
                     {"set", x.labelSet},
                     {"state", storage::assignmentStateName(x.state)},
                     {"updated_by", x.updatedBy},
                     {"updated_at", x.updatedAt}});
    }
    printJson({{"assignments", out}});
    return kExitOk;
  }
  std::printf("%-24s %-5s %-14s %-9s %-16s %s\n", "run", "group", "annotator", "state", "set",
              "updated");
  for (const storage::Assignment& x : list.value()) {
    std::printf("%-24s %-5s %-14s %-9s %-16s %s\n", x.run.c_str(),
                x.group ? std::string(groupInfo(*x.group).shortName).c_str() : "all",
                x.annotator.c_str(), std::string(storage::assignmentStateName(x.state)).c_str(),
                x.labelSet.empty() ? "-" : x.labelSet.c_str(), x.updatedAt.c_str());
  }
  return kExitOk;
}

// ---- labels agreement ------------------------------------------------------------------------

struct AgreementArgs {
  std::string db;
  std::vector<std::string> sets, runs;
  bool json = false;
};

nlohmann::json agreementJson(const workspace::GroupAgreement& g) {
  auto optional = [](const std::optional<double>& v) {
    return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
  };
  return {{"group", groupInfo(g.group).shortName},
          {"compared_steps", g.comparedSteps},
          {"agreeing_steps", g.agreeingSteps},
          {"percent", optional(g.percent)},
          {"kappa", optional(g.kappa)}};
}

int runLabelsAgreement(const AgreementArgs& a) {
  const std::vector<std::string> sets = splitNames(a.sets);
  if (sets.size() != 2) throw UsageError("--sets: name exactly two label sets, e.g. --sets A,B");
  auto db = openDatabaseForRead(a.db);
  auto first = db->labels().find(sets[0]);
  if (!first) throw std::runtime_error(first.errorText());
  auto second = db->labels().find(sets[1]);
  if (!second) throw std::runtime_error(second.errorText());
  std::vector<std::string> runs = splitNames(a.runs);
  if (runs.empty()) {
    // Every run both sets have segments on.
    auto catalog = db->runs().catalog();
    if (!catalog) throw std::runtime_error(catalog.errorText());
    for (const storage::RunCatalogEntry& e : catalog.value()) {
      const auto has = [&](const std::string& s) {
        return std::find(e.labelSets.begin(), e.labelSets.end(), s) != e.labelSets.end();
      };
      if (has(sets[0]) && has(sets[1])) runs.push_back(e.run.name);
    }
  }
  // Per run, and pooled over the runs as one sequence of steps.
  nlohmann::json perRun = nlohmann::json::array();
  std::vector<storage::LabelSegment> allFirst, allSecond;
  std::int64_t offset = 0;
  std::vector<std::pair<std::string, std::vector<workspace::GroupAgreement>>> rows;
  for (const std::string& name : runs) {
    auto run = db->runs().find(name);
    if (!run) throw std::runtime_error(run.errorText());
    auto a1 = db->labels().segments(first->id, run->id);
    auto a2 = db->labels().segments(second->id, run->id);
    if (!a1) throw std::runtime_error(a1.errorText());
    if (!a2) throw std::runtime_error(a2.errorText());
    rows.emplace_back(name, workspace::labelAgreement(run->stepCount, a1.value(), a2.value()));
    for (auto* pair : {&a1, &a2}) {
      auto& into = pair == &a1 ? allFirst : allSecond;
      for (storage::LabelSegment s : pair->value()) {
        s.firstStep += offset;
        s.lastStep += offset;
        into.push_back(std::move(s));
      }
    }
    offset += run->stepCount;
  }
  const std::vector<workspace::GroupAgreement> pooled =
      workspace::labelAgreement(offset, allFirst, allSecond);
  if (a.json) {
    for (const auto& [name, groups] : rows) {
      nlohmann::json list = nlohmann::json::array();
      for (const auto& g : groups)
        list.push_back(agreementJson(g));
      perRun.push_back({{"run", name}, {"groups", list}});
    }
    nlohmann::json all = nlohmann::json::array();
    for (const auto& g : pooled)
      all.push_back(agreementJson(g));
    printJson({{"sets", sets}, {"runs", perRun}, {"groups", all}});
    return kExitOk;
  }
  std::printf("'%s' against '%s' over %zu run%s (steps both label)\n", sets[0].c_str(),
              sets[1].c_str(), runs.size(), runs.size() == 1 ? "" : "s");
  std::printf("%-5s %12s %10s %7s\n", "group", "compared", "agree %", "kappa");
  for (const auto& g : pooled) {
    std::printf("%-5s %12lld ", std::string(groupInfo(g.group).shortName).c_str(),
                static_cast<long long>(g.comparedSteps));
    if (g.percent) {
      std::printf("%10.1f ", *g.percent);
    } else {
      std::printf("%10s ", "-");
    }
    if (g.kappa) {
      std::printf("%7.3f\n", *g.kappa);
    } else {
      std::printf("%7s\n", "-");
    }
  }
  return kExitOk;
}

// ---- labels from-model ----------------------------------------------------------------------

struct FromModelArgs {
  std::string db, set, model;
  std::vector<std::string> runs, groups;
  bool json = false;
};

int runLabelsFromModel(const FromModelArgs& a) {
  requireValidName(a.set, "--set", "label set");
  const std::vector<SensorGroup> groups = parseGroups(a.groups, "--groups");
  workspace::Workspace ws(openDatabaseForWrite(a.db));
  ProgressLine line("labels from-model", "runs");
  auto done = ws.labelFromModel(a.set, a.model, splitNames(a.runs), groups,
                                [&](std::size_t d, std::size_t total) {
                                  line.show(d, total);
                                  return true;
                                });
  if (!done) throw std::runtime_error(done.errorText());
  for (const std::string& warning : done->warnings)
    printWarning(warning);
  if (a.json) {
    printJson({{"set", a.set},
               {"model", a.model},
               {"annotator", workspace::modelAnnotator(a.model)},
               {"runs", done->runs},
               {"groups", done->groups},
               {"segments", done->segments}});
  } else {
    std::printf(
        "labelled %lld runs (%lld run-groups, %lld segments) in '%s' from model '%s' as "
        "%s\n",
        static_cast<long long>(done->runs), static_cast<long long>(done->groups),
        static_cast<long long>(done->segments), a.set.c_str(), a.model.c_str(),
        workspace::modelAnnotator(a.model).c_str());
  }
  return kExitOk;
}

}  // namespace

void registerTeamLabelVerbs(CLI::App& labels) {
  const char* dbHelp = "Database: a file or a PostgreSQL address";
  {
    auto a = std::make_shared<SetArgs>();
    CLI::App* cmd = labels.add_subcommand(
        "set",
        "Give steps of a run one class in the named groups, as one edit the history keeps (the "
        "set is created when absent)");
    cmd->add_option("--db", a->db, dbHelp)->envname("TACTILE_DB")->required();
    cmd->add_option("--set", a->set, "Label set name")->required();
    cmd->add_option("--run", a->run, "Run name")->required();
    cmd->add_option("--groups", a->groups, "Groups, e.g. F or F,L (F FLC L RLC B RRC R FRC)")
        ->required();
    cmd->add_option("--steps", a->steps, "Steps FIRST-LAST (inclusive, from 0)")->required();
    cmd->add_option("--class", a->cls, "NoContact, Wall, Corner, LeavingWall or DeadPath")
        ->required();
    cmd->add_option("--annotator", a->annotator,
                    "Who makes the edit (default: TACTILE_ANNOTATOR, else the login name)");
    cmd->add_option("--expect-revision", a->expectRevision,
                    "The revision the edit is based on (labels history): refused, storing "
                    "nothing, when a later revision changed any of its steps")
        ->check(CLI::NonNegativeNumber);
    cmd->add_flag(
        "--json", a->json,
        R"(Print {"set","run","groups","first_step","last_step","class","annotator","revision"})");
    setAction(cmd, [a] { return runLabelsSet(*a); });
  }
  {
    auto a = std::make_shared<HistoryArgs>();
    CLI::App* cmd = labels.add_subcommand(
        "history", "Show every edit of a set's labels on one run: who, when, which steps");
    cmd->add_option("--db", a->db, std::string(dbHelp) + " (opened read-only)")
        ->envname("TACTILE_DB")
        ->required();
    cmd->add_option("--set", a->set, "Label set name")->required();
    cmd->add_option("--run", a->run, "Run name")->required();
    cmd->add_flag(
        "--json", a->json,
        R"(Print {"set","run","revision","revisions":[{"revision","annotator","time","group","first_step","last_step","class","action","replaced"}]})");
    setAction(cmd, [a] { return runLabelsHistory(*a); });
  }
  {
    auto a = std::make_shared<AssignArgs>();
    CLI::App* cmd = labels.add_subcommand(
        "assign",
        "Assign runs (or one group of them) to an annotator, or move an assignment to labelled or "
        "reviewed");
    cmd->add_option("--db", a->db, dbHelp)->envname("TACTILE_DB")->required();
    cmd->add_option("--runs", a->runs, "Run names (A B or A,B)")->required();
    cmd->add_option("--group", a->group, "One group only (default: the whole run)");
    cmd->add_option("--to", a->to, "The annotator")->required();
    cmd->add_option("--set", a->set, "The label set to label in");
    cmd->add_option("--state", a->state, "todo (default), labelled or reviewed");
    cmd->add_flag("--remove", a->remove, "Remove the assignment instead");
    cmd->add_flag("--json", a->json, R"(Print {"runs","group","annotator","state"})");
    setAction(cmd, [a] { return runLabelsAssign(*a); });
  }
  {
    auto a = std::make_shared<AssignmentsArgs>();
    CLI::App* cmd = labels.add_subcommand("assignments", "List assignments and their states");
    cmd->add_option("--db", a->db, std::string(dbHelp) + " (opened read-only)")
        ->envname("TACTILE_DB")
        ->required();
    cmd->add_option("--annotator", a->annotator, "Only this annotator's");
    cmd->add_flag(
        "--json", a->json,
        R"(Print {"assignments":[{"run","group","annotator","set","state","updated_by","updated_at"}]})");
    setAction(cmd, [a] { return runLabelsAssignments(*a); });
  }
  {
    auto a = std::make_shared<FromModelArgs>();
    CLI::App* cmd = labels.add_subcommand(
        "from-model",
        "Label runs with a stored model's offline decision (annotator model:NAME), one edit per "
        "run and group that the history and undo keep; then fix what it got wrong");
    cmd->add_option("--db", a->db, dbHelp)->envname("TACTILE_DB")->required();
    cmd->add_option("--set", a->set, "Label set to write (created when absent)")->required();
    cmd->add_option("--model", a->model, "A stored model's name")->required();
    cmd->add_option("--runs", a->runs, "Runs (default: every stored run)");
    cmd->add_option("--groups", a->groups, "Groups (default: every group the model covers)");
    cmd->add_flag("--json", a->json,
                  R"(Print {"set","model","annotator","runs","groups","segments"})");
    setAction(cmd, [a] { return runLabelsFromModel(*a); });
  }
  {
    auto a = std::make_shared<AgreementArgs>();
    CLI::App* cmd = labels.add_subcommand(
        "agreement",
        "Agreement of two label sets (two annotators) per group: percent of steps and Cohen's "
        "kappa, over the steps both label");
    cmd->add_option("--db", a->db, std::string(dbHelp) + " (opened read-only)")
        ->envname("TACTILE_DB")
        ->required();
    cmd->add_option("--sets", a->sets, "The two label sets, A,B")->required();
    cmd->add_option("--runs", a->runs, "Runs (default: every run both sets label)");
    cmd->add_flag(
        "--json", a->json,
        R"(Print {"sets","runs":[{"run","groups":[...]}],"groups":[{"group","compared_steps","agreeing_steps","percent","kappa"}]})");
    setAction(cmd, [a] { return runLabelsAgreement(*a); });
  }
}

}  // namespace tactile::cli
