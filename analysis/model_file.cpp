#include "analysis/model_file.h"

#include <cmath>
#include <set>

#include "base/file_text.h"
#include "base/text_rules.h"
#include "run/json_text.h"
#include "run/run_csv.h"

namespace tactile::analysis {

using nlohmann::json;

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
          fail(cpath, "not symmetric at (" + std::to_string(r) + "," + std::to_string(q) + ")");
        }
        if (isDiagonal(form) && (a != 0.0 || b != 0.0)) {
          fail(cpath, "off-diagonal entry in a diagonal covariance form");
        }
      }
      if (!(m(r, r) > 0.0)) fail(cpath, "variance " + std::to_string(r) + " is not positive");
    }
    matrices.push_back(std::move(m));
  }
  Result<GaussianMixture> g = GaussianMixture::create(weights, means, matrices, form);
  if (!g) fail(path, g.error().message);
  return std::move(g.value());
}

GroupModel modelOf(const json& v, const std::string& path) {
  if (!v.is_object()) fail(path, "expected a model object");
  if (stringField(v, path, "format") != kModelFormat) {
    fail(path + ".format", "expected \"" + std::string(kModelFormat) + "\"");
  }
  const json& version = field(v, path, "version");
  if (!version.is_number_integer() || version.get<int>() != kModelVersion) {
    fail(path + ".version", "expected version " + std::to_string(kModelVersion));
  }
  GroupModel model;
  const std::string groupName = stringField(v, path, "group");
  const std::optional<SensorGroup> group = parseSensorGroup(groupName);
  if (!group) fail(path + ".group", "unknown sensor group '" + groupName + "'");
  model.group = *group;
  const std::string featureName = stringField(v, path, "features");
  const std::optional<FeatureKind> kind = parseFeatureKind(featureName);
  if (!kind) {
    fail(path + ".features",
         "expected normal, magnitude, normal+shear or normal+shear+touch, found '" + featureName +
             "'");
  }
  model.features = *kind;
  const int dim = featureDimension(model.group, model.features);
  const std::string methodName = stringField(v, path, "method");
  const std::optional<ClassifierMethod> method = parseClassifierMethod(methodName);
  if (!method) fail(path + ".method", "expected gaussian or gmm, found '" + methodName + "'");
  const std::string covName = stringField(v, path, "covariance");
  const std::optional<CovarianceForm> form = parseCovarianceForm(covName);
  if (!form) fail(path + ".covariance", "unknown covariance form '" + covName + "'");
  model.covariance = *form;
  model.varianceFloor = numberOf(field(v, path, "variance_floor"), path + ".variance_floor");
  if (model.varianceFloor < 0.0) fail(path + ".variance_floor", "must be >= 0");
  const std::string regName = stringField(v, path, "regularization");
  const std::optional<Regularization> reg = parseRegularization(regName);
  if (!reg) fail(path + ".regularization", "expected floor or add, found '" + regName + "'");
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
    if (!cls) fail(cpath, "unknown contact class '" + name + "'");
    if (!seen.insert(name).second) fail(cpath, "class '" + name + "' listed twice");
    model.classes.push_back(*cls);
    names.push_back(name);
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
    if (it == components.end()) fail(path + ".components", "missing class '" + name + "'");
    mixtures.push_back(mixtureOf(*it, cpath, storedForm, dim));
  }
  std::vector<GaussianMixture> rest;
  if (auto it = v.find("rest_components"); it != v.end()) {
    if (!it->is_object() || it->size() != names.size()) {
      fail(path + ".rest_components", "expected one entry per class");
    }
    for (const std::string& name : names) {
      auto r = it->find(name);
      if (r == it->end()) fail(path + ".rest_components", "missing class '" + name + "'");
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
  if (auto it = v.find("trained_on"); it != v.end()) {
    if (!it->is_object()) fail(path + ".trained_on", "expected an object");
    model.trainedOn = *it;
  }
  if (auto it = v.find("metrics"); it != v.end()) {
    if (!it->is_object()) fail(path + ".metrics", "expected an object");
    model.metrics = *it;
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

json modelToJson(const GroupModel& model) {
  const ClassModelSet& set = model.classifier;
  json out;
  out["format"] = kModelFormat;
  out["version"] = kModelVersion;
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
  json components = json::object();
  for (int c = 0; c < set.classCount(); ++c) {
    components[set.classNames()[static_cast<std::size_t>(c)]] = mixtureToJson(set.model(c));
  }
  out["components"] = std::move(components);
  if (set.hasRestModels()) {
    json rest = json::object();
    for (int c = 0; c < set.classCount(); ++c) {
      rest[set.classNames()[static_cast<std::size_t>(c)]] = mixtureToJson(set.restModel(c));
    }
    out["rest_components"] = std::move(rest);
  }
  out["trained_on"] = model.trainedOn.is_object() ? model.trainedOn : json::object();
  out["metrics"] = model.metrics.is_object() ? model.metrics : json::object();
  return out;
}

json bundleToJson(const ModelBundle& bundle) {
  json out;
  out["format"] = kModelBundleFormat;
  out["version"] = kModelVersion;
  json models = json::array();
  for (const GroupModel& m : bundle.models)
    models.push_back(modelToJson(m));
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
      const json& version = field(value, "(bundle)", "version");
      if (!version.is_number_integer() || version.get<int>() != kModelVersion) {
        fail("version", "expected version " + std::to_string(kModelVersion));
      }
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
    return Error(std::string(fileName), e.what());
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

Status writeModelFile(const std::filesystem::path& path, const GroupModel& model) {
  return writeFileAtomically(path, dumpJson(modelToJson(model), 1) + "\n");
}

Status writeModelBundleFile(const std::filesystem::path& path, const ModelBundle& bundle) {
  return writeFileAtomically(path, dumpJson(bundleToJson(bundle), 1) + "\n");
}

}  // namespace tactile::analysis
