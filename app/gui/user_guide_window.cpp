#include "app/gui/user_guide_window.h"

#include <QAction>
#include <QDesktopServices>
#include <QDialogButtonBox>
#include <QEvent>
#include <QFile>
#include <QHBoxLayout>
#include <QImage>
#include <QLabel>
#include <QScrollBar>
#include <QStyle>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextCursor>
#include <QTextDocument>
#include <QTextFragment>
#include <QTextImageFormat>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>

#include "app/gui/common/window_geometry.h"

namespace tactile::gui {

QString UserGuideWindow::guideUrl() {
  return QStringLiteral("qrc:/guide/user-guide.md");
}

QUrl UserGuideWindow::embeddedTarget(const QUrl& base, const QUrl& link) {
  if (!link.isRelative() && link.scheme() != QLatin1String("qrc")) return {};
  QUrl target = base.resolved(link);
  target.setFragment(QString());
  if (target.scheme() != QLatin1String("qrc")) return {};
  if (!QFile::exists(QLatin1Char(':') + target.path())) return {};
  return target;
}

UserGuideWindow::UserGuideWindow(QWidget* parent) : QDialog(parent) {
  setObjectName(QStringLiteral("userGuideWindow"));
  setWindowTitle(tr("User Guide"));
  browser_ = new QTextBrowser(this);
  browser_->setObjectName(QStringLiteral("userGuideText"));
  // Links between the guide's own pages stay inside; web and file links open outside.
  browser_->setOpenLinks(false);
  connect(browser_, &QTextBrowser::anchorClicked, this, &UserGuideWindow::follow);
  connect(browser_, &QTextBrowser::sourceChanged, this, [this] {
    fitImages();
    setWindowTitle(tr("User Guide: %1")
                       .arg(browser_->documentTitle().isEmpty() ? browser_->source().fileName()
                                                                : browser_->documentTitle()));
  });

  auto button = [this](QStyle::StandardPixmap icon, const QString& text, const QKeySequence& key,
                       const char* name) {
    auto* b = new QToolButton(this);
    b->setObjectName(QLatin1String(name));
    b->setIcon(style()->standardIcon(icon));
    b->setText(text);
    b->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    b->setShortcut(key);
    b->setToolTip(QStringLiteral("%1 (%2)").arg(text, key.toString(QKeySequence::NativeText)));
    b->setEnabled(false);
    return b;
  };
  back_ = button(QStyle::SP_ArrowBack, tr("Back"), QKeySequence::Back, "guideBack");
  forward_ = button(QStyle::SP_ArrowForward, tr("Forward"), QKeySequence::Forward, "guideForward");
  auto* home = button(QStyle::SP_DirHomeIcon, tr("Contents"), QKeySequence(Qt::ALT | Qt::Key_Home),
                      "guideHome");
  home->setEnabled(true);
  connect(back_, &QToolButton::clicked, browser_, &QTextBrowser::backward);
  connect(forward_, &QToolButton::clicked, browser_, &QTextBrowser::forward);
  connect(home, &QToolButton::clicked, this, [this] { follow(QUrl(guideUrl())); });
  connect(browser_, &QTextBrowser::backwardAvailable, back_, &QToolButton::setEnabled);
  connect(browser_, &QTextBrowser::forwardAvailable, forward_, &QToolButton::setEnabled);
  note_ = new QLabel(this);
  note_->setObjectName(QStringLiteral("guideNote"));
  note_->setWordWrap(true);

  auto* bar = new QHBoxLayout;
  bar->addWidget(back_);
  bar->addWidget(forward_);
  bar->addWidget(home);
  bar->addWidget(note_, 1);

  browser_->setSource(QUrl(guideUrl()), QTextDocument::MarkdownResource);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::close);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(bar);
  layout->addWidget(browser_);
  layout->addWidget(buttons);
  resize(980, 820);
  keepWithinScreen(this);
  // Pictures follow the viewer's width as it changes (the dialog's own resize comes before the
  // viewer has its new size).
  browser_->viewport()->installEventFilter(this);
}

bool UserGuideWindow::eventFilter(QObject* watched, QEvent* event) {
  if (watched == browser_->viewport() && event->type() == QEvent::Resize) fitImages();
  return QDialog::eventFilter(watched, event);
}

void UserGuideWindow::follow(const QUrl& link) {
  note_->clear();
  if (link.isRelative() && link.path().isEmpty() && link.hasFragment()) {
    browser_->scrollToAnchor(link.fragment());
    return;
  }
  if (!link.isRelative() && link.scheme() != QLatin1String("qrc")) {
    QDesktopServices::openUrl(link);
    return;
  }
  const QUrl target = embeddedTarget(browser_->source(), link);
  if (target.isEmpty()) {
    // A link to a file of the source tree (a script, a header): not part of the guide.
    note_->setText(
        tr("%1 is not part of the embedded guide; it is in the source tree.").arg(link.toString()));
    return;
  }
  QUrl shown = target;
  shown.setFragment(link.fragment());
  if (target.path().endsWith(QLatin1String(".md")))
    browser_->setSource(shown, QTextDocument::MarkdownResource);
  else
    browser_->setSource(shown);
}

void UserGuideWindow::fitImages() {
  QTextDocument* doc = browser_->document();
  // The viewer's width less the page margins and room for a scroll bar that may come.
  const int available =
      std::max(100, browser_->viewport()->width() - 2 * static_cast<int>(doc->documentMargin()) -
                        browser_->verticalScrollBar()->sizeHint().width());
  QTextCursor cursor(doc);
  cursor.beginEditBlock();
  for (QTextBlock block = doc->begin(); block.isValid(); block = block.next()) {
    for (auto it = block.begin(); !it.atEnd(); ++it) {
      const QTextFragment fragment = it.fragment();
      if (!fragment.charFormat().isImageFormat()) continue;
      QTextImageFormat format = fragment.charFormat().toImageFormat();
      const QVariant resource = doc->resource(QTextDocument::ImageResource, QUrl(format.name()));
      const QImage image =
          resource.value<QImage>().isNull()
              ? browser_->loadResource(QTextDocument::ImageResource, QUrl(format.name()))
                    .value<QImage>()
              : resource.value<QImage>();
      if (image.isNull() || image.width() <= 0) continue;
      const int width = std::min(image.width(), available);
      if (static_cast<int>(format.width()) == width) continue;
      format.setWidth(width);
      format.setHeight(static_cast<double>(image.height()) * width / image.width());
      cursor.setPosition(fragment.position());
      cursor.setPosition(fragment.position() + fragment.length(), QTextCursor::KeepAnchor);
      cursor.setCharFormat(format);
    }
  }
  cursor.endEditBlock();
}

}  // namespace tactile::gui
