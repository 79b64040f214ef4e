#include "core/machine/import_batch.h"

#include "core/job/job_io.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <set>

namespace cutcell {
namespace {

namespace fs = std::filesystem;

std::string lower(std::string s) {
    for (char& c : s)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// "*.nc1" against a file name, case-insensitively (the patterns are "*" + an extension).
bool matches(const JobImporter& importer, const fs::path& file) {
    const std::string name = lower(file.filename().string());
    for (const std::string& p : importer.patterns) {
        const std::string ext = lower(p.rfind('*', 0) == 0 ? p.substr(1) : p);
        if (name.size() > ext.size() &&
            name.compare(name.size() - ext.size(), ext.size(), ext) == 0)
            return true;
    }
    return false;
}

std::string jobNameFor(const fs::path& file, std::set<std::string>& taken) {
    std::string stem;
    for (const char c : file.stem().string())
        stem += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.'
                    ? c
                    : '_';
    if (stem.empty()) stem = "piece";
    std::string name = stem + ".json";
    for (int i = 2; !taken.insert(name).second; ++i)
        name = stem + "-" + std::to_string(i) + ".json";
    return name;
}

// One CSV field: quoted when it holds a comma, a quote or a line break; a text a spreadsheet
// would take for a formula (=, +, @ first) starts with an apostrophe.
std::string csvField(std::string v) {
    if (!v.empty() && (v[0] == '=' || v[0] == '+' || v[0] == '@')) v.insert(0, 1, '\'');
    if (v.find_first_of(",\"\r\n") == std::string::npos) return v;
    std::string out = "\"";
    for (const char c : v)
        out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

std::string csvOf(const ImportBatch& b) {
    std::string csv = "file,result,job";
    for (const std::string& c : b.columns)
        csv += "," + csvField(c);
    csv += ",reason,report\n";
    for (const ImportBatchRow& r : b.rows) {
        csv +=
            csvField(r.file) + "," + (r.imported ? "imported" : "refused") + "," + csvField(r.job);
        for (const std::string& c : b.columns)
            csv += "," + csvField(ImportBatch::fact(r, c));
        std::string report;
        for (const std::string& l : r.report)
            report += (report.empty() ? "" : " | ") + l;
        csv += "," + csvField(r.reason) + "," + csvField(report) + "\n";
    }
    return csv;
}

} // namespace

std::string ImportBatch::fact(const ImportBatchRow& row, const std::string& column) {
    for (const auto& [k, v] : row.facts)
        if (k == column) return v;
    return {};
}

std::vector<std::string> filesMatching(const JobImporter& importer, const std::string& dir) {
    std::vector<std::string> files;
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
        if (it->is_regular_file(ec) && matches(importer, it->path()))
            files.push_back(it->path().string());
    if (ec) throw JobError("cannot read the folder " + dir + ": " + ec.message());
    std::sort(files.begin(), files.end());
    return files;
}

ImportBatch importBatch(const JobImporter& importer, const std::vector<std::string>& files,
                        const std::string& outDir) {
    std::error_code ec;
    fs::create_directories(outDir, ec);
    if (ec || !fs::is_directory(outDir))
        throw JobError("the folder " + outDir + " cannot be made (" +
                       (ec ? ec.message() : std::string("a file of that name exists")) + ")");
    ImportBatch b;
    std::set<std::string> taken;
    for (const std::string& f : files) {
        ImportBatchRow row;
        row.file = fs::path(f).filename().string();
        try {
            ImportResult r = importer.import(readTextFile(f));
            const std::string job = jobNameFor(f, taken);
            const fs::path target = fs::path(outDir) / job;
            if (fs::exists(target, ec))
                r.report.push_back(job + " of an earlier import in this folder is replaced");
            saveJobFile(r.job, target.string());
            row.job = job;
            row.imported = true;
            row.facts = std::move(r.facts);
            row.report = std::move(r.report);
            for (const auto& [k, v] : row.facts)
                if (std::find(b.columns.begin(), b.columns.end(), k) == b.columns.end())
                    b.columns.push_back(k);
        } catch (const std::exception& e) {
            row.reason = e.what();
            ++b.refused;
        }
        b.rows.push_back(std::move(row));
    }
    b.csv_path = (fs::path(outDir) / "import-report.csv").string();
    writeFileAtomically(b.csv_path, csvOf(b));
    return b;
}

} // namespace cutcell
