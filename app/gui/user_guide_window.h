// Help > User Guide: the user guide (docs/user-guide.md, the pages it links and their pictures,
// embedded in the program under :/guide) shown in a browser window with Back and Forward, so an
// installed workbench needs no source tree.
#pragma once

#include <QDialog>
#include <QUrl>

class QLabel;
class QTextBrowser;
class QToolButton;

namespace tactile::gui {

class UserGuideWindow : public QDialog {
  Q_OBJECT
 public:
  explicit UserGuideWindow(QWidget* parent = nullptr);

  // Where the embedded guide lives.
  static QString guideUrl();
  // The embedded resource a link of the page at `base` leads to (its fragment dropped), or an
  // empty URL when the link leaves the guide (a web address) or names nothing embedded.
  static QUrl embeddedTarget(const QUrl& base, const QUrl& link);

  const QTextBrowser* browser() const { return browser_; }
  // Follows a link as a click on it does.
  void follow(const QUrl& link);
  QToolButton* backButton() const { return back_; }
  QToolButton* forwardButton() const { return forward_; }

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  // Pictures wider than the viewer are drawn at its width (height in proportion).
  void fitImages();

  QTextBrowser* browser_;
  QToolButton* back_;
  QToolButton* forward_;
  QLabel* note_;
};

}  // namespace tactile::gui
