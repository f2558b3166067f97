// Where the tests find the sources, the shared corpus, captures and OpENer,
// and the built edsc. The values are compiled once per build folder into
// test_paths.cpp (tests/CMakeLists.txt) rather than passed as -D flags: an
// absolute path on every compile line made each test object differ between two
// clones, so a fresh clone missed the compiler cache for every test file.
#pragma once

namespace edsc::test_paths {
extern const char* const project_dir;
extern const char* const tests_dir;
extern const char* const binary;
extern const char* const shared_dir;
extern const char* const corpus_dir;
extern const char* const corpus_rockwell_dir;
extern const char* const captures_dir;
extern const char* const opener_source_dir;
extern const char* const opener_binary;
extern const char* const eipscanner_library;
extern const char* const cxx_compiler;
extern const char* const stack_build_dir;
extern const char* const install_docdir;
extern const char* const install_datadir;
}  // namespace edsc::test_paths

#define EDSC_PROJECT_DIR (::edsc::test_paths::project_dir)
#define EDSC_TESTS_DIR (::edsc::test_paths::tests_dir)
#define EDSC_BINARY (::edsc::test_paths::binary)
#define EDSC_SHARED_DIR (::edsc::test_paths::shared_dir)
#define EDSC_CORPUS_DIR (::edsc::test_paths::corpus_dir)
#define EDSC_CORPUS_ROCKWELL_DIR (::edsc::test_paths::corpus_rockwell_dir)
#define EDSC_CAPTURES_DIR (::edsc::test_paths::captures_dir)
#define EDSC_OPENER_SOURCE_DIR (::edsc::test_paths::opener_source_dir)
#define EDSC_OPENER_BINARY (::edsc::test_paths::opener_binary)
#define EDSC_EIPSCANNER_LIBRARY (::edsc::test_paths::eipscanner_library)
#define EDSC_CXX_COMPILER (::edsc::test_paths::cxx_compiler)
#define EDSC_STACK_BUILD_DIR (::edsc::test_paths::stack_build_dir)
#define EDSC_INSTALL_DOCDIR (::edsc::test_paths::install_docdir)
#define EDSC_INSTALL_DATADIR (::edsc::test_paths::install_datadir)
