#include "app/gui/learning/sweep_cells_model.h"

#include <QString>

#include <algorithm>

#include <utility>

namespace tactile::gui {

namespace {

QString text(std::string_view s) {
  return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

bool isTrees(const analysis::SweepCell& c) {
  return c.method == analysis::ClassifierMethod::Gbt;
}

bool isGaussian(const analysis::SweepCell& c) {
  return c.method == analysis::ClassifierMethod::Gaussian;
}

// Test steps of the cell's rarest scored class (0 without test steps).
std::size_t rarestTestSteps(const analysis::ConfusionMatrix& m) {
  std::size_t rarest = 0;
  for (ContactClass c : m.activeClasses()) {
    const std::size_t n = m.trueCount(c);
    if (n > 0 && (rarest == 0 || n < rarest)) rarest = n;
  }
  return rarest;
}

}  // namespace

SweepCellsModel::SweepCellsModel(QObject* parent) : QAbstractTableModel(parent) {}

void SweepCellsModel::setCells(std::vector<analysis::SweepCellResult> cells) {
  beginResetModel();
  cells_ = std::move(cells);
  endResetModel();
}

void SweepCellsModel::addCell(const analysis::SweepCellResult& cell) {
  const int row = static_cast<int>(cells_.size());
  beginInsertRows({}, row, row);
  cells_.push_back(cell);
  endInsertRows();
}

void SweepCellsModel::clear() {
  setCells({});
}

int SweepCellsModel::rowCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : static_cast<int>(cells_.size());
}

int SweepCellsModel::columnCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : ColumnCount;
}

QVariant SweepCellsModel::data(const QModelIndex& index, int role) const {
  if (!index.isValid() || index.row() >= rowCount()) return {};
  const analysis::SweepCellResult& r = cells_[static_cast<std::size_t>(index.row())];
  const analysis::SweepCell& c = r.cell;
  const bool sort = role == Qt::UserRole;
  if (role == Qt::TextAlignmentRole) {
    const int c = index.column();
    const bool numeric =
        c == Order || c == Floor || c == Seed || (c >= BalancedAccuracy && c <= Iterations);
    return numeric ? QVariant(int(Qt::AlignRight | Qt::AlignVCenter)) : QVariant();
  }
  if (role == Qt::ToolTipRole) {
    if (!r.ok) return text(r.reason);
    QStringList lines;
    if (index.column() == TestSteps) {
      for (ContactClass cls : r.confusion.activeClasses())
        if (const std::size_t n = r.confusion.trueCount(cls); n > 0)
          lines << tr("%1: %2 test steps%3")
                       .arg(text(contactClassName(cls)))
                       .arg(n)
                       .arg(n < analysis::kMinTestSteps ? tr(" (too few)") : QString());
    }
    for (const std::string& w : r.warnings)
      lines << text(w);
    return lines.isEmpty() ? QVariant() : QVariant(lines.join(QLatin1Char('\n')));
  }
  if (role != Qt::DisplayRole && !sort) return {};
  // A score of a cell without a model sorts below every real score; a cell with a model but no
  // test steps has no score (never a 0), and sorts just above the cells without a model.
  const auto score = [&](double value, int decimals) -> QVariant {
    if (!r.ok) return sort ? QVariant(-1.0) : QVariant(QStringLiteral("-"));
    if (r.confusion.total() == 0) return sort ? QVariant(-0.5) : QVariant(tr("no test data"));
    return sort ? QVariant(value) : QVariant(QString::number(value, 'f', decimals));
  };
  switch (index.column()) {
    case Group:
      return sort ? QVariant(static_cast<int>(c.group))
                  : QVariant(text(groupInfo(c.group).shortName));
    case Method:
      return text(analysis::classifierMethodName(c.method));
    case Form:
      return isGaussian(c) || isTrees(c) ? QString() : text(analysis::covarianceFormName(c.form));
    case Order:
      return (isGaussian(c) || isTrees(c)) && !sort ? QVariant(QString()) : QVariant(c.order);
    case Floor:
      if (isTrees(c)) return sort ? QVariant(-1.0) : QVariant(QString());
      return sort ? QVariant(c.varianceFloor) : QVariant(QString::number(c.varianceFloor, 'g', 4));
    case Trees:
      if (!isTrees(c)) return sort ? QVariant(-1.0) : QVariant(QString());
      if (sort) return QVariant(c.trees * 100.0 + c.depth + c.learningRate);
      return tr("%1 trees, depth %2, rate %3, weight %4")
          .arg(c.trees)
          .arg(c.depth)
          .arg(c.learningRate, 0, 'g', 4)
          .arg(c.minChildWeight, 0, 'g', 4);
    case Features:
      return text(analysis::featureKindName(c.features));
    case Decision:
      return text(analysis::decisionModeName(c.decision));
    case TestSteps: {
      const std::size_t steps = r.confusion.total();
      if (sort) return QVariant(static_cast<qulonglong>(steps));
      if (!r.ok) return QString();
      if (steps == 0) return tr("none");
      const std::size_t rarest = rarestTestSteps(r.confusion);
      return rarest < analysis::kMinTestSteps ? tr("%1 (rarest %2, too few)").arg(steps).arg(rarest)
                                              : tr("%1 (rarest %2)").arg(steps).arg(rarest);
    }
    case Seed:
      return sort ? QVariant(static_cast<qulonglong>(c.seed)) : QVariant(QString::number(c.seed));
    case FitSeconds:  // shown in milliseconds, sorted by the seconds
      return sort ? QVariant(r.fitSeconds)
                  : QVariant(QString::number(1000.0 * r.fitSeconds, 'f', 1));
    case PredictSeconds:
      return sort ? QVariant(r.predictSeconds)
                  : QVariant(QString::number(1000.0 * r.predictSeconds, 'f', 1));
    case Iterations:
      return r.iterations;
    case Converged:
      return r.ok ? (r.converged ? tr("yes") : tr("no")) : QString();
    case Accuracy:
      return score(100.0 * r.metrics.accuracy, 1);
    case BalancedAccuracy:
      return score(100.0 * r.metrics.balancedAccuracy, 1);
    case MacroF1:
      return score(r.metrics.macroF1, 3);
    case LogLikelihood:
      if (!r.meanLogLikelihood) return sort ? QVariant(-1e300) : QVariant(QStringLiteral("-"));
      return score(*r.meanLogLikelihood, 2);
    case Status:
      return r.ok ? tr("fitted") : tr("no model: %1").arg(text(r.reason));
    default:
      return {};
  }
}

QVariant SweepCellsModel::headerData(int section, Qt::Orientation orientation, int role) const {
  if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
  switch (section) {
    case Group:
      return tr("Group");
    case Method:
      return tr("Method");
    case Form:
      return tr("Covariance");
    case Order:
      return tr("Order");
    case Floor:
      return tr("Floor");
    case Trees:
      return tr("Trees");
    case Features:
      return tr("Features");
    case Decision:
      return tr("Decision");
    case TestSteps:
      return tr("Test steps");
    case Seed:
      return tr("Seed");
    case FitSeconds:
      return tr("Fit ms");
    case PredictSeconds:
      return tr("Predict ms");
    case Iterations:
      return tr("Iterations");
    case Converged:
      return tr("Converged");
    case Accuracy:
      return tr("Accuracy %");
    case BalancedAccuracy:
      return tr("Balanced %");
    case MacroF1:
      return tr("Macro-F1");
    case LogLikelihood:
      return tr("Held-out loglik");
    case Status:
      return tr("Status");
    default:
      return {};
  }
}

std::vector<std::pair<int, bool>> SweepCellsModel::settingsColumns(
    const std::vector<analysis::ClassifierMethod>& methods) {
  const auto uses = [&methods](analysis::ClassifierMethod m) {
    return std::find(methods.begin(), methods.end(), m) != methods.end();
  };
  const bool mixtures =
      uses(analysis::ClassifierMethod::Gmm) || uses(analysis::ClassifierMethod::Gaussian);
  return {{Form, mixtures},
          {Order, mixtures},
          {Floor, mixtures},
          {Trees, uses(analysis::ClassifierMethod::Gbt)}};
}

}  // namespace tactile::gui
