#include "ui/language.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QLocale>
#include <QSettings>
#include <QTranslator>

#include <memory>

namespace CutCell::ui {
namespace {

const char* const kSettingsKey = "ui/language";

// The languages with a catalogue of ours (resources/i18n). English is the source language.
struct Catalogue {
    const char* code;
    const char* nativeName;
    QLocale::Language language;
    QLocale::Country country;
};
constexpr Catalogue kCatalogues[] = {
    {"en", "English", QLocale::English, QLocale::UnitedStates},
    {"de", "Deutsch", QLocale::German, QLocale::Germany},
};

const Catalogue* findCatalogue(const QString& code) {
    for (const Catalogue& c : kCatalogues)
        if (code == QLatin1String(c.code)) return &c;
    return nullptr;
}

// The installed translators (ours and Qt's), replaced on every change.
std::unique_ptr<QTranslator>& ownTranslator() {
    static std::unique_ptr<QTranslator> t;
    return t;
}
std::unique_ptr<QTranslator>& qtTranslator() {
    static std::unique_ptr<QTranslator> t;
    return t;
}
QString& shown() {
    static QString code = QStringLiteral("en");
    return code;
}

void removeTranslators() {
    for (auto* slot : {&ownTranslator(), &qtTranslator()}) {
        if (*slot) QCoreApplication::removeTranslator(slot->get());
        slot->reset();
    }
}

} // namespace

QList<GuiLanguage> guiLanguages() {
    QList<GuiLanguage> out;
    const QString desktop = QLocale::system().nativeLanguageName();
    out.push_back({QStringLiteral("system"),
                   QCoreApplication::translate("GuiLanguage", "System (%1)").arg(desktop)});
    for (const Catalogue& c : kCatalogues)
        out.push_back({QLatin1String(c.code), QString::fromUtf8(c.nativeName)});
    return out;
}

QString rememberedLanguage() {
    const QString code = QSettings().value(kSettingsKey, QStringLiteral("system")).toString();
    return findCatalogue(code) ? code : QStringLiteral("system");
}

void rememberLanguage(const QString& code) {
    QSettings().setValue(kSettingsKey, code);
}

bool applyGuiLanguage(const QString& code, QString* why) {
    const bool followSystem = code == QLatin1String("system");
    const Catalogue* chosen = nullptr;
    if (followSystem) {
        const QLocale desktop = QLocale::system();
        for (const Catalogue& c : kCatalogues)
            if (desktop.language() == c.language) chosen = &c;
        if (!chosen) chosen = findCatalogue(QStringLiteral("en"));
    } else {
        chosen = findCatalogue(code);
        if (!chosen) {
            if (why)
                *why = QCoreApplication::translate("GuiLanguage",
                                                   "unknown language \"%1\" (known: en, de)")
                           .arg(code);
            return false;
        }
    }
    removeTranslators();
    const QString lang = QLatin1String(chosen->code);
    if (lang != QLatin1String("en")) {
        auto own = std::make_unique<QTranslator>();
        if (!own->load(QStringLiteral(":/i18n/cutcell_%1.qm").arg(lang))) {
            if (why)
                *why = QCoreApplication::translate("GuiLanguage",
                                                   "the %1 catalogue is missing from this build")
                           .arg(QString::fromUtf8(chosen->nativeName));
            shown() = QStringLiteral("en");
            QLocale::setDefault(followSystem ? QLocale::system() : QLocale(QLocale::English));
            return false;
        }
        QCoreApplication::installTranslator(own.get());
        ownTranslator() = std::move(own);
        // Qt's own texts (dialog buttons, the file dialog); without them (package
        // qt6-translations-l10n missing) those stay English.
        auto qt = std::make_unique<QTranslator>();
        if (qt->load(QLocale(chosen->language, chosen->country), QStringLiteral("qtbase"),
                     QStringLiteral("_"), QLibraryInfo::path(QLibraryInfo::TranslationsPath))) {
            QCoreApplication::installTranslator(qt.get());
            qtTranslator() = std::move(qt);
        }
    }
    shown() = lang;
    // Numbers: the desktop's own form when following it, the language's otherwise.
    QLocale::setDefault(followSystem ? QLocale::system()
                                     : QLocale(chosen->language, chosen->country));
    return true;
}

QString shownLanguage() {
    return shown();
}

} // namespace CutCell::ui
