// Empty on purpose: the translation unit that builds a precompiled header which other test
// targets reuse (cmake/precompiled_headers.cmake).
