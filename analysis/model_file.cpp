#include "analysis/model_file.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "base/file_text.h"
#include "base/text_rules.h"
#include "run/json_text.h"
#include "run/run_csv.h"

namespace tactile::analysis {

using nlohmann::json;

json confusionToJson(const ConfusionMatrix& confusion) {
  json out;
  const std::vector<ContactClass> classes = confusion.activeClasses();
  json names = json::array();
  for (ContactClass c : classes)
    names.push_back(contactClassName(c));
  json counts = json::array();
  for (ContactClass t : classes) {
    json row = json::array();
    for (ContactClass p : classes)
      row.push_back(confusion.count(t, p));
    counts.push_back(std::move(row));
  }
  out["classes"] = std::move(names);
  out["counts"] = std::move(counts);
  return out;
}

bool confusionFromJson(const json& value, ConfusionMatrix& out) {
  out = ConfusionMatrix();
  if (!value.is_object() || !value.contains("classes") || !value.contains("counts")) return false;
  const json& names = value["classes"];
  const json& counts = value["counts"];
  if (!names.is_array() || !counts.is_array() || counts.size() != names.size()) return false;
  std::vector<ContactClass> classes;
  for (const json& n : names) {
    if (!n.is_string()) return false;
    const auto c = parseContactClass(n.get<std::string>());
    if (!c) return false;
    classes.push_back(*c);
  }
  for (std::size_t t = 0; t < classes.size(); ++t) {
    if (!counts[t].is_array() || counts[t].size() != classes.size()) return false;
    for (std::size_t p = 0; p < classes.size(); ++p) {
      if (!counts[t][p].is_number_unsigned()) return false;
      out.add(classes[t], classes[p], counts[t][p].get<std::size_t>());
    }
  }
  return true;
}

json patternsToJson(const ContactPatternTable& patterns) {
  json rows = json::array();
  for (const ContactPatternRow& r : patterns.rows) {
    json row;
    row["pattern"] = r.pattern;
    row["truth"] = contactClassName(r.truth);
    json predicted = json::object();
    for (int c = 0; c < kContactClassCount; ++c) {
      if (r.predicted[static_cast<std::size_t>(c)] > 0) {
        predicted[std::string(kContactClassNames[static_cast<std::size_t>(c)])] =
            r.predicted[static_cast<std::size_t>(c)];
      }
    }
    row["predicted"] = std::move(predicted);
    rows.push_back(std::move(row));
  }
  return rows;
}

bool patternsFromJson(const json& value, SensorGroup group, ContactPatternTable& out) {
  out = ContactPatternTable{};
  out.group = group;
  if (!value.is_array()) return false;
  for (const json& r : value) {
    if (!r.is_object()) return false;
    const auto truth = parseContactClass(r.value("truth", ""));
    if (!truth || !r.contains("predicted") || !r["predicted"].is_object()) return false;
    ContactPatternRow row{r.value("pattern", ""), *truth, {}};
    for (auto it = r["predicted"].begin(); it != r["predicted"].end(); ++it) {
      const auto p = parseContactClass(it.key());
      if (!p || !it.value().is_number_unsigned()) return false;
      row.predicted[static_cast<std::size_t>(*p)] = it.value().get<std::size_t>();
    }
    out.rows.push_back(std::move(row));
  }
  return true;
}

namespace {

json matrixRows(const Eigen::MatrixXd& m) {
  json rows = json::array();
  for (Eigen::Index r = 0; r < m.rows(); ++r) {
    json row = json::array();
    for (Eigen::Index c = 0; c < m.cols(); ++c)
      row.push_back(m(r, c));
    rows.push_back(std::move(row));
  }
  return rows;
}

json mixtureToJson(const GaussianMixture& g) {
  json out;
  json weights = json::array();
  for (Eigen::Index k = 0; k < g.weights().size(); ++k)
    weights.push_back(g.weights()[k]);
  out["weights"] = std::move(weights);
  out["means"] = matrixRows(g.means());
  json covs = json::array();
  for (const Eigen::MatrixXd& cov : g.covariances()) {
    if (isDiagonal(g.form())) {
      json diag = json::array();
      for (Eigen::Index i = 0; i < cov.rows(); ++i)
        diag.push_back(cov(i, i));
      covs.push_back(std::move(diag));
    } else {
      covs.push_back(matrixRows(cov));
    }
  }
  out["covariances"] = std::move(covs);
  return out;
}

// Thrown inside the reader only, caught in modelsFromJson and turned into a message.
struct ModelError {
  std::string path;
  std::string message;
};

[[noreturn]] void fail(const std::string& path, const std::string& message) {
  throw ModelError{path, message};
}

const json& field(const json& obj, const std::string& path, const char* key) {
  auto it = obj.find(key);
  if (it == obj.end()) fail(path, std::string("missing field '") + key + "'");
  return *it;
}

std::string stringField(const json& obj, const std::string& path, const char* key) {
  const json& v = field(obj, path, key);
  if (!v.is_string()) fail(path + "." + key, "expected a string");
  return v.get<std::string>();
}

double numberOf(const json& v, const std::string& path) {
  if (!v.is_number()) fail(path, "expected a number");
  const double d = v.get<double>();
  if (!std::isfinite(d)) fail(path, "expected a finite number");
  return d;
}

Eigen::VectorXd vectorOf(const json& v, const std::string& path) {
  if (!v.is_array()) fail(path, "expected an array of numbers");
  Eigen::VectorXd out(static_cast<Eigen::Index>(v.size()));
  for (std::size_t i = 0; i < v.size(); ++i) {
    out[static_cast<Eigen::Index>(i)] = numberOf(v[i], path + "[" + std::to_string(i) + "]");
  }
  return out;
}

Eigen::MatrixXd matrixOf(const json& v, const std::string& path, Eigen::Index rows,
                         Eigen::Index cols) {
  if (!v.is_array() || static_cast<Eigen::Index>(v.size()) != rows) {
    fail(path, "expected " + std::to_string(rows) + " rows");
  }
  Eigen::MatrixXd out(rows, cols);
  for (Eigen::Index r = 0; r < rows; ++r) {
    const std::string rowPath = path + "[" + std::to_string(r) + "]";
    const Eigen::VectorXd row = vectorOf(v[static_cast<std::size_t>(r)], rowPath);
    if (row.size() != cols) fail(rowPath, "expected " + std::to_string(cols) + " numbers");
    out.row(r) = row.transpose();
  }
  return out;
}

GaussianMixture mixtureOf(const json& v, const std::string& path, CovarianceForm form, int dim) {
  if (!v.is_object()) fail(path, "expected an object with weights, means, covariances");
  const Eigen::VectorXd weights = vectorOf(field(v, path, "weights"), path + ".weights");
  const Eigen::Index k = weights.size();
  if (k == 0) fail(path + ".weights", "expected at least one component");
  double weightSum = 0.0;  // a loop, not weights.sum(): see docs/analysis.md (GCC 12 warning)
  for (Eigen::Index i = 0; i < k; ++i) {
    if (weights[i] < 0.0) {
      fail(path + ".weights[" + std::to_string(i) + "]", "negative mixture weight");
    }
    weightSum += weights[i];
  }
  if (std::abs(weightSum - 1.0) > 1e-9) {
    fail(path + ".weights", "weights sum to " + std::to_string(weightSum) + ", expected 1");
  }
  const Eigen::MatrixXd means = matrixOf(field(v, path, "means"), path + ".means", k, dim);
  const json& covs = field(v, path, "covariances");
  const std::size_t expected = isNodal(form) ? static_cast<std::size_t>(k) : 1;
  if (!covs.is_array() || covs.size() != expected) {
    fail(path + ".covariances", "expected " + std::to_string(expected) + " covariance(s) for " +
                                    std::string(covarianceFormName(form)));
  }
  std::vector<Eigen::MatrixXd> matrices;
  for (std::size_t i = 0; i < covs.size(); ++i) {
    const std::string cpath = path + ".covariances[" + std::to_string(i) + "]";
    const json& c = covs[i];
    Eigen::MatrixXd m;
    if (isDiagonal(form) && c.is_array() && (c.empty() || !c[0].is_array())) {
      const Eigen::VectorXd d = vectorOf(c, cpath);
      if (d.size() != dim) fail(cpath, "expected " + std::to_string(dim) + " variances");
      m = d.asDiagonal();
    } else {
      m = matrixOf(c, cpath, dim, dim);
    }
    for (Eigen::Index r = 0; r < dim; ++r) {
      for (Eigen::Index q = r + 1; q < dim; ++q) {
        const double a = m(r, q), b = m(q, r);
        if (std::abs(a - b) > 1e-12 * std::max({1.0, std::abs(a), std::abs(b)})) {
          fail(cpath, "not symmetric at row " + std::to_string(r + 1) + ", column " +
                          std::to_string(q + 1) + " (rows and columns count from 1)");
        }
        if (isDiagonal(form) && (a != 0.0 || b != 0.0)) {
          fail(cpath, "off-diagonal entry in a diagonal covariance form");
        }
      }
      if (!(m(r, r) > 0.0)) {
        fail(cpath, "the variance of feature " + std::to_string(r + 1) + " of " +
                        std::to_string(dim) + " (counting from 1) is not positive");
      }
    }
    matrices.push_back(std::move(m));
  }
  Result<GaussianMixture> g = GaussianMixture::create(weights, means, matrices, form);
  if (!g) fail(path, g.error().message);
  return std::move(g.value());
}

// ---- provenance and evaluation ("trained_on", "metrics") ----

json runRefsJson(const std::vector<RunReference>& runs) {
  json out = json::array();
  for (const RunReference& r : runs) {
    json j{{"name", r.name}, {"steps", r.steps}};
    if (!r.checksum.empty()) j["checksum"] = r.checksum;
    if (!r.scene.empty()) j["scene"] = r.scene;
    out.push_back(std::move(j));
  }
  return out;
}

// Run lists: objects (this version), or plain names / paths (older files).
std::vector<RunReference> runRefsOf(const json& v) {
  std::vector<RunReference> out;
  if (!v.is_array()) return out;
  for (const json& r : v) {
    RunReference ref;
    if (r.is_string()) {
      ref.name = r.get<std::string>();
    } else if (r.is_object()) {
      ref.name = r.value("name", std::string());
      ref.steps = r.value("steps", std::int64_t{0});
      ref.checksum = r.value("checksum", std::string());
      ref.scene = r.value("scene", std::string());
    } else {
      continue;
    }
    out.push_back(std::move(ref));
  }
  return out;
}

json settingsToJson(const GroupModel& model) {
  const ClassifierOptions& c = model.provenance.classifier;
  json out;
  out["features"] = featureKindName(model.features);
  out["method"] = classifierMethodName(c.method);
  if (c.method == ClassifierMethod::Gmm) {
    out["order"] = c.gmm.components;
    out["covariance"] = covarianceFormName(c.gmm.form);
    out["init"] = gmmInitName(c.gmm.init);
    out["restarts"] = c.gmm.restarts;
    out["max_iterations"] = c.gmm.maxIterations;
    out["tolerance"] = c.gmm.tolerance;
    out["tolerance_rule"] = convergenceRuleName(c.gmm.rule);
  }
  if (c.method == ClassifierMethod::Gbt) {
    out["trees"] = c.gbt.trees;
    out["depth"] = c.gbt.depth;
    out["learning_rate"] = c.gbt.learningRate;
    out["min_child_weight"] = c.gbt.minChildWeight;
  }
  out["variance_floor"] = c.gmm.varianceFloor;
  out["regularization"] = regularizationName(c.gmm.reg);
  out["seed"] = c.gmm.seed;
  out["priors"] = priorModeName(c.priors);
  out["decision"] = decisionModeName(model.decision);
  return out;
}

// Settings as far as they are given (older files wrote fewer); the rest keep their defaults.
ClassifierOptions settingsOf(const json& v, const GroupModel& model) {
  ClassifierOptions c;
  c.method = model.classifier.method();
  c.gmm.form = model.covariance;
  c.gmm.varianceFloor = model.varianceFloor;
  c.gmm.reg = model.regularization;
  if (!v.is_object()) return c;
  if (auto m = parseClassifierMethod(v.value("method", std::string()))) c.method = *m;
  c.gmm.components = v.value("order", c.gmm.components);
  if (auto f = parseCovarianceForm(v.value("covariance", std::string()))) c.gmm.form = *f;
  if (auto i = parseGmmInit(v.value("init", std::string()))) c.gmm.init = *i;
  c.gmm.restarts = v.value("restarts", c.gmm.restarts);
  c.gmm.maxIterations = v.value("max_iterations", c.gmm.maxIterations);
  if (v.contains("tolerance") && v["tolerance"].is_number()) c.gmm.tolerance = v["tolerance"];
  if (auto r = parseConvergenceRule(v.value("tolerance_rule", std::string()))) c.gmm.rule = *r;
  if (v.contains("variance_floor") && v["variance_floor"].is_number())
    c.gmm.varianceFloor = v["variance_floor"];
  if (auto r = parseRegularization(v.value("regularization", std::string()))) c.gmm.reg = *r;
  if (v.contains("seed") && v["seed"].is_number_unsigned()) c.gmm.seed = v["seed"];
  if (auto p = parsePriorMode(v.value("priors", std::string()))) c.priors = *p;
  c.gbt.trees = v.value("trees", c.gbt.trees);
  c.gbt.depth = v.value("depth", c.gbt.depth);
  if (v.contains("learning_rate") && v["learning_rate"].is_number())
    c.gbt.learningRate = v["learning_rate"];
  if (v.contains("min_child_weight") && v["min_child_weight"].is_number())
    c.gbt.minChildWeight = v["min_child_weight"];
  c.gbt.seed = c.gmm.seed;
  return c;
}

json classCountsJson(const std::array<std::size_t, kContactClassCount>& counts) {
  json out = json::object();
  for (int c = 0; c < kContactClassCount; ++c) {
    if (counts[static_cast<std::size_t>(c)] > 0)
      out[std::string(kContactClassNames[static_cast<std::size_t>(c)])] =
          counts[static_cast<std::size_t>(c)];
  }
  return out;
}

ModelProvenance provenanceOf(const json& v, const std::string& /*path*/, const GroupModel& model) {
  ModelProvenance p;
  p.labelSet = v.value("label_set", std::string());
  p.labels = v.value("labels", std::string());
  // Older run-file models listed paths under "runs"; older stored ones "train_runs".
  p.trainRuns = runRefsOf(v.contains("train_runs") ? v["train_runs"] : v.value("runs", json()));
  p.testRuns = runRefsOf(v.value("test_runs", json()));
  p.split = v.value("split", std::string());
  if (v.contains("holdout") && v["holdout"].is_number()) p.holdout = v["holdout"];
  p.programVersion = v.value("program_version", std::string());
  p.importedFrom = v.value("imported_from", std::string());
  p.classifier = settingsOf(v.value("settings", json::object()), model);
  if (v.contains("samples") && v["samples"].is_number_unsigned()) p.samples = v["samples"];
  if (v.contains("zero_rows") && v["zero_rows"].is_number_unsigned()) p.zeroRows = v["zero_rows"];
  if (v.contains("class_counts") && v["class_counts"].is_object()) {
    for (const auto& [name, n] : v["class_counts"].items()) {
      const auto c = parseContactClass(name);
      if (c && n.is_number_unsigned()) p.classCounts[static_cast<std::size_t>(*c)] = n;
    }
  }
  for (const json& n : v.value("unmodelled_classes", json::array())) {
    if (!n.is_string()) continue;
    if (const auto c = parseContactClass(n.get<std::string>())) p.unmodelled.push_back(*c);
  }
  return p;
}

json optionalJson(const std::optional<double>& v) {
  return v ? json(*v) : json(nullptr);
}

json decisionJson(const ConfusionMatrix& confusion) {
  json out;
  out["samples"] = confusion.total();
  out["confusion"] = confusionToJson(confusion);
  if (confusion.total() == 0) {
    out["accuracy"] = nullptr;
    out["balanced_accuracy"] = nullptr;
    return out;
  }
  const Metrics m = computeMetrics(confusion);
  out["accuracy"] = m.accuracy;
  out["balanced_accuracy"] = m.balancedAccuracy;
  out["macro_f1"] = m.macroF1;
  json perClass = json::object();
  for (const ClassMetrics& c : m.perClass) {
    perClass[std::string(contactClassName(c.label))] = {{"support", c.support},
                                                        {"predicted", c.predicted},
                                                        {"recall", optionalJson(c.recall)},
                                                        {"precision", optionalJson(c.precision)},
                                                        {"f1", c.f1}};
  }
  out["per_class"] = std::move(perClass);
  return out;
}

bool readConfusion(const json& v, ConfusionMatrix& out) {
  return v.is_object() && v.contains("confusion") && confusionFromJson(v["confusion"], out);
}

ModelEvaluation evaluationOf(const json& v, const std::string& path, SensorGroup group,
                             std::size_t classes) {
  ModelEvaluation e;
  e.evaluatedOn = v.value("evaluated_on", std::string());
  if (v.contains("samples_train") && v["samples_train"].is_number_unsigned())
    e.samplesTrain = v["samples_train"];
  if (v.contains("fit_s") && v["fit_s"].is_number()) e.fitSeconds = v["fit_s"];
  if (v.contains("predict_s") && v["predict_s"].is_number()) e.predictSeconds = v["predict_s"];
  for (const json& w : v.value("warnings", json::array()))
    if (w.is_string()) e.warnings.push_back(w.get<std::string>());
  if (v.contains("mean_loglik") && v["mean_loglik"].is_number())
    e.meanLogLikelihood = v["mean_loglik"].get<double>();
  if (v.contains("neg_inf_rows") && v["neg_inf_rows"].is_number_unsigned())
    e.negInfRows = v["neg_inf_rows"];
  if (v.contains("zero_rows") && v["zero_rows"].is_number_unsigned()) e.zeroRows = v["zero_rows"];
  if (auto it = v.find("by_decision"); it != v.end() && it->is_object()) {
    for (DecisionMode m : kDecisionModes) {
      const std::string key(decisionModeName(m));
      if (it->contains(key) && !readConfusion((*it)[key], e.byDecision[decisionIndex(m)]))
        fail(path + ".by_decision." + key, "malformed confusion");
    }
  } else if (v.contains("evaluation")) {
    // Older run-file models: metrics.evaluation.confusion (per-step decisions).
    readConfusion(v["evaluation"], e.byDecision[0]);
  } else {
    // Older stored models: metrics.confusion.
    readConfusion(v, e.byDecision[0]);
  }
  const json& ev = v.contains("evaluation") && v["evaluation"].is_object() ? v["evaluation"] : v;
  if (ev.contains("contact_patterns")) patternsFromJson(ev["contact_patterns"], group, e.patterns);
  for (const json& b : ev.value("one_vs_rest", json::array())) {
    const auto c = parseContactClass(b.value("class", ""));
    if (!c) continue;
    e.oneVsRest.push_back({*c, b.value("tp", std::size_t{0}), b.value("fp", std::size_t{0}),
                           b.value("fn", std::size_t{0}), b.value("tn", std::size_t{0})});
  }
  if (auto it = v.find("classes_fit"); it != v.end() && it->is_array() && it->size() == classes) {
    for (const json& f : *it) {
      ClassFitRecord r;
      r.iterations = f.value("iterations", 0);
      r.converged = f.value("converged", false);
      r.trainMeanLogLikelihood = f.value("train_mean_loglik", 0.0);
      r.droppedComponents = f.value("dropped_components", 0);
      e.fit.push_back(r);
    }
  }
  for (const json& sc : v.value("scenes", json::array())) {
    SceneScore s;
    s.scene = sc.value("scene", std::string());
    const json bd = sc.value("by_decision", json::object());
    for (DecisionMode m : kDecisionModes) {
      const std::string key(decisionModeName(m));
      if (bd.contains(key)) readConfusion(bd[key], s.byDecision[decisionIndex(m)]);
    }
    e.scenes.push_back(std::move(s));
  }
  return e;
}

int versionOf(const json& version, const std::string& path) {
  if (!version.is_number_integer() || version.get<int>() < kOldestModelVersion ||
      version.get<int>() > kModelVersion) {
    fail(path, "expected version " + std::to_string(kOldestModelVersion) + " to " +
                   std::to_string(kModelVersion));
  }
  return version.get<int>();
}

// A log-probability vector / matrix row: finite or -inf entries summing to 1 in probability.
void checkLogDistribution(const Eigen::VectorXd& v, const std::string& path) {
  double total = 0.0;
  for (Eigen::Index i = 0; i < v.size(); ++i)
    total += std::exp(v[i]);
  if (std::abs(total - 1.0) > 1e-9) {
    fail(path, "probabilities sum to " + std::to_string(total) + ", expected 1");
  }
}

Eigen::VectorXd logVectorOf(const json& v, const std::string& path) {
  if (!v.is_array()) fail(path, "expected an array of numbers");
  Eigen::VectorXd out(static_cast<Eigen::Index>(v.size()));
  for (std::size_t i = 0; i < v.size(); ++i) {
    const std::string p = path + "[" + std::to_string(i) + "]";
    // -inf (an impossible move) is written as null.
    if (v[i].is_null()) {
      out[static_cast<Eigen::Index>(i)] = -std::numeric_limits<double>::infinity();
      continue;
    }
    const double d = numberOf(v[i], p);
    if (d > 0.0) fail(p, "a log-probability must be <= 0");
    out[static_cast<Eigen::Index>(i)] = d;
  }
  return out;
}

TransitionModel transitionsOf(const json& v, const std::string& path, int classes) {
  if (!v.is_object()) fail(path, "expected an object");
  TransitionModel m;
  m.logInitial = logVectorOf(field(v, path, "log_initial"), path + ".log_initial");
  if (m.logInitial.size() != classes) {
    fail(path + ".log_initial", "expected one entry per class (" + std::to_string(classes) + ")");
  }
  checkLogDistribution(m.logInitial, path + ".log_initial");
  const json& rows = field(v, path, "log_matrix");
  if (!rows.is_array() || static_cast<int>(rows.size()) != classes) {
    fail(path + ".log_matrix", "expected " + std::to_string(classes) + " rows");
  }
  Eigen::MatrixXd logA(classes, classes);
  for (int i = 0; i < classes; ++i) {
    const std::string rp = path + ".log_matrix[" + std::to_string(i) + "]";
    const Eigen::VectorXd row = logVectorOf(rows[static_cast<std::size_t>(i)], rp);
    if (row.size() != classes) fail(rp, "expected " + std::to_string(classes) + " numbers");
    checkLogDistribution(row, rp);
    logA.row(i) = row.transpose();
  }
  m.set(std::move(logA), m.logInitial);
  if (auto it = v.find("pseudo_count"); it != v.end()) {
    m.pseudoCount = numberOf(*it, path + ".pseudo_count");
  }
  if (auto it = v.find("initial_counts"); it != v.end()) {
    m.initialCounts = vectorOf(*it, path + ".initial_counts");
    if (m.initialCounts.size() != classes) fail(path + ".initial_counts", "one count per class");
  }
  if (auto it = v.find("counts"); it != v.end()) {
    m.counts = matrixOf(*it, path + ".counts", classes, classes);
  }
  if (auto it = v.find("emission_weight"); it != v.end()) {
    m.emissionWeight = numberOf(*it, path + ".emission_weight");
    if (!(m.emissionWeight > 0.0) || !std::isfinite(m.emissionWeight)) {
      fail(path + ".emission_weight", "expected a finite number > 0");
    }
  }
  return m;
}

json logRow(const Eigen::Ref<const Eigen::VectorXd>& v) {
  json out = json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i)
    out.push_back(std::isfinite(v[i]) ? json(v[i]) : json(nullptr));
  return out;
}

json transitionsToJson(const TransitionModel& m) {
  json out;
  out["log_initial"] = logRow(m.logInitial);
  json rows = json::array();
  for (Eigen::Index i = 0; i < m.logTransition.rows(); ++i)
    rows.push_back(logRow(m.logTransition.row(i).transpose()));
  out["log_matrix"] = std::move(rows);
  out["pseudo_count"] = m.pseudoCount;
  out["emission_weight"] = m.emissionWeight;
  if (m.initialCounts.size() == m.logInitial.size()) {
    json counts = json::array();
    for (Eigen::Index i = 0; i < m.initialCounts.size(); ++i)
      counts.push_back(m.initialCounts[i]);
    out["initial_counts"] = std::move(counts);
  }
  if (m.counts.rows() == m.logTransition.rows() && m.counts.cols() == m.logTransition.cols()) {
    out["counts"] = matrixRows(m.counts);
  }
  return out;
}

GroupModel finishModel(const json& v, const std::string& path, int fileVersion,
                       const std::vector<std::string>& names, GroupModel& model);

// A gbt model's classifier: the trees of its "gbt" object over the named classes.
ClassModelSet treesOf(const json& v, const std::string& path, const std::vector<std::string>& names,
                      int dimension) {
  const json& gbt = field(v, path, "gbt");
  if (!gbt.is_object()) fail(path + ".gbt", "expected an object with the trees");
  const json& trees = field(gbt, path + ".gbt", "model");
  if (!trees.is_object()) fail(path + ".gbt.model", "expected XGBoost's JSON form of the trees");
  auto loaded = GbtModel::load(trees.dump(), static_cast<int>(names.size()), dimension);
  if (!loaded) fail(path + ".gbt.model", loaded.error().message);
  Eigen::VectorXd logPriors;
  if (auto it = v.find("priors"); it != v.end()) {
    logPriors = vectorOf(*it, path + ".priors");
    if (logPriors.size() != static_cast<Eigen::Index>(names.size())) {
      fail(path + ".priors", "expected one log prior per class");
    }
  }
  auto set = ClassModelSet::createTrees(
      names, std::make_shared<const GbtModel>(std::move(loaded.value())), logPriors);
  if (!set) fail(path, set.error().message);
  return std::move(set.value());
}

GroupModel modelOf(const json& v, const std::string& path) {
  if (!v.is_object()) fail(path, "expected a model object");
  if (stringField(v, path, "format") != kModelFormat) {
    fail(path + ".format", "expected \"" + std::string(kModelFormat) + "\"");
  }
  const int fileVersion = versionOf(field(v, path, "version"), path + ".version");
  GroupModel model;
  const std::string groupName = stringField(v, path, "group");
  const std::optional<SensorGroup> group = parseSensorGroup(groupName);
  if (!group) fail(path + ".group", "unknown sensor group " + quotedInput(groupName));
  model.group = *group;
  const std::string featureName = stringField(v, path, "features");
  const std::optional<FeatureKind> kind = parseFeatureKind(featureName);
  if (!kind) {
    fail(path + ".features",
         "expected normal, magnitude, normal+shear, normal+shear+touch, "
         "normal+shear+touch+context, normal+shear+touch+context+neighbours, "
         "normal+shear+touch+motion or normal+shear+touch+motion+neighbours, found " +
             quotedInput(featureName));
  }
  // Kinds newer than version 2 need the version that brought them (earlier kinds read from 1 on).
  if (modelVersionFor(*kind) > 2 && fileVersion < modelVersionFor(*kind)) {
    fail(path + ".features", featureName + " needs version " +
                                 std::to_string(modelVersionFor(*kind)) + ", the file has " +
                                 std::to_string(fileVersion));
  }
  model.features = *kind;
  const int dim = featureDimension(model.group, model.features);
  const std::string methodName = stringField(v, path, "method");
  const std::optional<ClassifierMethod> method = parseClassifierMethod(methodName);
  if (!method) {
    fail(path + ".method", "expected gaussian, gmm or gbt, found " + quotedInput(methodName));
  }
  if (*method == ClassifierMethod::Gbt && fileVersion < kGbtModelVersion) {
    fail(path + ".method", "gbt needs version " + std::to_string(kGbtModelVersion) +
                               ", the file has " + std::to_string(fileVersion));
  }
  const std::string covName = stringField(v, path, "covariance");
  const std::optional<CovarianceForm> form = parseCovarianceForm(covName);
  if (!form) fail(path + ".covariance", "unknown covariance form " + quotedInput(covName));
  model.covariance = *form;
  model.varianceFloor = numberOf(field(v, path, "variance_floor"), path + ".variance_floor");
  if (model.varianceFloor < 0.0) fail(path + ".variance_floor", "must be >= 0");
  const std::string regName = stringField(v, path, "regularization");
  const std::optional<Regularization> reg = parseRegularization(regName);
  if (!reg) fail(path + ".regularization", "expected floor or add, found " + quotedInput(regName));
  model.regularization = *reg;

  const json& classes = field(v, path, "classes");
  if (!classes.is_array() || classes.empty()) {
    fail(path + ".classes", "expected a non-empty array of class names");
  }
  std::vector<std::string> names;
  std::set<std::string> seen;
  for (std::size_t i = 0; i < classes.size(); ++i) {
    const std::string cpath = path + ".classes[" + std::to_string(i) + "]";
    if (!classes[i].is_string()) fail(cpath, "expected a class name");
    const std::string name = classes[i].get<std::string>();
    const std::optional<ContactClass> cls = parseContactClass(name);
    if (!cls) fail(cpath, "unknown contact class " + quotedInput(name));
    if (!seen.insert(name).second) fail(cpath, "class " + quotedInput(name) + " listed twice");
    model.classes.push_back(*cls);
    names.push_back(name);
  }
  if (*method == ClassifierMethod::Gbt) {
    model.classifier = treesOf(v, path, names, dim);
    return finishModel(v, path, fileVersion, names, model);
  }
  // The Gaussian method stores one full Gaussian per class, whatever `covariance` says.
  const CovarianceForm storedForm =
      *method == ClassifierMethod::Gaussian ? CovarianceForm::NodalFull : model.covariance;
  const json& components = field(v, path, "components");
  if (!components.is_object()) fail(path + ".components", "expected an object keyed by class");
  if (components.size() != names.size()) {
    fail(path + ".components", "expected exactly one entry per class in 'classes'");
  }
  std::vector<GaussianMixture> mixtures;
  for (const std::string& name : names) {
    const std::string cpath = path + ".components." + name;
    auto it = components.find(name);
    if (it == components.end()) fail(path + ".components", "missing class " + quotedInput(name));
    mixtures.push_back(mixtureOf(*it, cpath, storedForm, dim));
  }
  std::vector<GaussianMixture> rest;
  if (auto it = v.find("rest_components"); it != v.end()) {
    if (!it->is_object() || it->size() != names.size()) {
      fail(path + ".rest_components", "expected one entry per class");
    }
    for (const std::string& name : names) {
      auto r = it->find(name);
      if (r == it->end()) fail(path + ".rest_components", "missing class " + quotedInput(name));
      rest.push_back(mixtureOf(*r, path + ".rest_components." + name, storedForm, dim));
    }
  }
  Eigen::VectorXd logPriors;
  if (auto it = v.find("priors"); it != v.end()) {
    logPriors = vectorOf(*it, path + ".priors");
    if (logPriors.size() != static_cast<Eigen::Index>(names.size())) {
      fail(path + ".priors", "expected one log prior per class");
    }
  }
  Result<ClassModelSet> set =
      ClassModelSet::create(*method, names, std::move(mixtures), logPriors, std::move(rest));
  if (!set) fail(path, set.error().message);
  model.classifier = std::move(set.value());
  return finishModel(v, path, fileVersion, names, model);
}

// The parts after the classifier: chain, default decision, provenance and metrics.
GroupModel finishModel(const json& v, const std::string& path, int fileVersion,
                       const std::vector<std::string>& names, GroupModel& model) {
  model.decision = DecisionMode::Step;
  if (fileVersion >= 2) {
    const int c = static_cast<int>(names.size());
    if (auto it = v.find("transitions"); it != v.end() && !it->is_null()) {
      model.transitions = transitionsOf(*it, path + ".transitions", c);
      model.decision = DecisionMode::Online;
    }
    if (auto it = v.find("decision"); it != v.end()) {
      const std::string name = it->is_string() ? it->get<std::string>() : std::string();
      const std::optional<DecisionMode> mode = parseDecisionMode(name);
      if (!mode) fail(path + ".decision", "expected step or online, found " + quotedInput(name));
      if (!isCausal(*mode)) {
        fail(path + ".decision",
             "a model's default decision must be causal (step or online), not offline");
      }
      if (*mode == DecisionMode::Online && model.transitions.empty()) {
        fail(path + ".decision", "online needs 'transitions'");
      }
      model.decision = *mode;
    }
  }
  if (auto it = v.find("trained_on"); it != v.end()) {
    if (!it->is_object()) fail(path + ".trained_on", "expected an object");
    model.provenance = provenanceOf(*it, path + ".trained_on", model);
  }
  if (auto it = v.find("metrics"); it != v.end()) {
    if (!it->is_object()) fail(path + ".metrics", "expected an object");
    model.evaluation = evaluationOf(*it, path + ".metrics", model.group, model.classes.size());
  }
  return model;
}

}  // namespace

const GroupModel* ModelBundle::find(SensorGroup group) const {
  for (const GroupModel& m : models) {
    if (m.group == group) return &m;
  }
  return nullptr;
}

int modelVersionFor(FeatureKind features) {
  if (usesMotion(features)) return 4;
  return features == FeatureKind::Neighbours ? 3 : 2;
}

json modelToJson(const GroupModel& model) {
  const ClassModelSet& set = model.classifier;
  json out;
  out["format"] = kModelFormat;
  out["version"] = modelVersionFor(model.features);
  out["group"] = groupInfo(model.group).shortName;
  out["features"] = featureKindName(model.features);
  json classes = json::array();
  for (const std::string& name : set.classNames())
    classes.push_back(name);
  out["classes"] = std::move(classes);
  out["method"] = classifierMethodName(set.method());
  out["covariance"] = covarianceFormName(model.covariance);
  out["variance_floor"] = model.varianceFloor;
  out["regularization"] = regularizationName(model.regularization);
  json priors = json::array();
  for (Eigen::Index c = 0; c < set.logPriors().size(); ++c)
    priors.push_back(set.logPriors()[c]);
  out["priors"] = std::move(priors);
  if (const GbtModel* trees = set.trees()) {
    // The trees in XGBoost's own JSON form, under the settings that grew them.
    const GbtSettings& g = model.provenance.classifier.gbt;
    json gbt;
    gbt["trees"] = g.trees;
    gbt["depth"] = g.depth;
    gbt["learning_rate"] = g.learningRate;
    gbt["min_child_weight"] = g.minChildWeight;
    auto text = trees->serialize();
    gbt["model"] = text ? json::parse(text.value(), nullptr, false) : json();
    out["gbt"] = std::move(gbt);
    out["version"] = std::max(out["version"].get<int>(), kGbtModelVersion);
  } else {
    json components = json::object();
    for (int c = 0; c < set.classCount(); ++c) {
      components[set.classNames()[static_cast<std::size_t>(c)]] = mixtureToJson(set.model(c));
    }
    out["components"] = std::move(components);
  }
  if (set.hasRestModels()) {
    json rest = json::object();
    for (int c = 0; c < set.classCount(); ++c) {
      rest[set.classNames()[static_cast<std::size_t>(c)]] = mixtureToJson(set.restModel(c));
    }
    out["rest_components"] = std::move(rest);
  }
  if (!model.transitions.empty()) out["transitions"] = transitionsToJson(model.transitions);
  // Never write a non-causal default, nor online without a chain.
  DecisionMode decision = isCausal(model.decision) ? model.decision : DecisionMode::Online;
  if (model.transitions.empty()) decision = DecisionMode::Step;
  out["decision"] = decisionModeName(decision);
  out["trained_on"] = provenanceToJson(model);
  out["metrics"] = evaluationToJson(model);
  return out;
}

json provenanceToJson(const GroupModel& model) {
  const ModelProvenance& p = model.provenance;
  json out = json::object();
  if (!p.labelSet.empty()) out["label_set"] = p.labelSet;
  if (!p.labels.empty()) out["labels"] = p.labels;
  out["train_runs"] = runRefsJson(p.trainRuns);
  out["test_runs"] = runRefsJson(p.testRuns);
  if (!p.split.empty()) out["split"] = p.split;
  if (p.holdout > 0.0) out["holdout"] = p.holdout;
  if (!p.programVersion.empty()) out["program_version"] = p.programVersion;
  if (!p.importedFrom.empty()) out["imported_from"] = p.importedFrom;
  out["settings"] = settingsToJson(model);
  out["samples"] = p.samples;
  out["class_counts"] = classCountsJson(p.classCounts);
  out["zero_rows"] = p.zeroRows;
  if (!p.unmodelled.empty()) {
    json un = json::array();
    for (ContactClass c : p.unmodelled)
      un.push_back(contactClassName(c));
    out["unmodelled_classes"] = std::move(un);
  }
  return out;
}

json evaluationToJson(const GroupModel& model) {
  const ModelEvaluation& e = model.evaluation;
  json out = json::object();
  out["evaluated_on"] = e.evaluatedOn;
  out["samples_train"] = e.samplesTrain;
  out["samples_test"] = e.samplesTest();
  out["fit_s"] = e.fitSeconds;
  out["predict_s"] = e.predictSeconds;
  out["warnings"] = e.warnings;
  // The model's default decision: its balanced accuracy is the headline; null = no test data.
  const DecisionMode d = model.transitions.empty() ? DecisionMode::Step : model.decision;
  out["decision"] = decisionModeName(d);
  out["accuracy"] = optionalJson(e.accuracy(d));
  out["balanced_accuracy"] = optionalJson(e.balancedAccuracy(d));
  json byMode = json::object(), rates = json::object();
  for (DecisionMode m : kDecisionModes) {
    byMode[std::string(decisionModeName(m))] = decisionJson(e.confusion(m));
    rates[std::string(decisionModeName(m))] = optionalJson(e.balancedAccuracy(m));
  }
  out["balanced_accuracy_by_decision"] = std::move(rates);
  out["by_decision"] = std::move(byMode);
  out["mean_loglik"] = optionalJson(e.meanLogLikelihood);
  out["neg_inf_rows"] = e.negInfRows;
  out["zero_rows"] = e.zeroRows;
  if (!e.patterns.rows.empty()) out["contact_patterns"] = patternsToJson(e.patterns);
  if (!e.oneVsRest.empty()) {
    json ovr = json::array();
    for (const BinaryConfusion& b : e.oneVsRest) {
      ovr.push_back({{"class", contactClassName(b.positive)},
                     {"tp", b.truePositive},
                     {"fp", b.falsePositive},
                     {"fn", b.falseNegative},
                     {"tn", b.trueNegative}});
    }
    out["one_vs_rest"] = std::move(ovr);
  }
  if (!e.fit.empty()) {
    json fits = json::array();
    for (std::size_t c = 0; c < e.fit.size(); ++c) {
      const ClassFitRecord& f = e.fit[c];
      fits.push_back({{"class", c < model.classes.size() ? json(contactClassName(model.classes[c]))
                                                         : json(nullptr)},
                      {"iterations", f.iterations},
                      {"converged", f.converged},
                      {"train_mean_loglik", f.trainMeanLogLikelihood},
                      {"dropped_components", f.droppedComponents}});
    }
    out["classes_fit"] = std::move(fits);
  }
  if (!e.scenes.empty()) {
    json scenes = json::array();
    for (const SceneScore& s : e.scenes) {
      json bd = json::object();
      for (DecisionMode m : kDecisionModes)
        bd[std::string(decisionModeName(m))] = decisionJson(s.byDecision[decisionIndex(m)]);
      scenes.push_back({{"scene", s.scene}, {"by_decision", std::move(bd)}});
    }
    out["scenes"] = std::move(scenes);
    json means = json::object();
    for (DecisionMode m : kDecisionModes)
      means[std::string(decisionModeName(m))] =
          optionalJson(meanSceneBalancedAccuracy(e.scenes, m));
    out["scene_mean_balanced_accuracy"] = std::move(means);
  }
  return out;
}

json bundleProvenanceToJson(const ModelBundle& bundle) {
  json out = bundle.models.empty() ? json::object() : provenanceToJson(bundle.models.front());
  for (const char* perGroup :
       {"settings", "samples", "class_counts", "zero_rows", "unmodelled_classes"})
    out.erase(perGroup);
  json settings = json::object();
  for (const GroupModel& m : bundle.models)
    settings[std::string(groupInfo(m.group).shortName)] = settingsToJson(m);
  out["settings"] = std::move(settings);
  return out;
}

json bundleMetricsToJson(const ModelBundle& bundle) {
  json out = json::object();
  for (const GroupModel& m : bundle.models)
    out[std::string(groupInfo(m.group).shortName)] = evaluationToJson(m);
  return out;
}

json bundleToJson(const ModelBundle& bundle) {
  json out;
  out["format"] = kModelBundleFormat;
  int version = 2;
  json models = json::array();
  for (const GroupModel& m : bundle.models) {
    version = std::max(version, modelVersionFor(m.features));
    models.push_back(modelToJson(m));
  }
  out["version"] = version;
  out["models"] = std::move(models);
  return out;
}

Result<ModelBundle> modelsFromJson(const json& value, std::string_view fileName) {
  ModelBundle bundle;
  try {
    if (!value.is_object()) fail("(top level)", "expected a JSON object");
    const std::string format = stringField(value, "(top level)", "format");
    if (format == kModelFormat) {
      bundle.models.push_back(modelOf(value, "(model)"));
    } else if (format == kModelBundleFormat) {
      versionOf(field(value, "(bundle)", "version"), "version");
      const json& models = field(value, "(bundle)", "models");
      if (!models.is_array() || models.empty()) fail("models", "expected a non-empty array");
      for (std::size_t i = 0; i < models.size(); ++i) {
        GroupModel m = modelOf(models[i], "models[" + std::to_string(i) + "]");
        if (bundle.find(m.group) != nullptr) {
          fail("models[" + std::to_string(i) + "].group",
               "second model for group " + std::string(groupInfo(m.group).shortName));
        }
        bundle.models.push_back(std::move(m));
      }
    } else {
      fail("format",
           "expected \"tactile-model\" or \"tactile-model-bundle\", found \"" + format + "\"");
    }
  } catch (const ModelError& e) {
    return Error(std::string(fileName), shownText(e.path + ": " + e.message, 400));
  } catch (const json::exception& e) {
    return Error(std::string(fileName), plainJsonError(e));
  }
  return bundle;
}

Result<ModelBundle> parseModelJson(std::string_view text, std::string_view fileName) {
  Result<json> value = parseJsonText(text, fileName);
  if (!value) {
    Error error = value.error();
    error.message = "invalid JSON: " + error.message;
    return error;
  }
  return modelsFromJson(value.value(), fileName);
}

Result<ModelBundle> readModelFile(const std::filesystem::path& path) {
  Result<std::string> text = readFileText(path);
  if (!text) return text.error();
  return parseModelJson(text.value(), path.string());
}

Status writeModelBundleFile(const std::filesystem::path& path, const ModelBundle& bundle) {
  return writeFileAtomically(path, dumpJson(bundleToJson(bundle), 1) + "\n");
}

}  // namespace tactile::analysis
