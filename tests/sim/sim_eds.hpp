#pragma once
// A small EtherNet/IP EDS for the simulator's object tests: [File] (revision
// 1.2) and [Device] (vendor 1, product code 2, revision 1.1), then `body`.
#include <string>
#include <string_view>

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

}  // namespace edsc::sim_test
