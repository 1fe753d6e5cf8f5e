// Turns the core's progress callback (called on a worker thread) into a queued Qt signal, and a
// Cancel from the GUI thread into the callback's `false`.
#pragma once

#include <QObject>

#include <atomic>
#include <cstdint>

#include "base/progress.h"

namespace tactile::gui {

class ProgressBridge : public QObject {
  Q_OBJECT

 public:
  explicit ProgressBridge(QObject* parent = nullptr);

  // The callback to hand to a core function; safe to call from any thread.
  ProgressFn callback();
  bool cancelled() const { return cancelled_.load(); }

 public slots:
  void cancel() { cancelled_.store(true); }

 signals:
  // Queued to the bridge's thread; `total` 0 means unknown.
  void progressed(qint64 done, qint64 total);

 private:
  std::atomic<bool> cancelled_{false};
};

}  // namespace tactile::gui
