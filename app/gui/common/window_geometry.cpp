#include "app/gui/common/window_geometry.h"

#include <QGuiApplication>
#include <QScreen>
#include <QWidget>

#include <algorithm>

namespace tactile::gui {

void keepWithinScreen(QWidget* window) {
  QScreen* screen =
      window->screen() != nullptr ? window->screen() : QGuiApplication::primaryScreen();
  if (screen == nullptr) return;
  const QRect available = screen->availableGeometry();
  // The frame (title bar and borders) around the client area, as the window manager draws it;
  // before the window is shown it is not known and taken as none.
  const QRect frame = window->frameGeometry();
  const QRect client = window->geometry();
  const int extraW = std::max(0, frame.width() - client.width());
  const int extraH = std::max(0, frame.height() - client.height());
  const int width = std::min(client.width(), available.width() - extraW);
  const int height = std::min(client.height(), available.height() - extraH);
  if (width != client.width() || height != client.height()) window->resize(width, height);
  QRect placed = window->frameGeometry();
  placed.moveLeft(std::clamp(placed.left(), available.left(),
                             std::max(available.left(), available.right() - placed.width() + 1)));
  placed.moveTop(std::clamp(placed.top(), available.top(),
                            std::max(available.top(), available.bottom() - placed.height() + 1)));
  if (placed.topLeft() != window->frameGeometry().topLeft()) window->move(placed.topLeft());
}

void restoreGeometryWithinScreen(QWidget* window, const QByteArray& saved) {
  if (!saved.isEmpty()) window->restoreGeometry(saved);
  keepWithinScreen(window);
}

}  // namespace tactile::gui
