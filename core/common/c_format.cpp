#include "core/common/c_format.h"

#include <charconv>
#include <clocale>
#include <cstdio>
#include <locale.h>
#include <vector>

namespace cutcell {
namespace {

// Made once; uselocale() with it switches only the calling thread.
locale_t cLocale() {
    static const locale_t c = newlocale(LC_ALL_MASK, "C", static_cast<locale_t>(nullptr));
    return c;
}

class CLocaleScope {
  public:
    CLocaleScope() : old_(uselocale(cLocale())) {}
    ~CLocaleScope() { uselocale(old_); }
    CLocaleScope(const CLocaleScope&) = delete;
    CLocaleScope& operator=(const CLocaleScope&) = delete;

  private:
    locale_t old_;
};

} // namespace

int vsnprintfC(char* buf, std::size_t size, const char* fmt, std::va_list ap) {
    const CLocaleScope scope;
    return std::vsnprintf(buf, size, fmt, ap);
}

int snprintfC(char* buf, std::size_t size, const char* fmt, ...) {
    std::va_list ap;
    va_start(ap, fmt);
    const int n = vsnprintfC(buf, size, fmt, ap);
    va_end(ap);
    return n;
}

std::string vformatC(const char* fmt, std::va_list ap) {
    char small[256];
    std::va_list again;
    va_copy(again, ap);
    const int n = vsnprintfC(small, sizeof small, fmt, ap);
    std::string out;
    if (n < 0) {
        out.clear();
    } else if (static_cast<std::size_t>(n) < sizeof small) {
        out.assign(small, static_cast<std::size_t>(n));
    } else {
        out.resize(static_cast<std::size_t>(n) + 1);
        vsnprintfC(out.data(), out.size(), fmt, again);
        out.resize(static_cast<std::size_t>(n));
    }
    va_end(again);
    return out;
}

std::string formatC(const char* fmt, ...) {
    std::va_list ap;
    va_start(ap, fmt);
    std::string out = vformatC(fmt, ap);
    va_end(ap);
    return out;
}

std::string messageC(const char* fmt, ...) {
    std::va_list ap;
    va_start(ap, fmt);
    std::string out = vformatC(fmt, ap);
    va_end(ap);
    return out;
}

std::optional<double> parseDouble(std::string_view text) {
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    double v = 0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
    if (r.ec != std::errc() || r.ptr != text.data() + text.size() || text.empty())
        return std::nullopt;
    return v;
}

} // namespace cutcell
