#include "core/job/file_set.h"
#include "core/job/job_io.h"

#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

namespace cutcell {

namespace fs = std::filesystem;

namespace {

constexpr const char* kStageTag = ".cutcell-set-";      // in a stage's name
constexpr const char* kJournalPrefix = ".cutcell-set-"; // a journal's name begins so
constexpr const char* kJournalSuffix = ".journal";
constexpr const char* kJournalHeader = "cutcell file set 1";

// A process that wrote a stage or a journal and is gone (this process is a later one that got
// the same id: it has written nothing yet when it recovers).
bool writerGone(long pid) {
    if (pid <= 0) return false;
    if (pid == static_cast<long>(::getpid())) return true;
    return ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
}

// The writer's process id in "<...><tag><pid><end>", or -1.
long pidAfter(const std::string& name, size_t from, size_t to) {
    if (from >= to || to > name.size()) return -1;
    long pid = 0;
    for (size_t i = from; i < to; ++i) {
        if (name[i] < '0' || name[i] > '9' || pid > 100000000) return -1;
        pid = pid * 10 + (name[i] - '0');
    }
    return pid;
}

// ".cutcell-set-<pid>.journal" -> pid, else -1.
long journalPid(const std::string& n) {
    const std::string pre = kJournalPrefix, suf = kJournalSuffix;
    if (n.size() <= pre.size() + suf.size() || n.compare(0, pre.size(), pre) != 0 ||
        n.compare(n.size() - suf.size(), suf.size(), suf) != 0)
        return -1;
    return pidAfter(n, pre.size(), n.size() - suf.size());
}

bool alnumTail(const std::string& n) { // the last 6 characters are mkstemp's
    for (size_t i = n.size() - 6; i < n.size(); ++i)
        if (!std::isalnum(static_cast<unsigned char>(n[i]))) return false;
    return true;
}

// A stage ".<name>.cutcell-set-<pid>-XXXXXX", or a journal being written (writeFileAtomically's
// temporary "..cutcell-set-<pid>.journal.XXXXXX") -> pid, else -1.
long leftoverPid(const std::string& n) {
    if (n.size() < 8 || n[0] != '.' || !alnumTail(n)) return -1;
    const std::string journalTail = std::string(kJournalSuffix) + ".";
    if (n[n.size() - 7] == '.') { // a journal's temporary file
        const std::string pre = std::string(".") + kJournalPrefix;
        if (n.compare(0, pre.size(), pre) != 0 || n.size() < pre.size() + journalTail.size() + 6)
            return -1;
        const size_t end = n.size() - 6 - journalTail.size();
        if (n.compare(end, journalTail.size(), journalTail) != 0) return -1;
        return pidAfter(n, pre.size(), end);
    }
    if (n[n.size() - 7] != '-') return -1;
    const size_t tag = n.rfind(kStageTag);
    if (tag == std::string::npos || tag == 0) return -1;
    return pidAfter(n, tag + std::strlen(kStageTag), n.size() - 7);
}

// writeFolderSet()'s sibling ".<dir>.cutcell-folder-<pid>-XXXXXX" -> pid, else -1.
constexpr const char* kFolderTag = ".cutcell-folder-";
long folderPid(const std::string& n) {
    if (n.size() < 8 || n[0] != '.' || !alnumTail(n) || n[n.size() - 7] != '-') return -1;
    const size_t tag = n.rfind(kFolderTag);
    if (tag == std::string::npos || tag == 0) return -1;
    return pidAfter(n, tag + std::strlen(kFolderTag), n.size() - 7);
}

// Removes the sibling folders of killed writeFolderSet() calls beside `dir`: before its
// exchange one holds an unfinished new set, after it the old set.
int removeDeadFolders(const fs::path& dir) {
    const fs::path parent = dir.has_parent_path() ? dir.parent_path() : fs::path(".");
    const std::string prefix = "." + dir.filename().string() + kFolderTag;
    int removed = 0;
    std::error_code ec;
    std::vector<fs::path> dead;
    for (fs::directory_iterator it(parent, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string n = it->path().filename().string();
        std::error_code e2;
        if (n.compare(0, prefix.size(), prefix) != 0 || it->is_symlink(e2) || !it->is_directory(e2))
            continue;
        if (const long pid = folderPid(n); pid > 0 && writerGone(pid)) dead.push_back(it->path());
    }
    for (const fs::path& p : dead) {
        std::error_code e2;
        if (fs::remove_all(p, e2) > 0) ++removed;
    }
    return removed;
}

[[noreturn]] void fail(const std::string& what, const std::string& path, int err) {
    throw JobError(what + " " + path + ": " + std::strerror(err));
}

// Writes `contents` beside `target` under a stage name, on disk when it returns.
std::string stage(const fs::path& target, const std::string& contents) {
    const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
    const std::string tmpl = (dir / ("." + target.filename().string() + kStageTag +
                                     std::to_string(::getpid()) + "-XXXXXX"))
                                 .string();
    return writeTemporaryFile(tmpl, target.string(), contents);
}

// Renames every stage a journal lists over its target; true when the journal was complete.
// Only what its writer staged: a stage of that process beside its target, named for it (a
// journal someone else wrote renames nothing else).
bool completeJournal(const fs::path& journal, long pid) {
    std::ifstream in(journal);
    std::string line;
    if (!std::getline(in, line) || line != kJournalHeader) return false;
    while (std::getline(in, line)) {
        const size_t tab = line.find('\t');
        if (tab == std::string::npos) continue;
        const fs::path from = line.substr(0, tab), to = line.substr(tab + 1);
        const std::string stageName = from.filename().string();
        const std::string ownName = "." + to.filename().string() + kStageTag;
        if (from.parent_path() != to.parent_path() || leftoverPid(stageName) != pid ||
            stageName.compare(0, ownName.size(), ownName) != 0)
            continue;
        std::error_code ec;
        if (fs::exists(from, ec)) fs::rename(from, to, ec); // absent: renamed before the kill
    }
    return true;
}

} // namespace

FileSetRecovery recoverFileSets(const std::string& dirName) {
    FileSetRecovery r;
    const fs::path dir = dirName.empty() ? fs::path(".") : fs::path(dirName);
    std::error_code ec;
    // Journals first: their stages are the decided new set, not leftovers.
    std::vector<fs::path> journals, leftovers;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        std::error_code e2;
        if (!it->is_regular_file(e2) || it->is_symlink(e2)) continue;
        const std::string n = it->path().filename().string();
        if (const long pid = journalPid(n); pid > 0) {
            if (writerGone(pid)) journals.push_back(it->path());
        } else if (const long owner = leftoverPid(n); owner > 0 && writerGone(owner)) {
            leftovers.push_back(it->path());
        }
    }
    for (const fs::path& j : journals) {
        completeJournal(j, journalPid(j.filename().string()));
        std::error_code e2;
        fs::remove(j, e2);
        ++r.journals_completed;
    }
    for (const fs::path& p : leftovers) {
        std::error_code e2;
        if (fs::remove(p, e2)) ++r.stages_removed; // gone already: a journal renamed it
    }
    r.folders_removed = removeDeadFolders(dir);
    return r;
}

void writeFileSet(const std::vector<FileContents>& files) {
    if (files.empty()) return;
    std::set<fs::path> dirs;
    for (const FileContents& f : files) {
        if (f.path.find_first_of("\t\n") != std::string::npos)
            throw JobError("cannot write " + f.path + ": the name holds a tab or a line break");
        const fs::path p(f.path);
        dirs.insert(p.has_parent_path() ? p.parent_path() : fs::path("."));
    }
    // What a killed writer left here is finished (or removed) before this set is staged.
    for (const fs::path& d : dirs)
        recoverFileSets(d.string());
    std::vector<std::string> staged;
    try {
        for (const FileContents& f : files)
            staged.push_back(stage(fs::path(f.path), f.contents));
    } catch (...) {
        for (const std::string& s : staged)
            ::unlink(s.c_str());
        throw;
    }
    if (files.size() == 1) { // one rename is atomic by itself
        if (std::rename(staged[0].c_str(), files[0].path.c_str()) != 0) {
            const int err = errno;
            ::unlink(staged[0].c_str());
            fail("cannot replace", files[0].path, err);
        }
        return;
    }
    // The journal decides the new set: written (atomically) only once every stage is on disk.
    std::ostringstream text;
    text << kJournalHeader << '\n';
    for (size_t i = 0; i < files.size(); ++i)
        text << fs::absolute(staged[i]).string() << '\t' << fs::absolute(files[i].path).string()
             << '\n';
    const fs::path first(files.front().path);
    const fs::path journal =
        (first.has_parent_path() ? first.parent_path() : fs::path(".")) /
        (std::string(kJournalPrefix) + std::to_string(::getpid()) + kJournalSuffix);
    try {
        writeFileAtomically(journal.string(), text.str());
    } catch (...) {
        for (const std::string& s : staged)
            ::unlink(s.c_str());
        throw;
    }
    for (size_t i = 0; i < files.size(); ++i)
        if (std::rename(staged[i].c_str(), files[i].path.c_str()) != 0) {
            // The set is decided: the journal stays for the next run to finish it.
            fail("cannot replace", files[i].path, errno);
        }
    ::unlink(journal.c_str());
}

} // namespace cutcell

namespace cutcell {

bool writeFolderSet(const std::string& dirName, const std::vector<FileContents>& files) {
    fs::path dir = fs::path(dirName).lexically_normal();
    if (dir.filename().empty()) dir = dir.parent_path(); // "out/" -> "out"
    std::vector<FileContents> inDir;
    std::set<std::string> names;
    for (const FileContents& f : files) {
        inDir.push_back({(dir / f.path).string(), f.contents});
        names.insert(f.path);
    }
    std::error_code ec;
    removeDeadFolders(dir);
    const bool exists = fs::exists(dir, ec);
    bool onlyOurs = !dir.filename().empty() && dir.filename() != "." && dir.filename() != "..";
    if (exists && onlyOurs) {
        if (!fs::is_directory(dir, ec) || fs::is_symlink(dir, ec)) onlyOurs = false;
        for (fs::directory_iterator it(dir, ec), end; onlyOurs && !ec && it != end;
             it.increment(ec)) {
            std::error_code e2;
            onlyOurs = names.count(it->path().filename().string()) > 0 && it->is_regular_file(e2) &&
                       !it->is_symlink(e2);
        }
        onlyOurs = onlyOurs && !ec;
    }
    if (!onlyOurs) {
        if (!exists) fs::create_directories(dir);
        writeFileSet(inDir);
        return false;
    }
    const fs::path parent = dir.has_parent_path() ? dir.parent_path() : fs::path(".");
    std::string tmpl = (parent / ("." + dir.filename().string() + kFolderTag +
                                  std::to_string(::getpid()) + "-XXXXXX"))
                           .string();
    if (!::mkdtemp(tmpl.data())) fail("cannot write", dir.string(), errno);
    ::chmod(tmpl.c_str(), 0755);
    try {
        for (const FileContents& f : files) {
            const std::string staged = stage(fs::path(tmpl) / f.path, f.contents);
            if (std::rename(staged.c_str(), (fs::path(tmpl) / f.path).c_str()) != 0)
                fail("cannot write", (dir / f.path).string(), errno);
        }
    } catch (...) {
        fs::remove_all(tmpl, ec);
        throw;
    }
    // The one step that shows the new set: a rename (new folder) or an exchange (old folder).
    const int done =
        exists ? ::renameat2(AT_FDCWD, tmpl.c_str(), AT_FDCWD, dir.c_str(), RENAME_EXCHANGE)
               : ::rename(tmpl.c_str(), dir.c_str());
    if (done != 0) {
        const int err = errno;
        fs::remove_all(tmpl, ec);
        if (exists && (err == EINVAL || err == ENOSYS || err == EXDEV)) {
            writeFileSet(inDir); // no exchange on this file system
            return false;
        }
        fail("cannot replace", dir.string(), err);
    }
    fs::remove_all(tmpl, ec); // the old set (nothing when the folder was new)
    return true;
}

} // namespace cutcell
