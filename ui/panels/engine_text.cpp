#include "ui/panels/engine_text.h"
#include "core/engine/engine_types.h"
#include "ui/language.h"
#include "ui/panels/run_words.h"
#include "ui/shown_number.h"

#include <QCoreApplication>
#include <QHash>
#include <QLocale>
#include <QRegularExpression>

#include <algorithm>
#include <vector>

namespace CutCell::ui {

extern const char* const kCoreMessages[];
extern const int kCoreMessageCount;

namespace {

// A printf conversion as core's templates use them: %s, %d, %u, %zu, %ld, %.3f, %.4g, %04X, %%.
const QRegularExpression& specPattern() {
    static const QRegularExpression re(
        QStringLiteral(R"(%[-+ #0]*\d*(?:\.(\d+))?(?:ll|l|z|h)?([diuxXfgeEsc%]))"));
    return re;
}

struct Spec {
    QChar conversion; // 's', 'd', 'f', 'g', 'X', ...
    int precision = -1;
};

struct Template {
    const char* source = nullptr;
    QRegularExpression pattern;
    std::vector<Spec> specs;
    qsizetype literal = 0; // characters outside the specs: the more, the more specific
};

std::vector<Spec> specsOf(const QString& text) {
    std::vector<Spec> specs;
    for (auto it = specPattern().globalMatch(text); it.hasNext();) {
        const auto m = it.next();
        const QChar c = m.captured(2).at(0);
        if (c == '%') continue;
        specs.push_back({c, m.captured(1).isEmpty() ? -1 : m.captured(1).toInt()});
    }
    return specs;
}

Template compiled(const char* source) {
    Template t;
    t.source = source;
    const QString text = QString::fromUtf8(source);
    QString pattern = QStringLiteral("^");
    qsizetype last = 0;
    for (auto it = specPattern().globalMatch(text); it.hasNext();) {
        const auto m = it.next();
        const QString before = text.mid(last, m.capturedStart() - last);
        pattern += QRegularExpression::escape(before);
        t.literal += before.size();
        last = m.capturedEnd();
        const QChar c = m.captured(2).at(0);
        if (c == '%') {
            pattern += QStringLiteral("%");
            ++t.literal;
            continue;
        }
        t.specs.push_back({c, m.captured(1).isEmpty() ? -1 : m.captured(1).toInt()});
        if (c == 's' || c == 'c')
            pattern += QStringLiteral("(.+?)");
        else if (c == 'x' || c == 'X')
            pattern += QStringLiteral("([0-9A-Fa-f]+)");
        else if (c == 'd' || c == 'i' || c == 'u')
            pattern += QStringLiteral("(-?\\d+)");
        else
            pattern += QStringLiteral(R"((-?(?:\d+(?:\.\d*)?(?:[eE][-+]?\d+)?|inf|nan)))");
    }
    const QString rest = text.mid(last);
    pattern += QRegularExpression::escape(rest) + QStringLiteral("$");
    t.literal += rest.size();
    t.pattern = QRegularExpression(pattern);
    return t;
}

// Most specific first: "Feed hold: decelerating along the path (%s %s)" before
// "Feed hold: %s (%s)".
const std::vector<Template>& templates() {
    static const std::vector<Template> all = [] {
        std::vector<Template> v;
        for (int i = 0; i < kCoreMessageCount; ++i)
            v.push_back(compiled(kCoreMessages[i]));
        std::stable_sort(v.begin(), v.end(), [](const Template& a, const Template& b) {
            return a.literal > b.literal;
        });
        return v;
    }();
    return all;
}

QString translated(const QString& english, int depth);

// A list no template matches as a whole ("bus off, transmit timeout"; the CAN link's
// "node 1: ...; nodes 2, 3: ..."): each item translated. Otherwise the text as it came.
QString listTranslated(const QString& english, int depth) {
    if (depth >= 4) return english;
    for (const QString& separator : {QStringLiteral("; "), QStringLiteral(", ")}) {
        if (!english.contains(separator)) continue;
        QStringList items = english.split(separator);
        bool any = false;
        for (QString& item : items) {
            const QString shown = translated(item, depth + 1);
            any = any || shown != item;
            item = shown;
        }
        if (any) return items.join(separator);
    }
    return english;
}

QString valueText(const Spec& spec, const QString& captured, int depth) {
    const char c = spec.conversion.toLatin1();
    if (c == 's') return depth < 4 ? translated(captured, depth + 1) : captured;
    if (c != 'f' && c != 'g' && c != 'e') return captured; // integers and hex read the same
    bool ok = false;
    const double v = captured.toDouble(&ok); // C notation, as core printed it
    if (!ok) return captured;
    if (c == 'f') return shownNumber(v, spec.precision < 0 ? 6 : spec.precision);
    return shownSignificant(v, spec.precision <= 0 ? 6 : spec.precision);
}

// The translation with its specs replaced, in order, by the values.
QString filled(const QString& translation, const std::vector<QString>& values) {
    QString out;
    qsizetype last = 0;
    size_t k = 0;
    for (auto it = specPattern().globalMatch(translation); it.hasNext();) {
        const auto m = it.next();
        out += translation.mid(last, m.capturedStart() - last);
        last = m.capturedEnd();
        if (m.captured(2) == QLatin1String("%"))
            out += QLatin1Char('%');
        else if (k < values.size())
            out += values[k++];
    }
    return out + translation.mid(last);
}

const Template* templateOf(const QString& english, QRegularExpressionMatch* match) {
    for (const Template& t : templates()) {
        auto m = t.pattern.match(english);
        if (!m.hasMatch()) continue;
        if (match) *match = m;
        return &t;
    }
    return nullptr;
}

QString translated(const QString& english, int depth) {
    if (english.isEmpty()) return english;
    // The states by the words the GUI uses for them everywhere else ("Vorschub halt").
    for (int s = 0; s <= static_cast<int>(cutcell::EngineState::Fault); ++s) {
        const auto state = static_cast<cutcell::EngineState>(s);
        if (english == QLatin1String(cutcell::toString(state))) return stateWord(state);
    }
    QRegularExpressionMatch m;
    const Template* t = templateOf(english, &m);
    if (!t) return listTranslated(english, depth);
    std::vector<QString> values;
    for (size_t k = 0; k < t->specs.size(); ++k)
        values.push_back(valueText(t->specs[k], m.captured(static_cast<int>(k) + 1), depth));
    const QString translation = QCoreApplication::translate("CoreMessage", t->source);
    // A translation whose specs differ from its source's would misplace the values
    // (gui.translations_complete refuses such a catalogue): the English then.
    if (specsOf(translation).size() != t->specs.size())
        return filled(QString::fromUtf8(t->source), values);
    return filled(translation, values);
}

} // namespace

QString engineText(const QString& english) {
    // The device panels show the same few texts many times a second: each is matched once per
    // language (the cache is small; it starts again when full).
    static QHash<QString, QString> cache;
    static QString cacheLanguage;
    const QString language = shownLanguage() + QLatin1Char('/') + QLocale().name();
    if (language != cacheLanguage || cache.size() > 4096) {
        cache.clear();
        cacheLanguage = language;
    }
    if (const auto it = cache.constFind(english); it != cache.constEnd()) return it.value();
    const QString shown = translated(english, 0);
    cache.insert(english, shown);
    return shown;
}

const char* engineTemplateOf(const QString& english) {
    const Template* t = templateOf(english, nullptr);
    return t ? t->source : nullptr;
}

} // namespace CutCell::ui
