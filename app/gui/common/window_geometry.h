// Windows that fit the screen they are on: a geometry restored from the settings (saved on a larger
// screen, or before a window grew) is clamped to the available area of the screen it lands on.
#pragma once

#include <QByteArray>

class QWidget;

namespace tactile::gui {

// Restores `saved` (QWidget::saveGeometry) when there is one, then keeps the window's frame within
// the available geometry of its screen (no taller or wider than it, no part off it).
void restoreGeometryWithinScreen(QWidget* window, const QByteArray& saved);

// Moves and, where needed, shrinks a top-level window so that its frame lies within the available
// geometry of its screen.
void keepWithinScreen(QWidget* window);

}  // namespace tactile::gui
