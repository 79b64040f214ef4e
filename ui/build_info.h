#pragma once
// What this binary was built from: written at every build by cmake/build_info.cmake (the
// source file changes only when the commit does), so Help -> About never shows a stale commit.
namespace CutCell::ui {

const char* buildCommit();     // `git describe --always --dirty`, or "unknown"
const char* buildCommitDate(); // the commit's date (YYYY-MM-DD), or "unknown"
const char* buildType();       // CMAKE_BUILD_TYPE
const char* buildCompiler();   // compiler id and version

} // namespace CutCell::ui
