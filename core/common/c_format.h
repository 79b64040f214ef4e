#pragma once
// Number text that does not depend on the process locale. Qt applications take LC_ALL from the
// environment, and under de_DE / fr_FR printf writes "57,15" and strtod stops at the '.'. Every
// file CutCell writes (CSV, G-code, SVG, PDF, JSON, run logs) and every number it reads go
// through these: printf-style formatting under the "C" locale of the calling thread only
// (POSIX uselocale, no global state changed, no allocation: safe on the engine thread), and
// std::from_chars for reading.
#include <cstdarg>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace cutcell {

int snprintfC(char* buf, std::size_t size, const char* fmt, ...)
    __attribute__((format(printf, 3, 4)));
int vsnprintfC(char* buf, std::size_t size, const char* fmt, std::va_list ap)
    __attribute__((format(printf, 3, 0)));
// The whole formatted text as a string.
std::string formatC(const char* fmt, ...) __attribute__((format(printf, 1, 2)));
std::string vformatC(const char* fmt, std::va_list ap) __attribute__((format(printf, 1, 0)));
// A sentence for the operator (a job issue's message): formatC under the name by which
// tools/core_messages.py finds its template. The GUI finds the template again from the text and
// shows it translated, its numbers in the GUI language's form. So every value goes in as a
// conversion (%.6g for a number as num() writes it, %d, %s), never glued onto the template,
// and no two conversions stand side by side without text between them.
std::string messageC(const char* fmt, ...) __attribute__((format(printf, 1, 2)));

// The whole of text as a number ("1.5", "-2e-3"); nullopt for anything else (also "1,5",
// trailing text, an empty string, or a value out of the range of a double).
std::optional<double> parseDouble(std::string_view text);

} // namespace cutcell
