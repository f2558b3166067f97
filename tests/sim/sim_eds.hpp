#pragma once
// EDS text for the simulator's tests: a small EtherNet/IP EDS ([File]
// revision 1.2, [Device] vendor 1, product code 2, revision 1.1, then
// `body`), and a file of the corpora analysed as the simulator reads it.
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <string_view>

#include "edit/analyze.hpp"

namespace edsc::sim_test {

inline std::string small_eds(std::string_view body) {
  return std::string(R"eds([File]
DescText = "simulator objects";
CreateDate = 01-01-2020;
CreateTime = 00:00:00;
Revision = 1.2;

[Device]
VendCode = 1;
VendName = "edsc";
ProdType = 12;
ProdTypeStr = "Communications Adapter";
ProdCode = 2;
MajRev = 1;
MinRev = 1;
ProdName = "simulator objects";
Catalog = "s";

)eds") + std::string(body);
}

// A file (OpENer's EDS, a corpus file) read and analysed; the analysis holds the text.
inline std::unique_ptr<analysis> analyze_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return edit::analyze(path, text.str());
}

}  // namespace edsc::sim_test
