#pragma once
// Files that belong together (a plan's files, an export of several files) written as one unit:
// a reader finds either the old set or the new one, never a mix, whenever the writer is killed.
//
//   1. Every file is staged beside its target (".<name>.cutcell-set-<pid>-XXXXXX"), written
//      and flushed to disk. A kill here leaves the old set; the stages are removed later.
//   2. A journal (".cutcell-set-<pid>.journal" in the first file's folder, written atomically)
//      lists stage -> target. From here on the new set is decided.
//   3. Each stage is renamed over its target, then the journal is removed.
// A kill in step 3 (renames only: microseconds) leaves the journal: the next writeFileSet()
// into that folder, or recoverFileSets(), finishes the renames before anything else, so the
// new set becomes whole. Stages and journals of a writer that is still running are left
// alone (its process id is in their names).
#include <string>
#include <vector>

namespace cutcell {

struct FileContents {
    std::string path;
    std::string contents;
};

// Throws JobError naming the file when a stage cannot be written (nothing is replaced then).
void writeFileSet(const std::vector<FileContents>& files);

// A folder's files as one unit, strictly: when `dir` holds nothing but these files (or does not
// exist yet), the set is written into a new sibling folder and exchanged with `dir` in one
// rename (renameat2 RENAME_EXCHANGE): no moment shows a mix, with or without a recovery. A
// folder that holds other files too (`plan --out .`), or a file system without the exchange,
// gets writeFileSet(). Names are plain file names inside `dir`. Returns true when exchanged.
bool writeFolderSet(const std::string& dir, const std::vector<FileContents>& files);

// What recoverFileSets() found in a folder.
struct FileSetRecovery {
    int journals_completed = 0; // sets a killed writer had decided on, renamed into place
    int stages_removed = 0;     // stages of killed writers that never got as far as a journal
    int folders_removed = 0;    // writeFolderSet()'s sibling folders of killed writers
};
// Finishes the sets of killed writers in `dir` and removes their leftover stages.
FileSetRecovery recoverFileSets(const std::string& dir);

} // namespace cutcell
