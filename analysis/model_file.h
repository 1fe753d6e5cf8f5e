// Model files (docs/file-formats.md#model-file): the ONE reader and writer of trained per-group
// classifiers.
//
// A model file holds one group's classifier:
//   {"format":"tactile-model","version":1,"group":"R","features":"normal",
//    "classes":["Wall","Corner",...],"method":"gaussian|gmm","covariance":"nodal-diag",
//    "variance_floor":0.03,"regularization":"floor|add","priors":[log P(c), ...],
//    "components":{"Wall":{"weights":[...],"means":[[...],...],"covariances":[...]},...},
//    "rest_components":{...}            (Gaussian one-vs-rest "rest" models, optional)
//    "transitions":{"log_initial":[...],"log_matrix":[[...],...],"pseudo_count":1,
//                   "initial_counts":[...],"counts":[[...],...]}   (version 2, optional)
//    "decision":"step|online",           (version 2; default online with transitions, else step)
//    "trained_on":{...},"metrics":{...}}
// `covariances` lists K matrices (nodal forms) or one (grand forms); each is a list of D rows for
// full forms, or a list of D variances for diagonal forms. `priors` are natural-log class priors in
// `classes` order (optional on read: equal priors when absent).
//
// `transitions` is the group's HMM over `classes` (same order, natural logs; analysis/temporal.h),
// `decision` how the model decides by default; it must be causal (step or online). Version-1 files
// (no transitions) still read, with decision "step".
//
// A model bundle holds one model per group (what `tactile train` writes):
//   {"format":"tactile-model-bundle","version":2,"models":[model, model, ...]}
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
#include "analysis/model_record.h"
#include "analysis/temporal.h"
#include "base/error.h"
#include "run/contact_class.h"
#include "run/sensor_layout.h"

namespace tactile::analysis {

inline constexpr std::string_view kModelFormat = "tactile-model";
inline constexpr std::string_view kModelBundleFormat = "tactile-model-bundle";
// The newest version this program reads. Files are written as version 2 unless a model takes the
// neighbours features (normal+shear+touch+context+neighbours, new in version 3) or a motion kind
// (normal+shear+touch+motion[+neighbours], new in version 4), so that older programs read every
// file they can use and refuse the others by version.
inline constexpr int kModelVersion = 5;
// Gradient-boosted trees came with version 5.
inline constexpr int kGbtModelVersion = 5;
inline constexpr int kOldestModelVersion = 1;
// The version a file with these models is written as.
int modelVersionFor(FeatureKind features);

// One group's trained classifier with the settings that made it.
struct GroupModel {
  SensorGroup group = SensorGroup::Front;
  FeatureKind features = FeatureKind::Normal;
  std::vector<ContactClass> classes;  // parallel to classifier.classNames()
  ClassModelSet classifier;
  CovarianceForm covariance = CovarianceForm::NodalDiag;
  double varianceFloor = 0.0;
  Regularization regularization = Regularization::Floor;
  // The class chain (empty for a version-1 model) and the default decision (always causal).
  TransitionModel transitions;
  DecisionMode decision = DecisionMode::Step;
  ModelProvenance provenance;  // the file's "trained_on"
  ModelEvaluation evaluation;  // the file's "metrics"
};

struct ModelBundle {
  std::vector<GroupModel> models;  // at most one per group
  const GroupModel* find(SensorGroup group) const;
};

nlohmann::json modelToJson(const GroupModel& model);
// A model's "trained_on" and "metrics" objects (also stored beside a model in a database).
nlohmann::json provenanceToJson(const GroupModel& model);
nlohmann::json evaluationToJson(const GroupModel& model);
// A bundle's provenance (the first model's, with every group's settings under "settings") and its
// metrics by group name.
nlohmann::json bundleProvenanceToJson(const ModelBundle& bundle);
nlohmann::json bundleMetricsToJson(const ModelBundle& bundle);
nlohmann::json bundleToJson(const ModelBundle& bundle);

// The scores a model file keeps, as JSON. A confusion is {"classes":[...],"counts":[[...]]}
// over its active classes; the reader is false on a malformed value.
nlohmann::json confusionToJson(const ConfusionMatrix& confusion);
bool confusionFromJson(const nlohmann::json& value, ConfusionMatrix& out);
// [{"pattern","truth","predicted":{class: n}}]; the reader is false on a malformed value.
nlohmann::json patternsToJson(const ContactPatternTable& patterns);
bool patternsFromJson(const nlohmann::json& value, SensorGroup group, ContactPatternTable& out);

// Parses model or bundle text. fileName names the source in errors: "FILE: path.to.field: what is
// wrong", or "FILE:LINE: invalid JSON: ..." for a syntax error.
Result<ModelBundle> parseModelJson(std::string_view text, std::string_view fileName);
// Parses an already-parsed JSON value (a model or a bundle object).
Result<ModelBundle> modelsFromJson(const nlohmann::json& value, std::string_view fileName);
Result<ModelBundle> readModelFile(const std::filesystem::path& path);

// Writes atomically.
Status writeModelBundleFile(const std::filesystem::path& path, const ModelBundle& bundle);

}  // namespace tactile::analysis
