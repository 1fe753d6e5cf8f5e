// The learning half of `tactile._core`: features of a run, labelled data sets, the classifier
// engine behind the scikit-learn estimators, training, sweeps, classifying and model files. Every
// call is the product's own core call, the one the CLI makes.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <string_view>
#include <unordered_map>

#include "analysis/classifier.h"
#include "analysis/classify_run.h"
#include "analysis/feature_table.h"
#include "analysis/features.h"
#include "analysis/sweep.h"
#include "analysis/training.h"
#include "python/src/common.h"
#include "run/label_file.h"

namespace tactile::python {
namespace {

using analysis::ClassifierOptions;
using analysis::ClassModelSet;
using analysis::CovarianceForm;
using analysis::GaussianMixture;

// A covariance form: this product's four names, or scikit-learn's "full", "diag" and "tied" where
// they mean the same (one full or diagonal covariance per component; one full covariance shared).
CovarianceForm parseForm(const std::string& name) {
  if (name == "full") return CovarianceForm::NodalFull;
  if (name == "diag") return CovarianceForm::NodalDiag;
  if (name == "tied") return CovarianceForm::GrandFull;
  const auto form = analysis::parseCovarianceForm(name);
  if (!form) {
    throw py::value_error("unknown covariance_type '" + name +
                          "' (nodal-full or full, nodal-diag or diag, grand-full or tied, "
                          "grand-diag)");
  }
  return *form;
}

analysis::FeatureKind parseKind(const std::string& name) {
  const auto kind = analysis::parseFeatureKind(name);
  if (!kind) {
    throw py::value_error("unknown feature kind '" + name +
                          "' (normal, magnitude, normal+shear, normal+shear+touch, "
                          "normal+shear+touch+context, normal+shear+touch+context+neighbours, "
                          "normal+shear+touch+motion, normal+shear+touch+motion+neighbours)");
  }
  return *kind;
}

analysis::DecisionMode parseDecision(const std::string& name) {
  const auto d = analysis::parseDecisionMode(name);
  if (!d) throw py::value_error("unknown decision '" + name + "' (step, online, offline)");
  return *d;
}

template <class T, class Parse>
T parsed(const std::string& name, Parse parse, const char* what) {
  const auto v = parse(name);
  if (!v) throw py::value_error(std::string("unknown ") + what + " '" + name + "'");
  return *v;
}

// An Eigen matrix moved into a numpy array (Fortran order) that owns it.
py::array_t<double> ownedMatrix(Eigen::MatrixXd&& matrix) {
  auto* owned = new Eigen::MatrixXd(std::move(matrix));
  py::capsule owner(owned, [](void* p) { delete static_cast<Eigen::MatrixXd*>(p); });
  const auto rows = static_cast<py::ssize_t>(owned->rows());
  const auto cols = static_cast<py::ssize_t>(owned->cols());
  return py::array_t<double>({rows, cols}, {py::ssize_t{8}, rows * 8}, owned->data(), owner);
}

Eigen::MatrixXd toMatrix(const py::array_t<double, py::array::f_style | py::array::forcecast>& a) {
  if (a.ndim() != 2) throw py::value_error("expected a 2-D array of samples (rows x features)");
  return Eigen::Map<const Eigen::MatrixXd>(a.data(), a.shape(0), a.shape(1));
}

// ---- the classifier engine of the estimators ----------------------------------------------

struct Classifier {
  ClassModelSet model;
  std::vector<int> iterations;
  std::vector<bool> converged;
  std::vector<int> droppedComponents;
  std::vector<std::string> warnings;
  double fitSeconds = 0.0;
};

ClassifierOptions classifierOptions(const std::string& method, int components,
                                    const std::string& covariance, double floor,
                                    const std::string& reg, const std::string& init,
                                    std::uint64_t seed, int restarts, int maxIterations,
                                    double tolerance, const std::string& tolRule,
                                    int kmeansIterations, const std::string& priors, int threads) {
  ClassifierOptions o;
  o.method = parsed<analysis::ClassifierMethod>(method, analysis::parseClassifierMethod, "method");
  o.gmm.components = components;
  o.gmm.form = parseForm(covariance);
  o.gmm.varianceFloor = floor;
  o.gmm.reg = parsed<analysis::Regularization>(reg, analysis::parseRegularization,
                                               "regularization (floor or add)");
  o.gmm.init = parsed<analysis::GmmInit>(init, analysis::parseGmmInit,
                                         "init (kmeans++ or random-from-data)");
  o.gmm.seed = seed;
  o.gmm.restarts = restarts;
  o.gmm.maxIterations = maxIterations;
  o.gmm.tolerance = tolerance;
  o.gmm.rule = parsed<analysis::ConvergenceRule>(tolRule, analysis::parseConvergenceRule,
                                                 "tolerance rule (relative or absolute)");
  o.gmm.kmeansIterations = kmeansIterations;
  o.priors =
      parsed<analysis::PriorMode>(priors, analysis::parsePriorMode, "priors (equal or empirical)");
  o.threads = threads;
  o.gmm.threads = threads;
  // As `tactile fit`: scored by the per-class likelihoods alone, no one-vs-rest models.
  o.oneVsRest = false;
  // As scikit-learn's estimators: a class with fewer samples than features is fitted too.
  o.fewSamples = true;
  if (components < 1) throw py::value_error("n_components must be at least 1");
  if (!(floor >= 0.0) || !std::isfinite(floor))
    throw py::value_error("variance_floor must be >= 0");
  if (restarts < 1) throw py::value_error("n_init must be at least 1");
  if (maxIterations < 1) throw py::value_error("max_iter must be at least 1");
  if (!(tolerance >= 0.0)) throw py::value_error("tol must be >= 0");
  if (threads < 0) throw py::value_error("n_jobs must be >= 0 (0: all cores)");
  return o;
}

// The labels of `y` (1-D) as indices into their distinct values, numbered in the order the values
// first appear: (the row of each distinct value's first appearance, each row's index), or None
// for a dtype handled elsewhere (floating point and others: the caller sorts the labels). Object
// labels are one value when Python finds them equal (==, as numpy's unique does), looked up by
// their hash; integer, boolean, bytes and text arrays are compared by their stored bytes. A None
// or NaN label raises ValueError.
py::object labelCodes(const py::array& y) {
  if (y.ndim() != 1) throw py::value_error("expected a 1-D array of labels");
  const char kind = y.dtype().kind();
  const bool isObject = kind == 'O';
  if (!isObject && kind != 'i' && kind != 'u' && kind != 'b' && kind != 'U' && kind != 'S')
    return py::none();
  const py::ssize_t n = y.shape(0);
  const py::ssize_t stride = y.strides(0);
  const auto itemsize = static_cast<std::size_t>(y.itemsize());
  const char* base = static_cast<const char*>(y.data());
  py::array_t<std::int64_t> codes(n);
  std::int64_t* code = codes.mutable_data();
  std::vector<std::int64_t> first;
  if (isObject) {
    std::unordered_multimap<Py_hash_t, std::int64_t> byHash;  // to the distinct value's index
    std::vector<PyObject*> distinct;
    // The objects met most recently and their indices, looked up by address before hashing: a
    // column of labels read from a file usually holds a few objects, each many times.
    constexpr std::size_t kSeen = 16;
    std::array<std::pair<PyObject*, std::int64_t>, kSeen> seen{};
    std::size_t seenCount = 0;
    std::size_t seenNext = 0;
    for (py::ssize_t r = 0; r < n; ++r) {
      PyObject* o = nullptr;
      std::memcpy(&o, base + r * stride, sizeof o);
      std::int64_t found = -1;
      for (std::size_t i = 0; i < seenCount; ++i) {
        if (seen[i].first == o) {
          found = seen[i].second;
          break;
        }
      }
      if (found < 0) {
        if (o == nullptr || o == Py_None ||
            (PyFloat_Check(o) && std::isnan(PyFloat_AS_DOUBLE(o)))) {
          throw py::value_error("y holds a missing label (None or NaN)");
        }
        const Py_hash_t h = PyObject_Hash(o);  // cached by str objects
        if (h == -1) throw py::error_already_set();
        for (auto [at, end] = byHash.equal_range(h); at != end && found < 0; ++at) {
          // Identity first, then ==.
          const int same =
              PyObject_RichCompareBool(o, distinct[static_cast<std::size_t>(at->second)], Py_EQ);
          if (same < 0) throw py::error_already_set();
          if (same == 1) found = at->second;
        }
        if (found < 0) {
          found = static_cast<std::int64_t>(distinct.size());
          distinct.push_back(o);
          first.push_back(r);
          byHash.emplace(h, found);
        }
        seen[seenNext] = {o, found};
        seenNext = (seenNext + 1) % kSeen;
        seenCount = std::min(seenCount + 1, kSeen);
      }
      code[r] = found;
    }
  } else {
    std::unordered_map<std::string_view, std::int64_t> byValue;
    // The first distinct values, compared byte for byte before hashing (a few classes).
    constexpr std::size_t kFew = 16;
    std::vector<std::string_view> few;
    for (py::ssize_t r = 0; r < n; ++r) {
      const std::string_view value(base + r * stride, itemsize);
      std::int64_t found = -1;
      for (std::size_t i = 0; i < few.size(); ++i) {
        if (few[i] == value) {
          found = static_cast<std::int64_t>(i);
          break;
        }
      }
      if (found < 0) {
        const auto [it, added] = byValue.emplace(value, static_cast<std::int64_t>(byValue.size()));
        if (added) {
          first.push_back(r);
          if (few.size() < kFew) few.push_back(value);
        }
        found = it->second;
      }
      code[r] = found;
    }
  }
  return py::make_tuple(
      py::array_t<std::int64_t>(static_cast<py::ssize_t>(first.size()), first.data()), codes);
}

// Fits on the rows of `x` (n x D float64, any layout) whose class indices are `codes` (n of them,
// into `classNames`): split by class with the core's splitByClass, as `tactile fit` does, and
// trained, both with the GIL released.
std::shared_ptr<Classifier> fitClassifier(
    const py::array_t<double>& x,
    const py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>& codes,
    const std::vector<std::string>& classNames, const ClassifierOptions& options) {
  if (x.ndim() != 2) throw py::value_error("expected a 2-D array of samples (rows x features)");
  if (codes.ndim() != 1 || codes.shape(0) != x.shape(0))
    throw py::value_error("expected one class index per row");
  if (x.strides(0) % 8 != 0 || x.strides(1) % 8 != 0)
    throw py::value_error("the samples' strides are not whole float64 values");
  const py::ssize_t n = x.shape(0);
  std::vector<int> labels(static_cast<std::size_t>(n));
  const std::int64_t* c = codes.data();
  for (py::ssize_t r = 0; r < n; ++r) {
    if (c[r] < 0 || c[r] >= static_cast<std::int64_t>(classNames.size()))
      throw py::value_error("class index " + std::to_string(c[r]) + " of row " + std::to_string(r) +
                            " names no class");
    labels[static_cast<std::size_t>(r)] = static_cast<int>(c[r]);
  }
  analysis::ClassifierFit fit;
  const auto work = [&](const ProgressFn& progress) {
    const std::vector<Eigen::MatrixXd> samples =
        analysis::splitByClass(x.data(), n, x.shape(1), x.strides(0) / 8, x.strides(1) / 8,
                               labels.data(), classNames.size());
    fit = analysis::trainClassifier(samples, classNames, options, progress);
  };
  // One thread: every fit runs on this thread (parallelFor's calling thread) and reports after
  // each EM iteration, so it is interrupted from here without a worker thread.
  if (options.threads == 1) {
    runInterruptibleHere(work);
  } else {
    runInterruptible(work);
  }
  if (!fit.ok) throw py::value_error(fit.reason);
  auto out = std::make_shared<Classifier>();
  out->model = std::move(fit.model);
  out->iterations = fit.iterations;
  out->converged = fit.converged;
  out->droppedComponents = fit.droppedComponents;
  out->warnings = fit.warnings;
  out->fitSeconds = fit.fitSeconds;
  return out;
}

Eigen::MatrixXd checkedSamples(
    const Classifier& c, const py::array_t<double, py::array::f_style | py::array::forcecast>& x) {
  Eigen::MatrixXd samples = toMatrix(x);
  if (samples.cols() != c.model.dimension()) {
    throw py::value_error("X has " + std::to_string(samples.cols()) +
                          " features, but the classifier was fitted with " +
                          std::to_string(c.model.dimension()));
  }
  return samples;
}

py::tuple mixtureState(const GaussianMixture& g) {
  py::list covariances;
  for (const Eigen::MatrixXd& c : g.covariances())
    covariances.append(py::cast(c));
  return py::make_tuple(py::cast(g.weights()), py::cast(g.means()), covariances,
                        std::string(analysis::covarianceFormName(g.form())));
}

GaussianMixture mixtureFromState(const py::tuple& t) {
  std::vector<Eigen::MatrixXd> covariances;
  for (const py::handle c : t[2].cast<py::list>())
    covariances.push_back(c.cast<Eigen::MatrixXd>());
  auto g = GaussianMixture::create(t[0].cast<Eigen::VectorXd>(), t[1].cast<Eigen::MatrixXd>(),
                                   covariances, parseForm(t[3].cast<std::string>()));
  if (!g) raiseValueError(g.error());
  return std::move(g.value());
}

py::tuple classifierState(const Classifier& c) {
  py::list models, rest;
  for (const GaussianMixture& g : c.model.models())
    models.append(mixtureState(g));
  for (const GaussianMixture& g : c.model.restModels())
    rest.append(mixtureState(g));
  return py::make_tuple(std::string(analysis::classifierMethodName(c.model.method())),
                        c.model.classNames(), py::cast(c.model.logPriors()), models, rest,
                        c.iterations, c.converged, c.droppedComponents, c.warnings, c.fitSeconds);
}

std::shared_ptr<Classifier> classifierFromState(const py::tuple& t) {
  std::vector<GaussianMixture> models, rest;
  for (const py::handle m : t[3].cast<py::list>())
    models.push_back(mixtureFromState(m.cast<py::tuple>()));
  for (const py::handle m : t[4].cast<py::list>())
    rest.push_back(mixtureFromState(m.cast<py::tuple>()));
  auto set = ClassModelSet::create(
      parsed<analysis::ClassifierMethod>(t[0].cast<std::string>(), analysis::parseClassifierMethod,
                                         "method"),
      t[1].cast<std::vector<std::string>>(), std::move(models), t[2].cast<Eigen::VectorXd>(),
      std::move(rest));
  if (!set) raiseValueError(set.error());
  auto c = std::make_shared<Classifier>();
  c->model = std::move(set.value());
  c->iterations = t[5].cast<std::vector<int>>();
  c->converged = t[6].cast<std::vector<bool>>();
  c->droppedComponents = t[7].cast<std::vector<int>>();
  c->warnings = t[8].cast<std::vector<std::string>>();
  c->fitSeconds = t[9].cast<double>();
  return c;
}

// ---- runs, labels, data sets -----------------------------------------------------------------

// The labels of a stored run from a label set, as Workspace::loadLabelled reads them for
// training: the set's segments through analysis::labelsFromSegments.
std::vector<std::optional<ContactClass>> runLabels(Database& db, std::int64_t setId,
                                                   const Run& run) {
  workspace::Workspace& rws = db.ws();
  auto info = rws.runStore().find(run.name);
  if (!info) raiseValueError(info.error());
  auto segments = rws.labelStore().segments(setId, info->id);
  if (!segments) raiseValueError(segments.error());
  std::vector<LabelRecord> records;
  for (const storage::LabelSegment& s : segments.value())
    records.push_back({run.name, s.group, s.firstStep, s.lastStep, s.cls, s.annotator, 0});
  auto labels = analysis::labelsFromSegments(run.data, run.name, records);
  if (!labels) throw py::value_error("run '" + run.name + "': " + labels.errorText());
  return std::move(labels.value());
}

// Labelled contact rows of one group over runs, in run order then step order: exactly the rows
// training fits on (analysis::buildGroupDataSet).
py::tuple dataset(Database& db, const std::string& set,
                  const std::vector<std::shared_ptr<Run>>& runs, const std::string& group,
                  const std::string& kind) {
  auto found = db.ws().labelStore().find(set);
  if (!found) raiseValueError(found.error());
  std::vector<analysis::LabelledRun> labelled;
  for (const std::shared_ptr<Run>& r : runs)
    labelled.push_back({&r->data, runLabels(db, found->id, *r)});
  analysis::GroupDataSet data =
      analysis::buildGroupDataSet(labelled, parseGroup(group), parseKind(kind));
  py::array_t<std::uint8_t> y(static_cast<py::ssize_t>(data.y.size()));
  for (std::size_t i = 0; i < data.y.size(); ++i)
    y.mutable_data()[i] = static_cast<std::uint8_t>(data.y[i]);
  py::array_t<std::uint32_t> runIndex(static_cast<py::ssize_t>(data.runIndex.size()),
                                      data.runIndex.data());
  py::array_t<std::uint32_t> step(static_cast<py::ssize_t>(data.step.size()), data.step.data());
  return py::make_tuple(ownedMatrix(std::move(data.x)), y, runIndex, step);
}

// ---- models ----------------------------------------------------------------------------------

// Fixed-width unicode names (numpy "<U11") of one group's classes at every step.
py::array classNames(const analysis::GroupClassification& g, std::size_t steps, bool stepDecision) {
  constexpr py::ssize_t kWidth = 11;  // "LeavingWall"
  py::array out(py::dtype("<U11"), std::vector<py::ssize_t>{static_cast<py::ssize_t>(steps)});
  auto* chars = static_cast<std::uint32_t*>(out.mutable_data());
  for (std::size_t t = 0; t < steps; ++t) {
    const std::string name = stepDecision ? g.stepClassName(t) : g.className(t);
    std::uint32_t* o = chars + static_cast<py::ssize_t>(t) * kWidth;
    for (py::ssize_t k = 0; k < kWidth; ++k)
      o[k] = k < static_cast<py::ssize_t>(name.size()) ? static_cast<unsigned char>(name[k]) : 0;
  }
  return out;
}

py::dict classify(const Model& model, const Run& run, const std::optional<std::string>& decision) {
  analysis::ClassifyOptions options;
  if (decision) options.decision = parseDecision(*decision);
  analysis::RunClassification result;
  {
    py::gil_scoped_release release;
    result = analysis::classifyRun(run.data, model.bundle, options);
  }
  py::dict out;
  for (const GroupInfo& g : kSensorGroups) {
    out[py::str(std::string(g.shortName))] = classNames(
        result.groups[static_cast<std::size_t>(groupIndex(g.group))], result.steps, false);
  }
  return out;
}

py::list modelGroups(const Model& model) {
  py::list out;
  for (const analysis::GroupModel& g : model.bundle.models) {
    py::dict d;
    d["group"] = std::string(groupInfo(g.group).shortName);
    d["features"] = std::string(analysis::featureKindName(g.features));
    d["classes"] = g.classifier.classNames();
    d["method"] = std::string(analysis::classifierMethodName(g.classifier.method()));
    d["covariance"] = std::string(analysis::covarianceFormName(g.covariance));
    d["variance_floor"] = g.varianceFloor;
    d["components"] =
        g.classifier.models().empty() ? 0 : g.classifier.models().front().components();
    d["decision"] = std::string(analysis::decisionModeName(g.decision));
    out.append(d);
  }
  return out;
}

std::shared_ptr<Model> loadModelFile(const std::filesystem::path& path) {
  if (!std::filesystem::exists(path)) {
    raiseOSError(ENOENT, "no model file at this path", path.string());
  }
  Result<analysis::ModelBundle> bundle = analysis::readModelFile(path);
  if (!bundle) raiseFileError(bundle.error(), path.string());
  auto m = std::make_shared<Model>();
  m->bundle = std::move(bundle.value());
  return m;
}

std::shared_ptr<Model> storedModel(Database& db, const std::string& name) {
  auto bundle = db.ws().loadModel(name);
  if (!bundle) raiseValueError(bundle.error());
  auto m = std::make_shared<Model>();
  m->name = name;
  m->bundle = std::move(bundle.value());
  return m;
}

// ---- train and sweep ---------------------------------------------------------------------------

struct TrainArgs {
  std::string set;
  std::vector<std::string> trainRuns, testRuns, groups;
  std::string split = "by-run";
  std::string name;
  std::size_t minRows = 20;
  std::optional<std::string> method, covariance, features, init, reg;
  std::optional<int> components, restarts, maxIterations, trees, depth;
  std::optional<double> floor, tolerance, emissionWeight, learningRate, minChildWeight;
  std::uint64_t seed = 1;
  std::string decision = "online";
  int threads = 0;
  bool store = true;
};

// Each group's default settings (analysis::defaultGroupSettings, as `tactile train` and the
// workbench), with what was given applied to every group: the CLI's rule.
analysis::GroupSettings trainSettings(const TrainArgs& a) {
  analysis::GroupSettings out = analysis::defaultGroupSettings();
  const analysis::DecisionMode decision = parseDecision(a.decision);
  if (!analysis::isCausal(decision)) {
    throw py::value_error("decision must be online or step (a model's default is causal)");
  }
  for (const GroupInfo& info : kSensorGroups) {
    analysis::TrainSettings& s = out.of(info.group);
    ClassifierOptions& o = s.classifier;
    std::optional<analysis::ClassifierMethod> given;
    if (a.method) {
      given = parsed<analysis::ClassifierMethod>(*a.method, analysis::parseClassifierMethod,
                                                 "method (gmm, gaussian or gbt)");
    }
    // Options of one family without a method train that family, as `tactile train` does.
    const auto method =
        analysis::impliedMethod(given, a.components || a.covariance || a.floor || a.restarts,
                                a.trees || a.depth || a.learningRate || a.minChildWeight, o.method);
    if (!method) throw py::value_error(method.errorText());
    o.method = method.value();
    if (a.components) o.gmm.components = *a.components;
    if (a.covariance) o.gmm.form = parseForm(*a.covariance);
    if (a.floor) o.gmm.varianceFloor = *a.floor;
    if (a.restarts) o.gmm.restarts = *a.restarts;
    if (a.maxIterations) o.gmm.maxIterations = *a.maxIterations;
    if (a.tolerance) o.gmm.tolerance = *a.tolerance;
    if (a.trees) o.gbt.trees = *a.trees;
    if (a.depth) o.gbt.depth = *a.depth;
    if (a.learningRate) o.gbt.learningRate = *a.learningRate;
    if (a.minChildWeight) o.gbt.minChildWeight = *a.minChildWeight;
    if (a.init) o.gmm.init = parsed<analysis::GmmInit>(*a.init, analysis::parseGmmInit, "init");
    if (a.reg) {
      o.gmm.reg = parsed<analysis::Regularization>(*a.reg, analysis::parseRegularization, "reg");
    }
    // The method brings its own default features and weight of the chain's evidence.
    s.features =
        a.features ? parseKind(*a.features) : analysis::defaultFeatures(info.group, o.method);
    s.emissionWeight = analysis::defaultEmissionWeight(info.group, o.method);
    if (a.emissionWeight) {
      if (!std::isfinite(*a.emissionWeight) || *a.emissionWeight <= 0.0)
        throw py::value_error("emission_weight must be a finite number > 0");
      s.emissionWeight = *a.emissionWeight;
    }
    o.gmm.seed = a.seed;
    o.threads = a.threads;
    o.gmm.threads = a.threads;
    s.decision = decision;
  }
  return out;
}

py::tuple train(Database& db, const TrainArgs& a) {
  const auto split = workspace::parseSplitMode(a.split);
  if (!split) {
    throw py::value_error("unknown split '" + a.split + "' (by-run, leave-one-run-out, by-scene)");
  }
  workspace::TrainRequest request;
  request.labelSet = a.set;
  request.trainRuns = a.trainRuns;
  request.testRuns = a.testRuns;
  request.split = *split;
  for (const std::string& g : a.groups)
    request.groups.push_back(parseGroup(g));
  request.settings = trainSettings(a);
  request.modelName = a.name;
  request.minRowsPerGroup = a.minRows;
  request.store = a.store;
  Result<workspace::TrainOutcome> outcome = Error("not trained");
  workspace::Workspace& ws = db.ws();
  runInterruptible([&](const ProgressFn& progress) { outcome = ws.train(request, progress); });
  if (!outcome) raiseValueError(outcome.error());
  const std::string report = workspace::trainReportJson(outcome.value(), request).dump();
  auto model = std::make_shared<Model>();
  model->name = outcome->modelName;
  model->bundle = std::move(outcome->bundle);
  return py::make_tuple(report, model);
}

// The sweep's arguments are the request's text form, parsed and checked by the same function as
// the CLI's options (workspace::parseSweepRequest): the same bad request, the same words.
// scikit-learn's covariance names ("diag", "tied", ...) are this module's everywhere, the sweep's
// too: they are spelt in this product's words before the request is parsed.
py::tuple sweep(Database& db, workspace::SweepRequestText a) {
  for (std::string& c : a.covariances) {
    if (c == "full" || c == "diag" || c == "tied")
      c = std::string(analysis::covarianceFormName(parseForm(c)));
  }
  auto parsedRequest = workspace::parseSweepRequest(a, workspace::SweepSource::Database);
  if (!parsedRequest) raiseValueError(parsedRequest.error());
  const workspace::SweepRequest& request = parsedRequest.value();
  Result<workspace::SweepOutcome> outcome = Error("not swept");
  workspace::Workspace& ws = db.ws();
  runInterruptible([&](const ProgressFn& progress) { outcome = ws.sweep(request, {}, progress); });
  if (!outcome) raiseValueError(outcome.error());
  py::list cells;
  for (const analysis::SweepCellResult& c : outcome->result.cells)
    cells.append(analysis::sweepCellToJson(c).dump());
  return py::make_tuple(outcome->sweepId, cells, outcome->result.cancelled,
                        outcome->result.wallSeconds);
}

}  // namespace

void bindLearning(py::module_& m) {
  m.def(
      "features",
      [](const Run& run, const std::string& group, const std::string& kind) {
        analysis::GroupSteps steps;
        {
          py::gil_scoped_release release;
          steps = analysis::extractGroupSteps(run.data, parseGroup(group), parseKind(kind));
        }
        return ownedMatrix(std::move(steps.features));
      },
      py::arg("run"), py::arg("group"), py::arg("kind") = "normal",
      "One group's feature vector at every step: steps x D (rows of steps where the group "
      "touches nothing are zero).");
  m.def(
      "contact",
      [](const Run& run, const std::string& group) {
        const SensorGroup g = parseGroup(group);
        py::array_t<bool> out(static_cast<py::ssize_t>(run.data.stepCount()));
        for (std::size_t t = 0; t < run.data.stepCount(); ++t)
          out.mutable_data()[t] = !analysis::groupIsZero(run.data, t, g);
        return out;
      },
      py::arg("run"), py::arg("group"),
      "True at the steps where the group touches something (the others are NoContact by rule).");
  m.def("dataset", &dataset, py::arg("db"), py::arg("set"), py::arg("runs"), py::arg("group"),
        py::arg("kind") = "normal");
  m.def("classifier_options", &classifierOptions);
  py::class_<ClassifierOptions>(m, "ClassifierOptions");

  py::class_<Classifier, std::shared_ptr<Classifier>>(m, "Classifier")
      .def_property_readonly("class_names",
                             [](const Classifier& c) { return c.model.classNames(); })
      .def_property_readonly("n_features", [](const Classifier& c) { return c.model.dimension(); })
      .def_property_readonly("log_priors", [](const Classifier& c) { return c.model.logPriors(); })
      .def_readonly("iterations", &Classifier::iterations)
      .def_readonly("converged", &Classifier::converged)
      .def_readonly("dropped_components", &Classifier::droppedComponents)
      .def_readonly("warnings", &Classifier::warnings)
      .def_readonly("fit_seconds", &Classifier::fitSeconds)
      .def_property_readonly("components",
                             [](const Classifier& c) {
                               std::vector<int> k;
                               for (const GaussianMixture& g : c.model.models())
                                 k.push_back(g.components());
                               return k;
                             })
      .def("log_likelihoods",
           [](const Classifier& c,
              const py::array_t<double, py::array::f_style | py::array::forcecast>& x) {
             const Eigen::MatrixXd samples = checkedSamples(c, x);
             Eigen::MatrixXd out;
             {
               py::gil_scoped_release release;
               c.model.logLikelihoods(samples, out);
             }
             return ownedMatrix(std::move(out));
           })
      .def("predict",
           [](const Classifier& c,
              const py::array_t<double, py::array::f_style | py::array::forcecast>& x) {
             const Eigen::MatrixXd samples = checkedSamples(c, x);
             std::vector<int> predicted;
             {
               py::gil_scoped_release release;
               predicted = c.model.predict(samples);
             }
             return py::array_t<int>(static_cast<py::ssize_t>(predicted.size()), predicted.data());
           })
      .def(py::pickle([](const Classifier& c) { return classifierState(c); },
                      [](const py::tuple& t) { return classifierFromState(t); }));
  m.def("label_codes", &labelCodes, py::arg("y"));
  m.def("fit_classifier", &fitClassifier, py::arg("x"), py::arg("codes"), py::arg("class_names"),
        py::arg("options"));

  py::class_<Model, std::shared_ptr<Model>>(m, "Model", "A model bundle: one model per group.")
      .def_readonly("name", &Model::name)
      .def_property_readonly("groups", &modelGroups)
      .def("classify", &classify, py::arg("run"), py::arg("decision") = py::none(),
           "Class names at every step, per group (the CLI's `tactile classify`): by each "
           "model's default decision, or decision='step', 'online' or 'offline'.")
      .def(
          "save",
          [](const Model& model, const std::filesystem::path& path) {
            const Status written = analysis::writeModelBundleFile(path, model.bundle);
            if (!written) raiseFileError(written.error(), path.string());
          },
          py::arg("path"))
      .def("to_json",
           [](const Model& model) { return analysis::bundleToJson(model.bundle).dump(); })
      .def("__repr__", [](const Model& model) {
        return "<tactile.Model" + (model.name.empty() ? std::string() : " '" + model.name + "'") +
               ", " + std::to_string(model.bundle.models.size()) + " group model(s)>";
      });
  m.def("load_model", &loadModelFile, py::arg("path"));
  m.def("stored_model", &storedModel, py::arg("db"), py::arg("name"));

  py::class_<TrainArgs>(m, "TrainArgs")
      .def(py::init<>())
      .def_readwrite("set", &TrainArgs::set)
      .def_readwrite("train_runs", &TrainArgs::trainRuns)
      .def_readwrite("test_runs", &TrainArgs::testRuns)
      .def_readwrite("groups", &TrainArgs::groups)
      .def_readwrite("split", &TrainArgs::split)
      .def_readwrite("name", &TrainArgs::name)
      .def_readwrite("min_rows", &TrainArgs::minRows)
      .def_readwrite("method", &TrainArgs::method)
      .def_readwrite("covariance_type", &TrainArgs::covariance)
      .def_readwrite("features", &TrainArgs::features)
      .def_readwrite("init", &TrainArgs::init)
      .def_readwrite("reg", &TrainArgs::reg)
      .def_readwrite("n_components", &TrainArgs::components)
      .def_readwrite("n_init", &TrainArgs::restarts)
      .def_readwrite("max_iter", &TrainArgs::maxIterations)
      .def_readwrite("variance_floor", &TrainArgs::floor)
      .def_readwrite("tol", &TrainArgs::tolerance)
      .def_readwrite("n_estimators", &TrainArgs::trees)
      .def_readwrite("max_depth", &TrainArgs::depth)
      .def_readwrite("learning_rate", &TrainArgs::learningRate)
      .def_readwrite("min_child_weight", &TrainArgs::minChildWeight)
      .def_readwrite("emission_weight", &TrainArgs::emissionWeight)
      .def_readwrite("seed", &TrainArgs::seed)
      .def_readwrite("decision", &TrainArgs::decision)
      .def_readwrite("n_jobs", &TrainArgs::threads)
      .def_readwrite("store", &TrainArgs::store);
  m.def("train", &train, py::arg("db"), py::arg("args"));

  using SweepText = workspace::SweepRequestText;
  py::class_<SweepText>(m, "SweepArgs")
      .def(py::init<>())
      .def_readwrite("set", &SweepText::labelSet)
      .def_readwrite("train_runs", &SweepText::trainRuns)
      .def_readwrite("test_runs", &SweepText::testRuns)
      .def_readwrite("groups", &SweepText::groups)
      .def_readwrite("methods", &SweepText::methods)
      .def_readwrite("orders", &SweepText::orders)
      .def_readwrite("covariance_types", &SweepText::covariances)
      .def_readwrite("variance_floors", &SweepText::floors)
      .def_readwrite("n_estimators", &SweepText::trees)
      .def_readwrite("max_depths", &SweepText::depths)
      .def_readwrite("learning_rates", &SweepText::learningRates)
      .def_readwrite("min_child_weights", &SweepText::minChildWeights)
      .def_readwrite("features", &SweepText::features)
      .def_readwrite("seeds", &SweepText::seeds)
      .def_readwrite("decisions", &SweepText::decisions)
      .def_readwrite("split", &SweepText::split)
      .def_readwrite("reg", &SweepText::reg)
      .def_readwrite("init", &SweepText::init)
      .def_readwrite("n_init", &SweepText::restarts)
      .def_readwrite("max_iter", &SweepText::maxIterations)
      .def_readwrite("tol", &SweepText::tolerance)
      .def_readwrite("name", &SweepText::name)
      .def_readwrite("n_jobs", &SweepText::threads);
  m.def("sweep", &sweep, py::arg("db"), py::arg("args"));
}

}  // namespace tactile::python
