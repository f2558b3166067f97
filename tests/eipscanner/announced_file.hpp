#pragma once
// Every class 1 connection `edsc connection FILE --format json` announces,
// opened by EIPScanner on `edsc sim` of the same file (announced_open.hpp),
// except those tests/eipscanner/announced_not_opened.txt lists with the
// reason (announced_not_opened_opener.txt on the generated OpENer device):
// each listed one must still fail, so the list stays true.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "announced.hpp"

namespace edsc::scanner_test {

// The corpus-wide sample (every file in Release, corpus_dirs.hpp) of the
// files with a ConnectionN.
std::vector<std::filesystem::path> files_with_connections();

// `edsc connection FILE --format json`, read back; empty with `error` set
// when edsc fails or the JSON cannot be read.
std::vector<announced_connection> announce(const std::string& file, std::string& error);

// The owner a listen-only connection is opened beside: the first the JSON
// names that has a request; null when none has.
const announced_connection* owner_of(const announced_connection& c, const std::vector<announced_connection>& all);

// "FILE.eds:N" (the file's name without folders) -> why EIPScanner cannot
// open ConnectionN, from the list `name` of tests/eipscanner.
using reviewed = std::map<std::string, std::string>;
reviewed not_opened(const std::string& name = "announced_not_opened.txt");

struct file_outcome {
  std::vector<std::string> failures;  // each names the file and the connection
  unsigned opened = 0, listed = 0;    // connections opened with frames; listed ones that still fail
};

// Opens each class 1 connection with a request in `all`, one after the
// other, at `ip`; `sim_log` is the simulator's event log.
file_outcome open_every_connection(const std::string& file, const std::vector<announced_connection>& all,
                                   const std::string& ip, const std::string& sim_log, const reviewed& listed);

}  // namespace edsc::scanner_test
