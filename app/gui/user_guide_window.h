// Help > User Guide: the user guide (docs/user-guide.md and its pictures, embedded in the program
// under :/guide) shown in a browser window, so an installed workbench needs no source tree.
#pragma once

#include <QDialog>

class QTextBrowser;

namespace tactile::gui {

class UserGuideWindow : public QDialog {
  Q_OBJECT
 public:
  explicit UserGuideWindow(QWidget* parent = nullptr);

  // Where the embedded guide lives.
  static QString guideUrl();

  const QTextBrowser* browser() const { return browser_; }

 private:
  QTextBrowser* browser_;
};

}  // namespace tactile::gui
