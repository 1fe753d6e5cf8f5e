#include "app/gui/user_guide_window.h"

#include <QDesktopServices>
#include <QDialogButtonBox>
#include <QTextBrowser>
#include <QUrl>
#include <QVBoxLayout>

namespace tactile::gui {

QString UserGuideWindow::guideUrl() {
  return QStringLiteral("qrc:/guide/user-guide.md");
}

UserGuideWindow::UserGuideWindow(QWidget* parent) : QDialog(parent) {
  setObjectName(QStringLiteral("userGuideWindow"));
  setWindowTitle(tr("User Guide"));
  browser_ = new QTextBrowser(this);
  browser_->setObjectName(QStringLiteral("userGuideText"));
  // Links between the guide's own pages stay inside; web and file links open outside.
  browser_->setOpenLinks(false);
  connect(browser_, &QTextBrowser::anchorClicked, this, [this](const QUrl& url) {
    if (url.scheme() == QLatin1String("qrc") || url.isRelative()) {
      if (url.hasFragment() && url.path().isEmpty())
        browser_->scrollToAnchor(url.fragment());
      else
        browser_->setSource(browser_->source().resolved(url));
    } else {
      QDesktopServices::openUrl(url);
    }
  });
  browser_->setSource(QUrl(guideUrl()), QTextDocument::MarkdownResource);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::close);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(browser_);
  layout->addWidget(buttons);
  resize(980, 820);
}

}  // namespace tactile::gui
