// The interface language: the Preferences choice (settings key ui/language) or else the first of
// the system's preferred languages the workbench has a translation for, English otherwise. One
// QLocale follows the chosen language everywhere (numbers, dates), so a German system with the
// English interface shows "1,032", not "1.032".
#pragma once

#include <QLocale>
#include <QString>
#include <QStringList>

class QCoreApplication;
class QTranslator;

namespace tactile::gui {

// The translations built into the program (":/i18n/tactile_workbench_LANG.qm") and installed next
// to it (PREFIX/share/tactile-workbench/translations), as language codes ("de", "zh_CN"), sorted;
// English, the source language, is not among them.
QStringList availableTranslations();

// The language to show: `setting` when it is "en" or one of `available`, else the first of
// `preferred` (system UI languages, most wanted first, e.g. "de-AT", "zh-Hans-CN") whose language
// has a translation (any Chinese maps to "zh_CN"), stopping at the first English one; "en" when
// none matches.
QString chooseUiLanguage(const QString& setting, const QStringList& preferred,
                         const QStringList& available);

// The locale for numbers in `language`: the system locale when it speaks that language (so a Swiss
// German keeps his separators), else the language's main locale (en -> en_US, de -> de_DE,
// zh_CN -> zh_CN).
QLocale uiLocale(const QString& language, const QLocale& system = QLocale::system());

// Chooses the language from the settings and the system, makes its locale the default and
// installs its translators (the workbench's own and, where Debian's qt6-translations-l10n is
// installed, Qt's for standard buttons). The translators are children of `app`. Returns the
// language shown.
QString installUiLanguage(QCoreApplication& app);

// Loads the workbench's translation for `language` into `translator` (built-in first, then the
// installed folder).
bool loadWorkbenchTranslation(QTranslator& translator, const QString& language);

}  // namespace tactile::gui
