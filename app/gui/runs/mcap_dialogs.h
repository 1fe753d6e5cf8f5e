// The workbench's MCAP dialogs (docs/interop.md): what File > Export Run > MCAP writes (the file,
// the label sets and the model to include), and the mapping of a ROS 2 bag dropped on the window
// or opened with File > Import MCAP (topics picked from the file's channels as `tactile mcap info`
// lists them, the tactile layout, the scale, the run's name).
#pragma once

#include <QDialog>
#include <QString>
#include <QStringList>

#include <string>

#include "mcap/reader.h"

class QComboBox;
class QDoubleSpinBox;
class QLineEdit;
class QListWidget;
class QTableWidget;

namespace tactile::gui {

class McapExportDialog : public QDialog {
  Q_OBJECT

 public:
  // `checkedSets` start ticked; `defaultPath` is the file offered (RUN.mcap).
  McapExportDialog(const QString& run, const QStringList& labelSets, const QStringList& checkedSets,
                   const QStringList& models, const QString& defaultPath,
                   QWidget* parent = nullptr);

  QStringList labelSets() const;
  QString model() const;  // empty: none
  QString path() const;

 private:
  void browse();
  void updateOk();

  QListWidget* sets_;
  QComboBox* model_;
  QLineEdit* path_;
};

class McapMappingDialog : public QDialog {
  Q_OBJECT

 public:
  // `scanned` is the file as `tactile mcap info` reads it.
  McapMappingDialog(const mcap::ScanResult& scanned, const QString& file,
                    QWidget* parent = nullptr);

  // The mapping file's text ({"tactile": {"topic": ..., "layout": ...}, "pose": ..., "scale":
  // ...}).
  std::string mappingJson() const;
  QString runName() const;

 private:
  void updateOk();

  QTableWidget* channels_;
  QComboBox* tactile_;
  QComboBox* pose_;
  QComboBox* command_;
  QComboBox* blocked_;
  QComboBox* layout_;
  QDoubleSpinBox* scale_;
  QLineEdit* name_;
};

}  // namespace tactile::gui
