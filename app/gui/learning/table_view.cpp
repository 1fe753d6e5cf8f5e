#include "app/gui/learning/table_view.h"

#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSortFilterProxyModel>
#include <QStandardItemModel>
#include <QTableView>
#include <QVBoxLayout>

#include "app/gui/common/file_dialog_memory.h"
#include "base/file_text.h"

namespace tactile::gui {

namespace {

// A cell that sorts as a number when it reads as one.
QStandardItem* itemFor(const std::string& text) {
  auto* item = new QStandardItem(QString::fromStdString(text));
  item->setEditable(false);
  bool number = false;
  const double v = QString::fromStdString(text).toDouble(&number);
  if (number) {
    item->setData(v, Qt::UserRole);
    item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
  } else {
    item->setData(QString::fromStdString(text), Qt::UserRole);
  }
  return item;
}

}  // namespace

TableView::TableView(QWidget* parent) : QWidget(parent) {
  title_ = new QLabel;
  title_->setWordWrap(true);
  title_->setAlignment(Qt::AlignLeft | Qt::AlignTop);
  QFont bold = title_->font();
  bold.setBold(true);
  title_->setFont(bold);
  model_ = new QStandardItemModel(this);
  auto* sorted = new QSortFilterProxyModel(this);
  sorted->setSourceModel(model_);
  sorted->setSortRole(Qt::UserRole);
  view_ = new QTableView;
  view_->setModel(sorted);
  view_->setSortingEnabled(true);
  view_->sortByColumn(-1, Qt::AscendingOrder);  // the table's own order until a header is clicked
  view_->verticalHeader()->hide();
  view_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  view_->verticalHeader()->setDefaultSectionSize(view_->fontMetrics().height() + 8);
  view_->setSelectionBehavior(QAbstractItemView::SelectRows);
  exportButton_ = new QPushButton(tr("Export CSV..."));
  exportButton_->setObjectName(QStringLiteral("exportCsv"));
  exportButton_->setVisible(false);
  connect(exportButton_, &QPushButton::clicked, this, &TableView::chooseCsvFile);
  auto* top = new QHBoxLayout;
  top->addWidget(title_, 1);
  top->addWidget(exportButton_, 0, Qt::AlignTop);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addLayout(top);
  layout->addWidget(view_, 1);
}

void TableView::setTable(const analysis::Table& table, CellColour colour) {
  table_ = table;
  title_->setText(QString::fromStdString(table.title));
  model_->clear();
  QStringList header;
  for (const std::string& h : table.header)
    header << QString::fromStdString(h);
  model_->setHorizontalHeaderLabels(header);
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    QList<QStandardItem*> items;
    for (std::size_t c = 0; c < table.rows[r].size(); ++c) {
      QStandardItem* item = itemFor(table.rows[r][c]);
      if (colour) {
        if (const std::optional<QColor> bg = colour(static_cast<int>(r), static_cast<int>(c)))
          item->setBackground(*bg);
      }
      items << item;
    }
    model_->appendRow(items);
  }
  view_->setVisible(true);
  exportButton_->setVisible(true);
}

void TableView::setMessage(const QString& message) {
  table_ = analysis::Table{};
  model_->clear();
  title_->setText(message);
  view_->setVisible(false);
  exportButton_->setVisible(false);
}

void TableView::setFitHeight(bool fit) {
  view_->setSizeAdjustPolicy(fit ? QAbstractScrollArea::AdjustToContents
                                 : QAbstractScrollArea::AdjustIgnored);
  view_->setSizePolicy(QSizePolicy::Expanding, fit ? QSizePolicy::Maximum : QSizePolicy::Expanding);
  setSizePolicy(QSizePolicy::Preferred, fit ? QSizePolicy::Maximum : QSizePolicy::Preferred);
}

QString TableView::cellText(int row, int column) const {
  const QStandardItem* item = model_->item(row, column);
  return item != nullptr ? item->text() : QString();
}

std::optional<QColor> TableView::cellBackground(int row, int column) const {
  const QStandardItem* item = model_->item(row, column);
  if (item == nullptr || item->background().style() == Qt::NoBrush) return std::nullopt;
  return item->background().color();
}

Status TableView::exportCsv(const QString& path) const {
  return writeFileAtomically(path.toStdString(), table_.render(analysis::TableStyle::Csv));
}

void TableView::chooseCsvFile() {
  const QString path = QFileDialog::getSaveFileName(
      this, tr("Export CSV"), startPath(QStringLiteral("tables")), tr("CSV files (*.csv)"));
  if (path.isEmpty()) return;
  rememberPath(QStringLiteral("tables"), path);
  if (Status s = exportCsv(path); !s)
    QMessageBox::warning(this, tr("Export CSV"), QString::fromStdString(s.errorText()));
}

}  // namespace tactile::gui
