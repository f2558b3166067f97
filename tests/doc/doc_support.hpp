#pragma once
// Shared by the `edsc doc` tests: datasheets of in-memory EDS text, and the
// inputs the browser tests render.
#include <memory>
#include <string>

#include "check/check_file.hpp"
#include "doc/render.hpp"
#include "emit/emit_support.hpp"
#include "test_paths.hpp"

namespace edsc::doc_test {

namespace fs = std::filesystem;

inline const fs::path project = EDSC_PROJECT_DIR;
inline const fs::path corpus = EDSC_CORPUS_DIR;
inline const fs::path rockwell = fs::path(EDSC_CORPUS_DIR).parent_path() / "eds-corpus-rockwell";

inline std::unique_ptr<analysis> analyse(const std::string& text, const std::string& name = "device.eds") {
  return analyze(std::make_unique<source_file>(name, text), check_options{});
}

inline std::unique_ptr<analysis> analyse_file(const fs::path& p) {
  return analyse(test::read_text(p), p.string());
}

// A small EtherNet/IP device whose strings try to be markup.
inline constexpr const char* hostile_eds = R"([File]
    DescText = "a & b";
    CreateDate = 01-02-2020;
    CreateTime = 10:00:00;
    Revision = 1.0;
[Device]
    VendCode = 65535;
    VendName = "Acme \"Quotes\" & 'Apostrophes'";
    ProdType = 12;
    ProdTypeStr = "Communications Adapter";
    ProdCode = 7;
    MajRev = 2;
    MinRev = 3;
    ProdName = "<script>alert(1)</script>";
    Catalog = "<b>bold</b>";
[Device Classification]
    Class1 = EtherNetIP;
[Params]
    Param1 = 0, "", "", 0x0014, 0xC7, 2, "Speed <rpm>", "rpm", "help & \"more\"",
             0, 1000, 10, , , , , , , , , ;
    Param2 = 0, "", "", 0x0000, 0xC1, 1, "Run|Stop", "", "", 0, 1, 0, , , , , , , , , ;
    Enum2 = 0, "Stop <now>", 1, "Run";
    Param3 = 0, "", "", 0x0004, 0xC6, 1, "Address", "", "", 64, 95, 70, 1, 1, 1, -63, , , , , 0;
[Assembly]
    Assem100 = "Inputs <1>", "20 04 24 64 30 03", 4, 0x0000, , ,
        16, Param1,
        1, Param2,
        7, ,
        8, Param3;
[Connection Manager]
    Connection1 = 0x84010002, 0x44640405, 10000, , Assem100, 20000, , Assem100, , , , ,
        "Exclusive <Owner>", "", "20 04 24 01 2C 64 2C 64";
)";

}  // namespace edsc::doc_test
