// Deterministic fuzzing of every reader of user files (docs/file-formats.md#hostile-input): a few
// thousand seeded mutants of the product's own run, label, model and scene files go through the
// core readers in process, and a few hundred more through the `tactile` command line. Checked:
// nothing crashes or hangs (the CTest timeout), every rejection names the file (and the line: CSV
// always, JSON for syntax errors; JSON content errors name the element instead), accepted input
// writes back to text that reads again, every message is valid UTF-8, and every `--json` verb
// prints exactly one valid JSON object whatever the bytes it met.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/features.h"
#include "analysis/model_file.h"
#include "analysis/training.h"
#include "base/text_rules.h"
#include "run/builtin_scenes.h"
#include "run/json_text.h"
#include "run/label_file.h"
#include "run/run_csv.h"
#include "run/synthetic_run.h"
#include "sim/scene.h"
#include "tests/analysis/learn_test_data.h"

namespace tactile {
namespace {

namespace fs = std::filesystem;
using Rng = std::mt19937_64;

std::size_t pick(Rng& rng, std::size_t n) {
  return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);
}

// Tokens that broke readers before, or are at the edge of a rule.
const std::vector<std::string>& csvTokens() {
  static const std::vector<std::string> tokens = {"-0",
                                                  "00",
                                                  "01",
                                                  "001",
                                                  "1e400",
                                                  "1e-400",
                                                  "nan",
                                                  "inf",
                                                  "",
                                                  "0\f",
                                                  "\xE9",
                                                  "\xC3",
                                                  "a,b",
                                                  "+1",
                                                  "0x10",
                                                  " 1",
                                                  "1 ",
                                                  "5.0000001",
                                                  "-5.1",
                                                  "1e308",
                                                  "4.9e-324",
                                                  "\r",
                                                  "#",
                                                  "Wall",
                                                  "wall",
                                                  "\"1\"",
                                                  "18446744073709551615",
                                                  "9223372036854775808",
                                                  "-9223372036854775808",
                                                  "\t",
                                                  std::string("\0", 1),
                                                  "\xEF\xBB\xBF"};
  return tokens;
}

const std::vector<std::string>& jsonTokens() {
  static const std::vector<std::string> tokens = {
      "1e400",     "-1e400",      "1e-400",   "18446744073709551615",
      "-1",        "0",           "null",     "true",
      "\"\"",      "[]",          "{}",       "\"a,b\"",
      "\"x\\ny\"", "\"\\u0000\"", "\"\xE9\"", "[[[[",
      "]",         "}",           ",",        "\"Wall\"",
      "1.5",       "-0",          "1e308",    "\f"};
  return tokens;
}

// Byte-level damage: flips, inserts, deletes, truncation, duplicated or deleted lines.
std::string mutateBytes(std::string text, Rng& rng) {
  static const std::string kBytes = ",\n\r-+e.0159#: xNaI\xEF\xE9\f\t\"[]{}";
  const int count = 1 + static_cast<int>(pick(rng, 3));
  for (int m = 0; m < count && !text.empty(); ++m) {
    const std::size_t at = pick(rng, text.size());
    const std::size_t lineBegin =
        text.rfind('\n', at) == std::string::npos ? 0 : text.rfind('\n', at) + 1;
    const std::size_t lineEnd = text.find('\n', at);
    switch (pick(rng, 7)) {
      case 0:
        text[at] = static_cast<char>(text[at] ^ (1 << pick(rng, 8)));
        break;
      case 1:
        text.insert(at, 1, kBytes[pick(rng, kBytes.size())]);
        break;
      case 2:
        text.erase(at, 1);
        break;
      case 3:
        text[at] = kBytes[pick(rng, kBytes.size())];
        break;
      case 4:
        text.resize(at);
        break;
      case 5:
        if (lineEnd != std::string::npos) {
          text.insert(lineBegin, text.substr(lineBegin, lineEnd - lineBegin + 1));
        }
        break;
      default:
        text.erase(lineBegin,
                   lineEnd == std::string::npos ? std::string::npos : lineEnd - lineBegin + 1);
        break;
    }
  }
  return text;
}

// Replaces one whole token (a CSV field, or a JSON number or string) by an interesting one.
std::string mutateToken(std::string text, Rng& rng, bool json) {
  if (text.empty()) return text;
  const std::vector<std::string>& tokens = json ? jsonTokens() : csvTokens();
  const std::string& token = tokens[pick(rng, tokens.size())];
  const std::size_t at = pick(rng, text.size());
  const std::string stops = json ? ",:[]{}\n" : ",\n";
  std::size_t begin = text.find_last_of(stops, at);
  begin = begin == std::string::npos ? 0 : begin + 1;
  std::size_t end = text.find_first_of(stops, at);
  if (end == std::string::npos) end = text.size();
  if (end < begin) end = begin;
  text.replace(begin, end - begin, json ? " " + token : token);
  return text;
}

std::string mutate(const std::string& seed, Rng& rng, bool json) {
  return pick(rng, 2) == 0 ? mutateBytes(seed, rng) : mutateToken(seed, rng, json);
}

// What every rejection must carry.
void expectNamedError(const Error& e, const std::string& file, bool lineRequired,
                      const std::string& input) {
  EXPECT_EQ(e.file, file) << e.text();
  EXPECT_FALSE(e.message.empty());
  if (lineRequired) {
    EXPECT_GT(e.line, 0u) << e.text() << "\ninput:\n" << shownText(input, 400);
  }
  EXPECT_TRUE(isValidUtf8(e.text())) << shownText(e.text());
}

// A JSON error is a syntax error (with line and column) or names the element it is about.
bool isJsonSyntaxError(const Error& e) {
  return e.message.find("not valid JSON") != std::string::npos ||
         e.message.find("invalid JSON") != std::string::npos;
}

// ---- seeds: the product's own files ------------------------------------------------------------

std::vector<std::string> runSeeds() {
  std::vector<std::string> seeds;
  RunData a = makeSyntheticRun(12, true, 1);
  a.metadata = {{"format", "tactile-run 1"}, {"scene", "room1"}, {"dt", "0.1"},
                {"start", "1,2,0.5"},        {"goal", "3,4"},    {"outcome", "success"}};
  seeds.push_back(formatRunCsv(a));
  RunData b = makeSyntheticRun(8, false, 2);
  b.extraColumns = {"x_note"};
  for (int i = 0; i < 8; ++i)
    b.extraValues.push_back("n" + std::to_string(i));
  seeds.push_back(formatRunCsv(b));
  return seeds;
}

std::vector<std::string> labelCsvSeeds() {
  std::vector<LabelRecord> records;
  for (int i = 0; i < 6; ++i) {
    LabelRecord r;
    r.run = i < 3 ? "room1_run_0000" : "run 2";
    r.group = static_cast<SensorGroup>(i % kGroupCount);
    r.firstStep = i * 10;
    r.lastStep = i * 10 + 9;
    r.cls = static_cast<ContactClass>(i % kContactClassCount);
    r.annotator = i % 2 ? "ann" : "";
    records.push_back(r);
  }
  const std::vector<LabelRunProvenance> runs = {{"room1_run_0000", 60, "3ecbddcee5e28d37", 0},
                                                {"run 2", 70, "d17975ca8831b6dc", 0}};
  return {formatLabelCsv(records, runs), formatLabelCsv(records),
          formatLabelJson(records, "set", "someone", runs)};
}

std::string modelSeed() {
  const RunData run = testdata::makeLabelledRun(600, 11);
  std::vector<analysis::LabelledRun> runs{{&run, analysis::labelsFromTruth(run)}};
  analysis::ModelBundle bundle;
  for (SensorGroup group : {SensorGroup::Right, SensorGroup::Front}) {
    const analysis::GroupDataSet data =
        analysis::buildGroupDataSet(runs, group, analysis::FeatureKind::Normal);
    analysis::TrainSettings settings;
    settings.classifier.method = analysis::ClassifierMethod::Gmm;
    settings.classifier.gmm.components = 2;
    settings.classifier.gmm.form = analysis::CovarianceForm::NodalDiag;
    settings.classifier.gmm.varianceFloor = 0.01;
    settings.classifier.gmm.seed = 5;
    analysis::GroupTrainResult r = analysis::trainGroupModel(data, settings);
    if (r.ok) bundle.models.push_back(std::move(r.model));
  }
  return dumpJson(analysis::bundleToJson(bundle), 1);
}

std::vector<std::string> sceneSeeds() {
  std::vector<std::string> seeds;
  for (const std::string& name : builtinSceneNames()) {
    if (auto text = builtinSceneJson(name)) seeds.emplace_back(*text);
  }
  return seeds;
}

// ---- in-process readers ------------------------------------------------------------------------

constexpr int kRunMutants = 2500;
constexpr int kLabelMutants = 1500;
constexpr int kModelMutants = 800;
constexpr int kSceneMutants = 800;

TEST(Fuzz, RunFiles) {
  const std::vector<std::string> seeds = runSeeds();
  Rng rng(1);
  int accepted = 0;
  for (int i = 0; i < kRunMutants; ++i) {
    const std::string text = mutate(seeds[static_cast<std::size_t>(i) % seeds.size()], rng, false);
    const RunCsvResult result = parseRunCsv(text, "m.csv");
    // Chunked parsing gives the same answer, the same first error included.
    const RunCsvResult chunked = parseRunCsvParallel(text, "m.csv", 2, 64 + i % 300);
    ASSERT_EQ(result.ok(), chunked.ok()) << i;
    if (!result.ok()) {
      EXPECT_EQ(result.errorText(), chunked.errorText());
      expectNamedError(result.error(), "m.csv", true, text);
      continue;
    }
    ++accepted;
    const std::string again = formatRunCsv(result.value());
    const RunCsvResult back = parseRunCsv(again, "again.csv");
    ASSERT_TRUE(back.ok()) << back.errorText();
    EXPECT_EQ(formatRunCsv(back.value()), again) << i;
  }
  EXPECT_GT(accepted, kRunMutants / 50);
  EXPECT_LT(accepted, kRunMutants / 2);
}

// Header and metadata shapes: many columns and many metadata lines (around the limits), with a
// repeat put first, last or anywhere. Every file is refused or read in full, at once (one look-up
// per column and key), with the file and line named, and chunked parsing agrees.
TEST(Fuzz, HeaderAndMetadataShapes) {
  const std::string seed = runSeeds().front();
  const std::size_t headerAt = seed.find("\nstep,") + 1;
  const std::string metadata = seed.substr(0, headerAt);
  const std::size_t headerEnd = seed.find('\n', headerAt);
  const std::string header = seed.substr(headerAt, headerEnd - headerAt);
  const std::string rows = seed.substr(headerEnd);
  const std::size_t baseColumns =
      static_cast<std::size_t>(std::count(header.begin(), header.end(), ',')) + 1;
  Rng rng(7);
  int refusedForSize = 0;
  int refusedForRepeat = 0;
  for (int i = 0; i < 60; ++i) {
    SCOPED_TRACE(i);
    // Columns: a few, up to the limit, or past it.
    const std::size_t extras =
        pick(rng, 3) == 0 ? pick(rng, 20) : kMaxRunColumns - baseColumns - 5 + pick(rng, 12);
    std::vector<std::string> names;
    std::size_t at = 0;
    for (std::size_t start = 0;; start = at + 1) {
      at = header.find(',', start);
      names.push_back(
          header.substr(start, at == std::string::npos ? std::string::npos : at - start));
      if (at == std::string::npos) break;
    }
    for (std::size_t e = 0; e < extras; ++e)
      names.push_back("x_" + std::to_string(e));
    // Metadata: the seed's lines, then none, a few or about the limit more.
    std::string head = metadata;
    const std::size_t keys =
        pick(rng, 3) == 0 ? kMaxRunMetadataLines - 8 + pick(rng, 12) : pick(rng, 5);
    for (std::size_t k = 0; k < keys; ++k)
      head += "# key" + std::to_string(k) + ": v\n";
    const int repeat = static_cast<int>(pick(rng, 4));  // 0: none, 1: a column, 2: a key, 3: both
    if (repeat & 1) {
      const std::size_t from = pick(rng, 2) == 0 ? 0 : pick(rng, names.size());
      const std::string copy = names[from];
      if (pick(rng, 2) == 0) {
        names.push_back(copy);
      } else {
        names.insert(names.begin() + static_cast<std::ptrdiff_t>(pick(rng, names.size() + 1)),
                     copy);
      }
    }
    if (repeat & 2) head += "# scene: again\n";
    std::string line;
    for (const std::string& n : names)
      line += (line.empty() ? "" : ",") + n;
    const std::string text = head + line + rows;
    const RunCsvResult result = parseRunCsv(text, "m.csv");
    const RunCsvResult chunked = parseRunCsvParallel(text, "m.csv", 2, 64 + pick(rng, 300));
    ASSERT_EQ(result.ok(), chunked.ok());
    if (result.ok()) continue;  // a few extras and no repeat: the rows lack the extra fields
    EXPECT_EQ(result.errorText(), chunked.errorText());
    expectNamedError(result.error(), "m.csv", true, text.substr(0, 400));
    const std::string& m = result.error().message;
    if (m.find("too many") != std::string::npos) ++refusedForSize;
    if (m.find("duplicate column") != std::string::npos ||
        m.find("repeated metadata key") != std::string::npos)
      ++refusedForRepeat;
    // Past the limit the header is refused for its size, unless a repeat comes first.
    if (names.size() > kMaxRunColumns && m.find("metadata") == std::string::npos) {
      if (m.find("duplicate column") != std::string::npos) {
        EXPECT_LE(result.error().column, kMaxRunColumns) << m;
      } else {
        EXPECT_NE(m.find("too many columns"), std::string::npos) << m;
      }
    }
  }
  EXPECT_GT(refusedForSize, 0);
  EXPECT_GT(refusedForRepeat, 0);
}

TEST(Fuzz, LabelFiles) {
  const std::vector<std::string> seeds = labelCsvSeeds();
  Rng rng(2);
  int accepted = 0;
  for (int i = 0; i < kLabelMutants; ++i) {
    const std::size_t s = static_cast<std::size_t>(i) % seeds.size();
    const bool json = s == 2;
    const std::string text = mutate(seeds[s], rng, json);
    const std::string name = json ? "l.json" : "l.csv";
    const Result<LabelFile> result = json ? parseLabelJson(text, name) : parseLabelCsv(text, name);
    if (!result.ok()) {
      expectNamedError(result.error(), name, !json || isJsonSyntaxError(result.error()), text);
      continue;
    }
    ++accepted;
    for (const LabelRecord& r : result->records) {
      EXPECT_EQ(nameProblem(r.run), std::nullopt) << shownText(r.run);
      if (!r.annotator.empty()) {
        EXPECT_EQ(nameProblem(r.annotator), std::nullopt);
      }
    }
    // What was read writes back to files that read again, the same records.
    const auto csv = parseLabelCsv(formatLabelCsv(result->records, result->runs), "w.csv");
    ASSERT_TRUE(csv.ok()) << csv.errorText();
    EXPECT_EQ(csv->records.size(), result->records.size());
    const auto back =
        parseLabelJson(formatLabelJson(result->records, "set", "", result->runs), "w.json");
    ASSERT_TRUE(back.ok()) << back.errorText();
    EXPECT_EQ(back->records.size(), result->records.size());
  }
  EXPECT_GT(accepted, kLabelMutants / 50);
}

TEST(Fuzz, ModelFiles) {
  const std::string seed = modelSeed();
  ASSERT_TRUE(analysis::parseModelJson(seed, "seed.json").ok());
  Rng rng(3);
  int accepted = 0;
  for (int i = 0; i < kModelMutants; ++i) {
    const std::string text = mutate(seed, rng, true);
    const Result<analysis::ModelBundle> result = analysis::parseModelJson(text, "m.json");
    if (!result.ok()) {
      expectNamedError(result.error(), "m.json", isJsonSyntaxError(result.error()), text);
      continue;
    }
    ++accepted;
    const std::string again = dumpJson(analysis::bundleToJson(result.value()));
    const auto back = analysis::parseModelJson(again, "again.json");
    ASSERT_TRUE(back.ok()) << back.errorText();
  }
  EXPECT_GT(accepted, 0);
}

TEST(Fuzz, SceneFiles) {
  const std::vector<std::string> seeds = sceneSeeds();
  ASSERT_FALSE(seeds.empty());
  Rng rng(4);
  int accepted = 0;
  for (int i = 0; i < kSceneMutants; ++i) {
    const std::string text = mutate(seeds[static_cast<std::size_t>(i) % seeds.size()], rng, true);
    const Result<sim::Scene> result = sim::parseSceneJson(text, "s.json");
    if (!result.ok()) {
      expectNamedError(result.error(), "s.json", isJsonSyntaxError(result.error()), text);
      continue;
    }
    ++accepted;
    const auto back = sim::parseSceneJson(sim::sceneToJson(result.value()), "again.json");
    ASSERT_TRUE(back.ok()) << back.errorText();
  }
  EXPECT_GT(accepted, 0);
}

// ---- the command line --------------------------------------------------------------------------
#ifdef TACTILE_CLI

struct Ran {
  int exitCode = -1;
  std::string out;
  std::string err;
};

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string quoted(const std::string& arg) {
  std::string q = "'";
  for (char c : arg)
    q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

Ran runCli(const fs::path& dir, const std::vector<std::string>& args) {
  std::string command = quoted(TACTILE_CLI);
  for (const std::string& a : args)
    command += " " + quoted(a);
  command +=
      " > " + quoted((dir / "out.txt").string()) + " 2> " + quoted((dir / "err.txt").string());
  const int status = std::system(command.c_str());
  Ran r;
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(dir / "out.txt");
  r.err = slurp(dir / "err.txt");
  return r;
}

// Exactly one valid JSON object on one line.
nlohmann::json expectOneJsonObject(const Ran& r, const std::string& what) {
  EXPECT_TRUE(r.exitCode == 0 || r.exitCode == 1) << what << " exit " << r.exitCode << "\n"
                                                  << r.err;
  EXPECT_FALSE(r.out.empty()) << what << ": nothing on stdout\n" << r.err;
  EXPECT_EQ(r.out.find('\n'), r.out.size() - 1) << what << ": more than one line";
  Result<nlohmann::json> doc = parseJsonText(r.out, what);
  EXPECT_TRUE(doc.ok()) << what << ": " << doc.errorText() << "\n" << shownText(r.out, 400);
  if (!doc.ok()) return {};
  EXPECT_TRUE(doc->is_object()) << what;
  return doc.value();
}

class FuzzCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("tactile_fuzz_cli_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

void writeFile(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

TEST_F(FuzzCli, JsonVerbsPrintOneValidObjectWhateverTheBytes) {
  const fs::path runs = dir_ / "runs,x";  // a folder with a comma: never split
  fs::create_directories(runs);
  const std::vector<std::string> seeds = runSeeds();
  // Clean runs under hostile file names, then mutants.
  writeFile(runs / "caf\xE9.csv", formatRunCsv(makeSyntheticRun(7, true, 12)));
  writeFile(runs / "run,one.csv", formatRunCsv(makeSyntheticRun(6, true, 11)));
  writeFile(runs / "tab\there.csv", formatRunCsv(makeSyntheticRun(5, true, 9)));
  Rng rng(5);
  constexpr int kFiles = 300;
  for (int i = 0; i < kFiles; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "m%03d.csv", i);
    writeFile(runs / name, mutate(seeds[static_cast<std::size_t>(i) % seeds.size()], rng, false));
  }
  const std::string db = (dir_ / "f.db").string();
  Ran r = runCli(dir_, {"import", "--db", db, "--json", runs.string()});
  nlohmann::json doc = expectOneJsonObject(r, "import --json");
  ASSERT_TRUE(doc.contains("failed") && doc.contains("runs"));
  EXPECT_GT(doc["failed"].size(), 0u);
  EXPECT_GT(doc["runs"].size(), 1u);
  bool sawInvalidName = false;
  for (const nlohmann::json& f : doc["failed"]) {
    const std::string file = f["file"].get<std::string>();
    const std::string message = f["message"].get<std::string>();
    EXPECT_EQ(message.rfind(file, 0), 0u) << message;
    if (message.find("run name") != std::string::npos) {
      sawInvalidName = true;  // a file name that cannot name a run: no line to give
      continue;
    }
    // FILE:LINE: message
    const std::string rest = message.substr(file.size());
    ASSERT_GE(rest.size(), 3u) << message;
    EXPECT_EQ(rest[0], ':') << message;
    EXPECT_TRUE(rest[1] >= '1' && rest[1] <= '9') << message;
  }
  EXPECT_TRUE(sawInvalidName) << "caf\\xE9.csv was not refused";
  bool sawCommaRun = false;
  for (const nlohmann::json& run : doc["runs"]) {
    const std::string name = run["name"].get<std::string>();
    EXPECT_EQ(nameProblem(name), std::nullopt) << name;
    sawCommaRun = sawCommaRun || name == "run_one";
  }
  EXPECT_TRUE(sawCommaRun) << "run,one.csv was not imported as run_one";

  expectOneJsonObject(runCli(dir_, {"runs", "list", "--db", db, "--json"}), "runs list");
  ASSERT_EQ(runCli(dir_, {"autolabel", "--db", db, "--all", "--set", "truth", "--json"}).exitCode,
            0);

  // Label files: mutants of the product's own, imported one by one.
  const std::vector<std::string> labelSeeds = labelCsvSeeds();
  for (int i = 0; i < 24; ++i) {
    const bool json = i % 3 == 2;
    const fs::path file = dir_ / (json ? "l.json" : "l.csv");
    writeFile(file, mutate(labelSeeds[static_cast<std::size_t>(i) % labelSeeds.size()], rng, json));
    const Ran imported = runCli(dir_, {"labels", "import", "--db", db, "--set",
                                       "s" + std::to_string(i), "--json", file.string()});
    if (imported.exitCode == 0) {
      expectOneJsonObject(imported, "labels import");
    } else {
      EXPECT_EQ(imported.exitCode, 1) << imported.err;
      EXPECT_NE(imported.err.find(file.string()), std::string::npos) << imported.err;
      EXPECT_TRUE(isValidUtf8(imported.err)) << shownText(imported.err);
    }
  }
  expectOneJsonObject(runCli(dir_, {"labels", "list", "--db", db, "--json"}), "labels list");
  const Ran exported = runCli(dir_, {"labels", "export", "--db", db, "--set", "truth", "--json",
                                     (dir_ / "truth.json").string()});
  expectOneJsonObject(exported, "labels export");
  EXPECT_TRUE(parseJsonText(slurp(dir_ / "truth.json"), "truth.json").ok());

  // Model files.
  const std::string model = modelSeed();
  for (int i = 0; i < 24; ++i) {
    const fs::path file = dir_ / ("model" + std::to_string(i) + ".json");
    writeFile(file, mutate(model, rng, true));
    const Ran imported = runCli(dir_, {"models", "import", "--db", db, "--json", file.string()});
    if (imported.exitCode == 0) {
      expectOneJsonObject(imported, "models import");
    } else {
      EXPECT_EQ(imported.exitCode, 1) << imported.err;
      EXPECT_NE(imported.err.find(file.string()), std::string::npos) << imported.err;
    }
  }
  expectOneJsonObject(runCli(dir_, {"models", "list", "--db", db, "--json"}), "models list");
}
#endif  // TACTILE_CLI

}  // namespace
}  // namespace tactile
