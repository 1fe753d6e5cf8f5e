// Model files (docs/file-formats.md#model-file): the ONE reader and writer of trained per-group
// classifiers.
//
// A model file holds one group's classifier:
//   {"format":"tactile-model","version":1,"group":"R","features":"normal",
//    "classes":["Wall","Corner",...],"method":"gaussian|gmm","covariance":"nodal-diag",
//    "variance_floor":0.03,"regularization":"floor|add","priors":[log P(c), ...],
//    "components":{"Wall":{"weights":[...],"means":[[...],...],"covariances":[...]},...},
//    "rest_components":{...}            (Gaussian one-vs-rest "rest" models, optional)
//    "trained_on":{...},"metrics":{...}}
// `covariances` lists K matrices (nodal forms) or one (grand forms); each is a list of D rows for
// full forms, or a list of D variances for diagonal forms. `priors` are natural-log class priors in
// `classes` order (optional on read: equal priors when absent).
//
// A model bundle holds one model per group (what `tactile train` writes):
//   {"format":"tactile-model-bundle","version":1,"models":[model, model, ...]}
// Readers accept either; a single model reads as a bundle of one.
//
// Doubles are written as the shortest text that reads back to the same bits (nlohmann_json's
// number serialisation), so a model read back classifies bit for bit like the one written.
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/classifier.h"
#include "analysis/features.h"
#include "analysis/gmm.h"
#include "base/error.h"
#include "run/contact_class.h"
#include "run/sensor_layout.h"

namespace tactile::analysis {

inline constexpr std::string_view kModelFormat = "tactile-model";
inline constexpr std::string_view kModelBundleFormat = "tactile-model-bundle";
inline constexpr int kModelVersion = 1;

// One group's trained classifier with the settings that made it.
struct GroupModel {
  SensorGroup group = SensorGroup::Front;
  FeatureKind features = FeatureKind::Normal;
  std::vector<ContactClass> classes;  // parallel to classifier.classNames()
  ClassModelSet classifier;
  CovarianceForm covariance = CovarianceForm::NodalDiag;
  double varianceFloor = 0.0;
  Regularization regularization = Regularization::Floor;
  nlohmann::json trainedOn = nlohmann::json::object();  // free-form provenance
  nlohmann::json metrics = nlohmann::json::object();    // free-form evaluation results
};

struct ModelBundle {
  std::vector<GroupModel> models;  // at most one per group
  const GroupModel* find(SensorGroup group) const;
};

nlohmann::json modelToJson(const GroupModel& model);
nlohmann::json bundleToJson(const ModelBundle& bundle);

// Parses model or bundle text. fileName names the source in errors: "FILE: path.to.field: what is
// wrong", or "FILE:LINE: invalid JSON: ..." for a syntax error.
Result<ModelBundle> parseModelJson(std::string_view text, std::string_view fileName);
// Parses an already-parsed JSON value (a model or a bundle object).
Result<ModelBundle> modelsFromJson(const nlohmann::json& value, std::string_view fileName);
Result<ModelBundle> readModelFile(const std::filesystem::path& path);

// Writes atomically; a bundle of exactly one model is still written as a bundle.
Status writeModelFile(const std::filesystem::path& path, const GroupModel& model);
Status writeModelBundleFile(const std::filesystem::path& path, const ModelBundle& bundle);

}  // namespace tactile::analysis
