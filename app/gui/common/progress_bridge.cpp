#include "app/gui/common/progress_bridge.h"

namespace tactile::gui {

ProgressBridge::ProgressBridge(QObject* parent) : QObject(parent) {}

ProgressFn ProgressBridge::callback() {
  return [this](std::size_t done, std::size_t total) {
    // A signal emitted from another thread reaches a receiver in the GUI thread queued.
    emit progressed(static_cast<qint64>(done), static_cast<qint64>(total));
    return !cancelled_.load();
  };
}

}  // namespace tactile::gui
