#pragma once
// Shared by the `edsc doc` tests: datasheets of in-memory EDS text, and the
// inputs the browser tests render.
#include <memory>
#include <string>
#include <vector>

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

inline std::unique_ptr<analysis> analyse_file(const fs::path& p) { return analyse(test::read_text(p), p.string()); }

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

// File names a library may hold that a link must carry as they are: URL
// syntax (# ? % & : \\), HTML syntax (quotes, <), spaces and line breaks,
// UTF-8, a Latin-1 byte that is not UTF-8, a leading '-'.
inline const std::vector<std::string> awkward_names{
    "d\xC3\xA9v #1?.eds", "two words.eds", "hash#.eds",       "query?x=1.eds",  "percent%41.eds", "amp&amp;.eds",
    "quote\".eds",        "apos'.eds",     "lt<gt>.eds",      "latin\xE9.eds",  "-leading.eds",   "new\nline.eds",
    "tab\tbed.eds",       "colon:x.eds",   "back\\slash.eds", "plus+semi;.eds", "[brackets].eds", "%2Fslash.eds",
};

// A small valid EDS whose product name tells its page apart.
inline std::string named_eds(const std::string& product) {
  return "[File]\nDescText = \"x\";\nCreateDate = 01-01-2020;\nCreateTime = 00:00:00;\nRevision = 1.0;\n"
         "[Device]\nVendCode = 65535;\nVendName = \"edsc-example\";\nProdType = 100;\n"
         "ProdTypeStr = \"Vendor Specific\";\nProdCode = 1;\nMajRev = 1;\nMinRev = 1;\nProdName = \"" +
         product + "\";\n";
}

// `awkward_names` in `dir`, the i-th with the product name "Page i".
inline void write_awkward_library(const fs::path& dir) {
  fs::create_directories(dir);
  for (std::size_t i = 0; i < awkward_names.size(); ++i)
    test::write_text(dir / awkward_names[i], named_eds("Page " + std::to_string(i)));
}

}  // namespace edsc::doc_test
