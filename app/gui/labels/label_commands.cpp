#include "app/gui/labels/label_commands.h"

#include "app/gui/labels/label_model.h"

namespace tactile::gui {

LabelEditCommand::LabelEditCommand(LabelModel* model, const QString& text, Apply apply,
                                   QUndoCommand* parent)
    : QUndoCommand(text, parent), model_(model), apply_(std::move(apply)) {}

void LabelEditCommand::redo() {
  if (!applied_) {
    Result<workspace::LabelEdit> edit = apply_();
    if (!edit) {
      error_ = edit.error();
      setObsolete(true);
      return;
    }
    edit_ = std::move(edit.value());
    applied_ = true;
    apply_ = {};
    return;
  }
  if (Status s = model_->redoEdit(edit_); !s) error_ = s.error();
}

void LabelEditCommand::undo() {
  if (!applied_) return;
  if (Status s = model_->undoEdit(edit_); !s) error_ = s.error();
}

}  // namespace tactile::gui
