// Model files: round trip bit for bit (docs/learning.md, "Stability cases") and validation of bad
// files, one test per defect.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <random>

#include <unistd.h>

#include "analysis/model_file.h"
#include "analysis/report.h"
#include "analysis/training.h"
#include "run/json_text.h"
#include "tests/analysis/learn_test_data.h"

namespace tactile::analysis {
namespace {

using nlohmann::json;

// A trained model of the right side group for the given method and covariance form, into `out`.
// Everything after the training depends on it: a failed training stops here (ASSERT_), and
// callers wrap the call in ASSERT_NO_FATAL_FAILURE so that the test stops too instead of going on
// with an empty model.
void trainModel(GroupModel& out, ClassifierMethod method, CovarianceForm form, int order = 3) {
  static const RunData run = testdata::makeLabelledRun(1500, 11);
  std::vector<LabelledRun> runs{{&run, labelsFromTruth(run)}};
  const GroupDataSet data = buildGroupDataSet(runs, SensorGroup::Right, FeatureKind::Normal);
  TrainSettings settings;
  settings.classifier.method = method;
  settings.classifier.gmm.components = order;
  settings.classifier.gmm.form = form;
  settings.classifier.gmm.varianceFloor = 0.01;
  settings.classifier.gmm.seed = 5;
  GroupTrainResult r = trainGroupModel(data, settings);
  ASSERT_TRUE(r.ok) << r.reason;
  r.model.provenance.trainRuns = {{"synthetic", 1500, "", "room1"}};
  r.model.provenance.labels = "truth columns";
  r.model.provenance.classifier = settings.classifier;
  r.model.evaluation.evaluatedOn = "test runs";
  r.model.evaluation.byDecision[0].add(ContactClass::Wall, ContactClass::Wall, 7);
  r.model.evaluation.byDecision[1].add(ContactClass::Wall, ContactClass::Corner, 2);
  out = std::move(r.model);
}

Eigen::MatrixXd probeRows() {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 5.0);
  Eigen::MatrixXd x(200, 10);
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    for (Eigen::Index j = 0; j < x.cols(); ++j)
      x(i, j) = u(rng);
  }
  return x;
}

bool bitIdentical(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() &&
         std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0;
}

void expectSamePredictions(const GroupModel& original, const GroupModel& loaded) {
  const Eigen::MatrixXd x = probeRows();
  Eigen::MatrixXd a, b;
  original.classifier.logLikelihoods(x, a);
  loaded.classifier.logLikelihoods(x, b);
  EXPECT_TRUE(bitIdentical(a, b));
  EXPECT_EQ(original.classifier.predict(x), loaded.classifier.predict(x));
  EXPECT_EQ(loaded.classes, original.classes);
  EXPECT_EQ(loaded.group, original.group);
  EXPECT_EQ(loaded.features, original.features);
  EXPECT_EQ(loaded.covariance, original.covariance);
  EXPECT_EQ(loaded.varianceFloor, original.varianceFloor);
  EXPECT_EQ(loaded.provenance.trainRuns, original.provenance.trainRuns);
  EXPECT_EQ(loaded.provenance.labels, original.provenance.labels);
  if (original.classifier.method() == ClassifierMethod::Gmm) {  // the Gaussian has no order
    EXPECT_EQ(loaded.provenance.classifier.gmm.components,
              original.provenance.classifier.gmm.components);
  }
  EXPECT_EQ(loaded.provenance.classifier.gmm.seed, original.provenance.classifier.gmm.seed);
  EXPECT_EQ(loaded.evaluation.evaluatedOn, original.evaluation.evaluatedOn);
  EXPECT_EQ(loaded.evaluation.byDecision, original.evaluation.byDecision);
  EXPECT_EQ(loaded.decision, original.decision);
  EXPECT_TRUE(bitIdentical(loaded.transitions.logTransition, original.transitions.logTransition));
  EXPECT_TRUE(bitIdentical(loaded.transitions.logInitial, original.transitions.logInitial));
}

// Stability case 9: a model file round trip gives identical predictions, bit for
// bit, for every covariance form.
TEST(ModelFile, RoundTripIsBitIdenticalForEveryForm) {
  for (CovarianceForm form : kAllCovarianceForms) {
    SCOPED_TRACE(std::string(covarianceFormName(form)));
    GroupModel model;
    ASSERT_NO_FATAL_FAILURE(trainModel(model, ClassifierMethod::Gmm, form));
    const std::string text = modelToJson(model).dump(1);
    const Result<ModelBundle> read = parseModelJson(text, "m.json");
    ASSERT_TRUE(read.ok()) << read.errorText();
    ASSERT_EQ(read->models.size(), 1u);
    expectSamePredictions(model, read->models[0]);
  }
}

TEST(ModelFile, GaussianWithRestModelsRoundTrips) {
  GroupModel model;
  ASSERT_NO_FATAL_FAILURE(trainModel(model, ClassifierMethod::Gaussian, CovarianceForm::NodalFull));
  ASSERT_TRUE(model.classifier.hasRestModels());
  const Result<ModelBundle> read = parseModelJson(modelToJson(model).dump(), "m.json");
  ASSERT_TRUE(read.ok()) << read.errorText();
  const GroupModel& loaded = read->models[0];
  ASSERT_TRUE(loaded.classifier.hasRestModels());
  expectSamePredictions(model, loaded);
  Eigen::VectorXd a, b;
  model.classifier.oneVsRestLogRatio(probeRows(), 0, a);
  loaded.classifier.oneVsRestLogRatio(probeRows(), 0, b);
  EXPECT_TRUE(bitIdentical(a, b));
}

// A model of gradient-boosted trees keeps its trees in the file: read back, it gives the same
// scaled likelihoods and decisions bit for bit, and its tree settings come back with it.
TEST(ModelFile, BoostedTreesRoundTripBitForBit) {
  GroupModel model;
  ASSERT_NO_FATAL_FAILURE(trainModel(model, ClassifierMethod::Gbt, CovarianceForm::NodalDiag));
  ASSERT_NE(model.classifier.trees(), nullptr);
  const json written = modelToJson(model);
  EXPECT_EQ(written["method"], "gbt");
  EXPECT_EQ(written["version"], kGbtModelVersion);
  EXPECT_FALSE(written.contains("components"));
  const Result<ModelBundle> read = parseModelJson(written.dump(1), "m.json");
  ASSERT_TRUE(read.ok()) << read.errorText();
  const GroupModel& loaded = read->models[0];
  ASSERT_NE(loaded.classifier.trees(), nullptr);
  expectSamePredictions(model, loaded);
  EXPECT_EQ(loaded.provenance.classifier.gbt.trees, model.provenance.classifier.gbt.trees);
  EXPECT_EQ(loaded.provenance.classifier.gbt.depth, model.provenance.classifier.gbt.depth);
  // Written again, the file is the same.
  EXPECT_EQ(modelToJson(loaded).dump(), written.dump());
  // Trees in a file of an older version, or damaged trees, are refused with the field's path.
  json old = written;
  old["version"] = 4;
  auto refused = modelsFromJson(old, "old.json");
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.errorText().find("gbt needs version 5"), std::string::npos)
      << refused.errorText();
  json damaged = written;
  damaged["gbt"]["model"] = json::object({{"learner", 3}});
  auto broken = modelsFromJson(damaged, "broken.json");
  ASSERT_FALSE(broken.ok());
  EXPECT_NE(broken.errorText().find("gbt.model"), std::string::npos) << broken.errorText();
}

// The report of a bundle mixing families: trees show their settings in a column of their own and
// no covariance, order or floor (they have none); a bundle of mixtures alone has no such column.
TEST(ModelFile, ReportGivesTreesTheirOwnSettingsColumn) {
  GroupModel trees;
  ASSERT_NO_FATAL_FAILURE(trainModel(trees, ClassifierMethod::Gbt, CovarianceForm::NodalDiag));
  GroupModel mixture;
  ASSERT_NO_FATAL_FAILURE(trainModel(mixture, ClassifierMethod::Gmm, CovarianceForm::NodalDiag));
  const std::string settings = describeGbtSettings(trees.provenance.classifier.gbt);
  // A fit record as training writes one per class: its dropped count is a mixtures' figure.
  trees.evaluation.fit.assign(static_cast<std::size_t>(trees.classifier.classCount()),
                              ClassFitRecord{});
  ModelBundle both;
  both.models.push_back(std::move(trees));
  both.models.push_back(std::move(mixture));
  const std::string report = modelReport(both, TableStyle::Csv);
  const auto line = [&](const std::string& method) {
    const std::size_t at = report.find("," + method + ",");
    if (at == std::string::npos) return std::string();
    const std::size_t begin = report.rfind('\n', at) + 1;
    return report.substr(begin, report.find('\n', at) - begin);
  };
  EXPECT_NE(report.find("group,features,method,covariance,order,floor,trees,dropped"),
            std::string::npos)
      << report;
  const std::string treeRow = line("gbt");
  ASSERT_FALSE(treeRow.empty()) << report;
  // No covariance, order, floor or dropped components: the trees' settings alone.
  EXPECT_NE(treeRow.find(",gbt,,,,\"" + settings + "\",,"), std::string::npos) << treeRow;
  const std::string gmmRow = line("gmm");
  ASSERT_FALSE(gmmRow.empty()) << report;
  EXPECT_NE(gmmRow.find(",gmm,nodal-diag,"), std::string::npos) << gmmRow;
  both.models.erase(both.models.begin());
  EXPECT_EQ(modelReport(both, TableStyle::Csv).find(",trees,"), std::string::npos);
}

TEST(ModelFile, BundleFileRoundTripThroughDisk) {
  ModelBundle bundle;
  GroupModel first;
  ASSERT_NO_FATAL_FAILURE(trainModel(first, ClassifierMethod::Gmm, CovarianceForm::NodalDiag));
  bundle.models.push_back(std::move(first));
  GroupModel second;
  ASSERT_NO_FATAL_FAILURE(trainModel(second, ClassifierMethod::Gmm, CovarianceForm::GrandFull, 2));
  second.group = SensorGroup::Left;  // same dimension (10), so it stays valid
  bundle.models.push_back(std::move(second));
  const auto path = std::filesystem::temp_directory_path() /
                    ("tactile_model_test_" + std::to_string(::getpid()) + ".json");
  ASSERT_TRUE(writeModelBundleFile(path, bundle).ok());
  const Result<ModelBundle> read = readModelFile(path);
  std::filesystem::remove(path);
  ASSERT_TRUE(read.ok()) << read.errorText();
  ASSERT_EQ(read->models.size(), 2u);
  ASSERT_NE(read->find(SensorGroup::Left), nullptr);
  EXPECT_EQ(read->find(SensorGroup::Front), nullptr);
  expectSamePredictions(bundle.models[0], *read->find(SensorGroup::Right));
  expectSamePredictions(bundle.models[1], *read->find(SensorGroup::Left));
}

TEST(ModelFile, JsonDoublesReadBackBitForBit) {
  std::mt19937_64 rng(42);
  std::vector<double> values{
      0.1, 1.0 / 3.0, 1e-300, 4.9e-324, 1.7976931348623157e308, -2.5e-17, 0.0, 123456789.123456789};
  std::uniform_int_distribution<std::uint64_t> bits;
  while (values.size() < 5000) {
    const std::uint64_t b = bits(rng);
    double d;
    std::memcpy(&d, &b, sizeof d);
    if (std::isfinite(d)) values.push_back(d);
  }
  const json back = json::parse(json(values).dump());
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double d = back[i].get<double>();
    ASSERT_EQ(std::memcmp(&d, &values[i], sizeof d), 0) << values[i];
  }
}

// --- validation: each defect its own test ----------------------------------------------------

// Null (the training's failure recorded) when the model cannot be trained.
json validModelJson() {
  static const json j = [] {
    GroupModel model;
    trainModel(model, ClassifierMethod::Gmm, CovarianceForm::NodalFull, 2);
    return ::testing::Test::HasFatalFailure() ? json() : modelToJson(model);
  }();
  return j;
}

std::string errorOf(const json& j) {
  const Result<ModelBundle> r = parseModelJson(j.dump(), "bad.json");
  EXPECT_FALSE(r.ok());
  return r.ok() ? std::string() : r.errorText();
}

std::string firstClass(const json& j) {
  return j["classes"][0].get<std::string>();
}

TEST(ModelFileValidation, SyntaxErrorNamesLine) {
  const Result<ModelBundle> r =
      parseModelJson("{\n\"format\": \"tactile-model\",\n  oops\n}", "bad.json");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.errorText().rfind("bad.json:3:", 0), 0u) << r.errorText();
}

TEST(ModelFileValidation, WrongFormat) {
  json j = validModelJson();
  j["format"] = "something-else";
  EXPECT_NE(errorOf(j).find("format"), std::string::npos);
}

TEST(ModelFileValidation, WrongVersion) {
  json j = validModelJson();
  j["version"] = 6;  // versions 1 to 5 read
  EXPECT_NE(errorOf(j).find("expected version 1 to 5"), std::string::npos) << errorOf(j);
  j["version"] = 0;
  EXPECT_NE(errorOf(j).find("expected version 1 to 5"), std::string::npos) << errorOf(j);
}

TEST(ModelFileValidation, MissingField) {
  json j = validModelJson();
  j.erase("method");
  EXPECT_NE(errorOf(j).find("missing field 'method'"), std::string::npos);
}

TEST(ModelFileValidation, UnknownClass) {
  json j = validModelJson();
  j["classes"][0] = "Wal";
  EXPECT_NE(errorOf(j).find("unknown contact class 'Wal'"), std::string::npos);
}

TEST(ModelFileValidation, WeightsNotSummingToOne) {
  json j = validModelJson();
  j["components"][firstClass(j)]["weights"][0] = 5.0;
  EXPECT_NE(errorOf(j).find("weights"), std::string::npos);
}

TEST(ModelFileValidation, NegativeWeight) {
  json j = validModelJson();
  auto& w = j["components"][firstClass(j)]["weights"];
  const double a = w[0].get<double>(), b = w[1].get<double>();
  w[0] = -0.5;
  w[1] = a + b + 0.5;
  EXPECT_NE(errorOf(j).find("negative"), std::string::npos);
}

TEST(ModelFileValidation, MeansWrongShape) {
  json j = validModelJson();
  j["components"][firstClass(j)]["means"][0].erase(0);
  EXPECT_NE(errorOf(j).find("means[0]"), std::string::npos);
}

TEST(ModelFileValidation, CovarianceNotSymmetric) {
  json j = validModelJson();
  auto& cov = j["components"][firstClass(j)]["covariances"][0];
  cov[0][1] = cov[0][1].get<double>() + 0.5;
  const std::string e = errorOf(j);
  EXPECT_NE(e.find("not symmetric"), std::string::npos) << e;
  EXPECT_NE(e.find("covariances[0]"), std::string::npos) << e;
}

TEST(ModelFileValidation, CovarianceNotPositiveDefinite) {
  json j = validModelJson();
  auto& cov = j["components"][firstClass(j)]["covariances"][1];
  // Off-diagonal (0,1) larger than both variances: symmetric, positive diagonal, indefinite.
  const double big = 10.0 * (cov[0][0].get<double>() + cov[1][1].get<double>());
  cov[0][1] = big;
  cov[1][0] = big;
  EXPECT_NE(errorOf(j).find("positive definite"), std::string::npos);
}

TEST(ModelFileValidation, NonPositiveVariance) {
  json j = validModelJson();
  j["components"][firstClass(j)]["covariances"][0][2][2] = 0.0;
  const std::string error = errorOf(j);
  EXPECT_NE(error.find("not positive"), std::string::npos);
  // The third feature counted from 1 (it once said "variance 2", an index from 0).
  EXPECT_NE(error.find("the variance of feature 3 of "), std::string::npos) << error;
}

TEST(ModelFileValidation, WrongCovarianceCountForForm) {
  json j = validModelJson();
  j["covariance"] = "grand-full";  // grand forms store one covariance, the file has two
  EXPECT_NE(errorOf(j).find("expected 1 covariance"), std::string::npos);
}

TEST(ModelFileValidation, DiagonalFormWithOffDiagonalEntries) {
  GroupModel model;
  ASSERT_NO_FATAL_FAILURE(trainModel(model, ClassifierMethod::Gmm, CovarianceForm::NodalDiag, 2));
  json j = modelToJson(model);
  const std::string c = firstClass(j);
  json diag = j["components"][c]["covariances"][0];
  json full = json::array();
  for (std::size_t r = 0; r < diag.size(); ++r) {
    json row = json::array();
    for (std::size_t q = 0; q < diag.size(); ++q)
      row.push_back(r == q ? diag[r] : json(0.0));
    full.push_back(row);
  }
  full[0][1] = 0.01;
  full[1][0] = 0.01;
  j["components"][c]["covariances"][0] = full;
  EXPECT_NE(errorOf(j).find("off-diagonal"), std::string::npos);
}

TEST(ModelFileValidation, MissingClassComponents) {
  json j = validModelJson();
  j["components"].erase(firstClass(j));
  EXPECT_FALSE(errorOf(j).empty());
}

TEST(ModelFileValidation, DimensionMustMatchGroupFeatures) {
  json j = validModelJson();
  j["group"] = "F";  // 8 sensors, the model has 10 dimensions
  EXPECT_NE(errorOf(j).find("means"), std::string::npos);
}

TEST(ModelFileValidation, DuplicateGroupInBundle) {
  json bundle = {{"format", "tactile-model-bundle"},
                 {"version", 1},
                 {"models", {validModelJson(), validModelJson()}}};
  EXPECT_NE(errorOf(bundle).find("second model"), std::string::npos);
}

TEST(ModelFileValidation, MissingFileIsError) {
  const Result<ModelBundle> r = readModelFile("/nonexistent/dir/model.json");
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.errorText().find("/nonexistent/dir/model.json"), std::string::npos);
}

// Regression: a number too large for a double (1e400) escaped the reader as a bare nlohmann
// exception, without the file's name.
TEST(ModelFileHostile, NumberOverflowNamesFileLineAndColumn) {
  GroupModel model;
  ASSERT_NO_FATAL_FAILURE(trainModel(model, ClassifierMethod::Gaussian, CovarianceForm::NodalFull));
  std::string text = dumpJson(modelToJson(model), 1);
  const std::size_t at = text.find("\"variance_floor\": ");
  ASSERT_NE(at, std::string::npos);
  const std::size_t value = at + std::string("\"variance_floor\": ").size();
  text.replace(value, text.find_first_of(",\n", value) - value, "1e400");
  std::size_t line = 1;
  for (std::size_t i = 0; i < value; ++i)
    line += text[i] == '\n';
  const auto r = parseModelJson(text, "big.json");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().file, "big.json");
  EXPECT_EQ(r.error().line, line) << r.errorText();
  EXPECT_GT(r.error().column, 0u);
  EXPECT_NE(r.errorText().find("overflow"), std::string::npos) << r.errorText();
  EXPECT_NE(r.errorText().find("1e400"), std::string::npos) << r.errorText();
}

// A model trained now carries its class chain and decides online by default.
TEST(ModelFile, TrainedModelHasTransitionsAndDecidesOnline) {
  GroupModel model;
  ASSERT_NO_FATAL_FAILURE(trainModel(model, ClassifierMethod::Gmm, CovarianceForm::NodalDiag));
  ASSERT_FALSE(model.transitions.empty());
  EXPECT_EQ(model.transitions.classCount(), static_cast<int>(model.classes.size()));
  EXPECT_EQ(model.decision, DecisionMode::Online);
  const json j = modelToJson(model);
  EXPECT_EQ(j["version"], 2);
  EXPECT_EQ(j["decision"], "online");
  EXPECT_EQ(j["transitions"]["log_matrix"].size(), model.classes.size());
}

// A model on the neighbours features is written as version 3, reads back with the same
// predictions, and a version-2 file that claims those features is refused by name; a bundle takes
// the highest version of its models.
TEST(ModelFile, NeighbourFeaturesNeedVersionThree) {
  static const RunData run = testdata::makeLabelledRun(1500, 11);
  std::vector<LabelledRun> runs{{&run, labelsFromTruth(run)}};
  const GroupDataSet data = buildGroupDataSet(runs, SensorGroup::Right, FeatureKind::Neighbours);
  TrainSettings settings;
  settings.classifier.method = ClassifierMethod::Gmm;
  settings.classifier.gmm.components = 2;
  settings.classifier.gmm.form = CovarianceForm::NodalFull;
  settings.classifier.gmm.varianceFloor = 0.01;
  settings.features = FeatureKind::Neighbours;
  GroupTrainResult r = trainGroupModel(data, settings);
  ASSERT_TRUE(r.ok) << r.reason;
  ASSERT_EQ(r.model.features, FeatureKind::Neighbours);
  const json j = modelToJson(r.model);
  EXPECT_EQ(j["version"], 3);
  EXPECT_EQ(j["features"], "normal+shear+touch+context+neighbours");
  const Result<ModelBundle> read = parseModelJson(j.dump(1), "n.json");
  ASSERT_TRUE(read.ok()) << read.errorText();
  ASSERT_EQ(read->models.size(), 1u);
  EXPECT_EQ(read->models[0].features, FeatureKind::Neighbours);
  EXPECT_EQ(modelToJson(read->models[0]).dump(), j.dump());

  json old = j;
  old["version"] = 2;
  const Result<ModelBundle> refused = parseModelJson(old.dump(1), "n2.json");
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.errorText().find("needs version 3"), std::string::npos) << refused.errorText();

  ModelBundle bundle;
  GroupModel first;
  ASSERT_NO_FATAL_FAILURE(trainModel(first, ClassifierMethod::Gmm, CovarianceForm::NodalDiag));
  bundle.models.push_back(std::move(first));
  EXPECT_EQ(bundleToJson(bundle)["version"], 2);
  bundle.models.push_back(std::move(r.model));
  EXPECT_EQ(bundleToJson(bundle)["version"], 3);
}

// Version-1 files (no transitions, no decision) still load and decide per step.
TEST(ModelFile, VersionOneFilesLoad) {
  GroupModel model;
  ASSERT_NO_FATAL_FAILURE(trainModel(model, ClassifierMethod::Gmm, CovarianceForm::NodalFull));
  json j = modelToJson(model);
  j["version"] = 1;
  j.erase("transitions");
  j.erase("decision");
  // Version-1 metrics: the run-file form's metrics.evaluation.confusion.
  // Parsed from text, as a file is (counts are unsigned numbers there).
  const json confusion =
      json::parse(R"({"classes": ["Wall", "Corner"], "counts": [[5, 1], [2, 3]]})");
  j["metrics"] = {{"evaluated_on", "test runs"}, {"evaluation", {{"confusion", confusion}}}};
  j["trained_on"] = {{"runs", {"a.csv", "b.csv"}}, {"labels", "truth columns"}};
  const Result<ModelBundle> read = modelsFromJson(
      json{{"format", "tactile-model-bundle"}, {"version", 1}, {"models", json::array({j})}},
      "old.json");
  ASSERT_TRUE(read.ok()) << read.errorText();
  const GroupModel& m = read->models.front();
  EXPECT_TRUE(m.transitions.empty());
  EXPECT_EQ(m.decision, DecisionMode::Step);
  EXPECT_EQ(m.evaluation.samplesTest(), 11u);
  EXPECT_EQ(
      m.evaluation.confusion(DecisionMode::Step).count(ContactClass::Corner, ContactClass::Wall),
      2u);
  ASSERT_EQ(m.provenance.trainRuns.size(), 2u);
  EXPECT_EQ(m.provenance.trainRuns[1].name, "b.csv");
  const Eigen::MatrixXd x = probeRows();
  EXPECT_EQ(m.classifier.predict(x), model.classifier.predict(x));
  // The database form's older metrics.confusion reads the same way.
  j["metrics"] = json::parse(R"({"confusion": {"classes": ["Wall"], "counts": [[4]]}})");
  const Result<ModelBundle> db = modelsFromJson(j, "stored");
  ASSERT_TRUE(db.ok()) << db.errorText();
  EXPECT_EQ(db->models.front().evaluation.samplesTest(), 4u);
}

// A model's default decision must be causal; "online" needs transitions; the chain's rows must
// be distributions.
TEST(ModelFile, DecisionAndTransitionsAreValidated) {
  GroupModel model;
  ASSERT_NO_FATAL_FAILURE(trainModel(model, ClassifierMethod::Gmm, CovarianceForm::NodalDiag));
  json j = modelToJson(model);
  j["decision"] = "offline";
  Result<ModelBundle> r = modelsFromJson(j, "m.json");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.errorText().find("causal"), std::string::npos) << r.errorText();
  j = modelToJson(model);
  j.erase("transitions");
  r = modelsFromJson(j, "m.json");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.errorText().find("online needs 'transitions'"), std::string::npos);
  j = modelToJson(model);
  j["transitions"]["log_matrix"][0][0] = -0.001;
  r = modelsFromJson(j, "m.json");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.errorText().find("transitions.log_matrix[0]"), std::string::npos) << r.errorText();
}

// A model whose group had no test rows: its report says "no test data" where the test count
// and the rates stand, in every format, never 0, and prints no (empty) confusion matrix.
TEST(ModelFile, ReportOfAnUnscoredModelSaysNoTestDataInEveryFormat) {
  GroupModel model;
  ASSERT_NO_FATAL_FAILURE(trainModel(model, ClassifierMethod::Gmm, CovarianceForm::NodalDiag));
  model.evaluation.byDecision = {};  // trained, but no test rows
  model.evaluation.oneVsRest.clear();
  ASSERT_FALSE(model.evaluation.scored());
  for (TableStyle style :
       {TableStyle::Text, TableStyle::Markdown, TableStyle::Csv, TableStyle::Html}) {
    const std::string report = modelReport(ModelBundle{{model}}, style);
    std::size_t n = 0;
    for (std::size_t at = report.find("no test data"); at != std::string::npos;
         at = report.find("no test data", at + 1))
      ++n;
    // The test count, three decisions, and the class-rate row's accuracy and balanced accuracy.
    EXPECT_EQ(n, 6u) << static_cast<int>(style) << "\n" << report;
    EXPECT_EQ(report.find("confusion"), std::string::npos) << static_cast<int>(style);
  }
}

// The chain's emission weight is written and read back; a file without it (written before it
// existed) reads as 1 (the plain HMM); a weight that is not a finite number > 0 is an error.
TEST(ModelFile, EmissionWeightRoundTripsAndIsValidated) {
  GroupModel model;
  ASSERT_NO_FATAL_FAILURE(trainModel(model, ClassifierMethod::Gmm, CovarianceForm::NodalDiag));
  model.transitions.emissionWeight = 0.3;
  json j = modelToJson(model);
  EXPECT_EQ(j["transitions"]["emission_weight"], 0.3);
  Result<ModelBundle> r = modelsFromJson(j, "m.json");
  ASSERT_TRUE(r.ok()) << r.errorText();
  EXPECT_EQ(r->models.front().transitions.emissionWeight, 0.3);
  // The report names it beside the decision; a plain chain shows the decision alone.
  const std::string report = modelReport(ModelBundle{{model}}, TableStyle::Csv);
  EXPECT_NE(report.find(",online (evidence x 0.3)"), std::string::npos) << report;
  model.transitions.emissionWeight = 1.0;
  const std::string plain = modelReport(ModelBundle{{model}}, TableStyle::Csv);
  EXPECT_EQ(plain.find("evidence x"), std::string::npos) << plain;
  EXPECT_NE(plain.find(",online"), std::string::npos) << plain;
  j["transitions"].erase("emission_weight");
  r = modelsFromJson(j, "m.json");
  ASSERT_TRUE(r.ok()) << r.errorText();
  EXPECT_EQ(r->models.front().transitions.emissionWeight, 1.0);
  for (double bad : {0.0, -0.5}) {
    j["transitions"]["emission_weight"] = bad;
    r = modelsFromJson(j, "m.json");
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.errorText().find("transitions.emission_weight"), std::string::npos)
        << r.errorText();
  }
}

// A group with no test rows reports null, never 0.
TEST(ModelFile, NoTestRowsIsNullNotZero) {
  GroupModel model;
  ASSERT_NO_FATAL_FAILURE(trainModel(model, ClassifierMethod::Gmm, CovarianceForm::NodalDiag));
  model.evaluation.byDecision = {};
  const json metrics = evaluationToJson(model);
  EXPECT_TRUE(metrics["balanced_accuracy"].is_null());
  EXPECT_TRUE(metrics["accuracy"].is_null());
  for (const char* mode : {"step", "online", "offline"})
    EXPECT_TRUE(metrics["balanced_accuracy_by_decision"][mode].is_null()) << mode;
  EXPECT_EQ(metrics["samples_test"], 0);
}

}  // namespace
}  // namespace tactile::analysis
