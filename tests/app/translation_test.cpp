// Translations: no .ts entry unfinished or with different placeholders or shortcuts than its
// source; every compiled .qm loads and translates known strings of the code's own contexts
// (menus, classes, plural forms); the interface language follows the setting or the system, and
// numbers follow the interface language.
#include <QDir>
#include <QFile>
#include <QKeySequence>
#include <QMenuBar>
#include <QRegularExpression>
#include <QSet>
#include <QTranslator>
#include <QXmlStreamReader>
#include <QtTest>

#include "app/gui/common/ui_language.h"
#include "app/gui/main_window.h"

using tactile::gui::chooseUiLanguage;
using tactile::gui::MainWindow;
using tactile::gui::uiLocale;

namespace {

struct Entry {
  QString context;
  QString source;
  QStringList forms;  // one per plural form, or the one translation
  bool unfinished = false;
};

QList<Entry> readTs(const QString& path, QString* error) {
  QList<Entry> out;
  QFile file(path);
  if (!file.open(QIODevice::ReadOnly)) {
    *error = path + QStringLiteral(": cannot open");
    return out;
  }
  QXmlStreamReader xml(&file);
  QString context;
  Entry entry;
  bool vanished = false;
  while (!xml.atEnd()) {
    xml.readNext();
    if (xml.isStartElement()) {
      const auto name = xml.name();
      if (name == QLatin1String("name")) {
        context = xml.readElementText();
      } else if (name == QLatin1String("message")) {
        entry = Entry{context, {}, {}, false};
      } else if (name == QLatin1String("source")) {
        entry.source = xml.readElementText();
      } else if (name == QLatin1String("translation")) {
        const QString type = xml.attributes().value(QLatin1String("type")).toString();
        vanished = type == QLatin1String("vanished") || type == QLatin1String("obsolete");
        entry.unfinished = type == QLatin1String("unfinished");
        bool numerus = false;
        QString text;
        while (!xml.atEnd()) {
          xml.readNext();
          if (xml.isStartElement() && xml.name() == QLatin1String("numerusform")) {
            numerus = true;
            entry.forms << xml.readElementText();
          } else if (xml.isCharacters()) {
            text += xml.text();
          } else if (xml.isEndElement() && xml.name() == QLatin1String("translation")) {
            break;
          }
        }
        if (!numerus) entry.forms << text;
      }
    } else if (xml.isEndElement() && xml.name() == QLatin1String("message")) {
      if (!vanished) out << entry;
      vanished = false;
    }
  }
  if (xml.hasError()) *error = path + QStringLiteral(": ") + xml.errorString();
  return out;
}

QSet<QString> placeholders(const QString& text) {
  static const QRegularExpression re(QStringLiteral("%(?:\\d+|n)"));
  QSet<QString> out;
  for (auto it = re.globalMatch(text); it.hasNext();)
    out.insert(it.next().captured());
  return out;
}

QStringList tsFiles() {
  return QDir(QStringLiteral(TACTILE_TS_DIR))
      .entryList({QStringLiteral("tactile_workbench_*.ts")}, QDir::Files, QDir::Name);
}

QString qmPath(const QString& language) {
  return QStringLiteral(TACTILE_QM_DIR "/tactile_workbench_") + language + QStringLiteral(".qm");
}

}  // namespace

class TranslationTest : public QObject {
  Q_OBJECT

 private slots:
  void everyTsEntryIsFinishedWithItsPlaceholdersAndShortcuts() {
    const QStringList files = tsFiles();
    QVERIFY2(files.contains(QStringLiteral("tactile_workbench_de.ts")), "no German .ts");
    QVERIFY2(files.contains(QStringLiteral("tactile_workbench_zh_CN.ts")), "no Chinese .ts");
    QStringList problems;
    for (const QString& name : files) {
      QString error;
      const QList<Entry> entries =
          readTs(QDir(QStringLiteral(TACTILE_TS_DIR)).filePath(name), &error);
      QVERIFY2(error.isEmpty(), qPrintable(error));
      // English holds only the plural forms of the "%n" texts; every other language all texts.
      const bool pluralsOnly = name == QStringLiteral("tactile_workbench_en.ts");
      QVERIFY2(entries.size() > (pluralsOnly ? 5 : 100), qPrintable(name + ": too few entries"));
      for (const Entry& e : entries) {
        const QString where = name + QStringLiteral(" [") + e.context + QStringLiteral("] \"") +
                              e.source + QStringLiteral("\": ");
        if (e.unfinished) problems << where + QStringLiteral("unfinished");
        for (const QString& form : e.forms) {
          if (form.trimmed().isEmpty() && !e.source.trimmed().isEmpty())
            problems << where + QStringLiteral("empty translation");
          QSet<QString> wanted = placeholders(e.source);
          QSet<QString> got = placeholders(form);
          if (wanted != got) problems << where + QStringLiteral("placeholders differ: ") + form;
        }
        // A key sequence in the source ("Ctrl+I") binds a shortcut: its translation must bind the
        // same keys, or the shortcut stops working in that language.
        if (e.source.contains(QLatin1Char('+')) && !e.source.contains(QLatin1Char(' ')) &&
            !QKeySequence::fromString(e.source, QKeySequence::PortableText).isEmpty()) {
          if (QKeySequence::fromString(e.forms.value(0), QKeySequence::PortableText) !=
              QKeySequence::fromString(e.source, QKeySequence::PortableText))
            problems << where + QStringLiteral("shortcut changed to ") + e.forms.value(0);
        }
      }
    }
    QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
  }

  void eachQmLoadsAndTranslatesKnownStrings() {
    struct Known {
      const char* language;
      const char* context;
      const char* source;
      int n;
      const char* expected;
    };
    const Known known[] = {
        {"de", "tactile::gui::MainWindow", "&File", -1, "&Datei"},
        {"de", "ContactClass", "Wall", -1, "Wand"},
        {"de", "tactile::gui::MainWindow", "Imported %n run(s)", 1, "1 Lauf importiert"},
        {"de", "tactile::gui::MainWindow", "Imported %n run(s)", 3, "3 Läufe importiert"},
        {"de", "tactile::gui::RunListModel", "Subject", -1, "Proband"},
        {"zh_CN", "tactile::gui::MainWindow", "&File", -1, "文件(&F)"},
        {"zh_CN", "ContactClass", "Wall", -1, "墙"},
        {"zh_CN", "tactile::gui::MainWindow", "Imported %n run(s)", 3, "已导入 3 个运行"},
        {"zh_CN", "tactile::gui::LabelPanelView", "Label set", -1, "标签集"},
        {"en", "tactile::gui::MainWindow", "Imported %n run(s)", 1, "Imported 1 run"},
        {"en", "tactile::gui::MainWindow", "Imported %n run(s)", 2, "Imported 2 runs"},
    };
    for (const Known& k : known) {
      QTranslator translator;
      const QString language = QString::fromLatin1(k.language);
      QVERIFY2(translator.load(qmPath(language)), qPrintable(qmPath(language)));
      QVERIFY(!translator.isEmpty());
      QString text = translator.translate(k.context, k.source, nullptr, k.n);
      if (k.n >= 0) text.replace(QStringLiteral("%n"), QString::number(k.n));
      QCOMPARE(text, QString::fromUtf8(k.expected));
    }
    // Every language with a .ts file has its .qm.
    for (const QString& name : tsFiles()) {
      const QString language = name.mid(18).chopped(3);
      QTranslator translator;
      QVERIFY2(translator.load(qmPath(language)), qPrintable(language));
    }
  }

  void menusOfTheMainWindowAreTranslated() {
    QTranslator translator;
    QVERIFY(translator.load(qmPath(QStringLiteral("de"))));
    QVERIFY(QCoreApplication::installTranslator(&translator));
    {
      MainWindow window;
      QStringList titles;
      for (QAction* a : window.menuBar()->actions())
        titles << a->text();
      QVERIFY2(titles.contains(QStringLiteral("&Datei")), qPrintable(titles.join(',')));
      QVERIFY2(titles.contains(QStringLiteral("&Bearbeiten")), qPrintable(titles.join(',')));
      QVERIFY2(!titles.contains(QStringLiteral("&File")), qPrintable(titles.join(',')));
    }
    QCoreApplication::removeTranslator(&translator);
  }

  void languageFollowsTheSettingThenTheSystem() {
    const QStringList available{QStringLiteral("de"), QStringLiteral("zh_CN")};
    auto choose = [&](const char* setting, QStringList preferred) {
      return chooseUiLanguage(QString::fromLatin1(setting), preferred, available);
    };
    QCOMPARE(choose("", {"de-DE", "en-US"}), QStringLiteral("de"));
    QCOMPARE(choose("", {"de-AT"}), QStringLiteral("de"));
    QCOMPARE(choose("", {"zh-Hans-CN", "zh-CN"}), QStringLiteral("zh_CN"));
    QCOMPARE(choose("", {"zh-TW"}), QStringLiteral("zh_CN"));
    QCOMPARE(choose("", {"fr-FR", "de-DE"}), QStringLiteral("de"));  // the first translated one
    QCOMPARE(choose("", {"en-GB", "de-DE"}), QStringLiteral("en"));  // English wanted first
    QCOMPARE(choose("", {"fr-FR"}), QStringLiteral("en"));
    QCOMPARE(choose("", {}), QStringLiteral("en"));
    QCOMPARE(choose("en", {"de-DE"}), QStringLiteral("en"));  // the setting wins
    QCOMPARE(choose("zh_CN", {"de-DE"}), QStringLiteral("zh_CN"));
    QCOMPARE(choose("fr", {"de-DE"}), QStringLiteral("de"));  // no such translation
    QCOMPARE(chooseUiLanguage(QString(), {QStringLiteral("de-DE")}, {}), QStringLiteral("en"));
  }

  void numbersFollowTheInterfaceLanguage() {
    const QLocale german(QStringLiteral("de_DE"));
    // English interface on a German system: English numbers, not "1.032".
    QCOMPARE(uiLocale(QStringLiteral("en"), german).toString(1032), QStringLiteral("1,032"));
    QCOMPARE(uiLocale(QStringLiteral("en"), german).toString(0.5), QStringLiteral("0.5"));
    QCOMPARE(uiLocale(QStringLiteral("de"), german).toString(1032), QStringLiteral("1.032"));
    QCOMPARE(uiLocale(QStringLiteral("de"), german).toString(0.5), QStringLiteral("0,5"));
    // German interface on a French system: German numbers.
    QCOMPARE(uiLocale(QStringLiteral("de"), QLocale(QStringLiteral("fr_FR"))).name(),
             QStringLiteral("de_DE"));
    // The system's own variant of the interface language is kept.
    QCOMPARE(uiLocale(QStringLiteral("de"), QLocale(QStringLiteral("de_CH"))).name(),
             QStringLiteral("de_CH"));
    QCOMPARE(uiLocale(QStringLiteral("en"), QLocale(QStringLiteral("en_GB"))).name(),
             QStringLiteral("en_GB"));
    QCOMPARE(uiLocale(QStringLiteral("zh_CN"), QLocale(QStringLiteral("en_US"))).name(),
             QStringLiteral("zh_CN"));
    QCOMPARE(uiLocale(QStringLiteral("zh_CN"), QLocale(QStringLiteral("zh_TW"))).name(),
             QStringLiteral("zh_CN"));
  }
};

QTEST_MAIN(TranslationTest)
#include "translation_test.moc"
