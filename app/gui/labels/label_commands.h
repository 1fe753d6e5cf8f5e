// Undo commands of label edits. The first redo (done by QUndoStack::push) performs the edit
// through a function given by the model and keeps the workspace's record of it (the segments
// before and after); later undo and redo write back exactly those segments. An edit that fails on
// its first redo marks itself obsolete, so the stack drops it and nothing half-done stays.
#pragma once

#include <QUndoCommand>

#include <functional>

#include "base/error.h"
#include "workspace/workspace.h"

namespace tactile::gui {

class LabelModel;

class LabelEditCommand : public QUndoCommand {
 public:
  using Apply = std::function<Result<workspace::LabelEdit>()>;

  LabelEditCommand(LabelModel* model, const QString& text, Apply apply,
                   QUndoCommand* parent = nullptr);

  void redo() override;
  void undo() override;

  bool applied() const { return applied_; }
  const Error& error() const { return error_; }

 private:
  LabelModel* model_;
  Apply apply_;
  workspace::LabelEdit edit_;
  bool applied_ = false;
  Error error_;
};

}  // namespace tactile::gui
