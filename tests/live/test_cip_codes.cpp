// The one table of wire codes (cip/codes.def): its names and words, read by
// code, and the places that print them.
#include <gtest/gtest.h>

#include <set>

#include "cip/codes.hpp"
#include "cip/status.hpp"

namespace edsc::cip {
namespace {

// A code listed twice in one table would make one of its names unreachable.
template <class T>
void expect_unique(std::initializer_list<T> codes, const char* table) {
  std::set<T> seen;
  for (const auto c : codes) EXPECT_TRUE(seen.insert(c).second) << table << " lists 0x" << std::hex << +c << " twice";
}

TEST(cip_codes, each_code_once_per_table) {
#define ENIP_COMMAND(sym, code, name) code,
  expect_unique<unsigned>(
      {
#include "cip/codes.def"
      },
      "commands");
#define CPF_ITEM(sym, code, name) code,
  expect_unique<unsigned>(
      {
#include "cip/codes.def"
      },
      "items");
#define CIP_CLASS(sym, code, name) code,
  expect_unique<unsigned>(
      {
#include "cip/codes.def"
      },
      "classes");
#define CIP_SERVICE(sym, code, name) code,
  expect_unique<unsigned>(
      {
#include "cip/codes.def"
      },
      "services");
#define GENERAL_STATUS(sym, code, words, ...) code,
  expect_unique<unsigned>(
      {
#include "cip/codes.def"
      },
      "general statuses");
#define EXTENDED_STATUS(sym, code, words, ...) code,
  expect_unique<unsigned>(
      {
#include "cip/codes.def"
      },
      "extended statuses");
}

TEST(cip_codes, names_and_words_by_code) {
  EXPECT_EQ(name_of(command::send_unit_data), "SendUnitData");
  EXPECT_EQ(name_of(command{0x0099}), "");
  EXPECT_EQ(name_of(item{0x00B2}), "unconnected data");
  EXPECT_EQ(name_of(class_id{0x37}), "File");
  EXPECT_EQ(words_of(general_status::connection_failure), "connection failure");
  EXPECT_EQ(words_of(general_status{0x23}), "");
  EXPECT_EQ(words_of(extended_status{0x0315}), "invalid segment in connection path");
  EXPECT_EQ(code(service::large_forward_open), 0x5B);
}

TEST(cip_codes, a_class_service_is_named_only_with_its_class) {
  EXPECT_EQ(name_of(service{0x0E}), "Get_Attribute_Single");
  EXPECT_EQ(name_of(service{0x4B}), "");
  EXPECT_EQ(name_of(service{0x4B}, class_id::file), "Initiate_Upload");
  EXPECT_EQ(name_of(service{0x4B}, class_id::devicenet), "Allocate_Master/Slave_Connection_Set");
  EXPECT_EQ(name_of(service{0x4B}, class_id::identity), "");
  EXPECT_EQ(name_of(service{0x54}, class_id::connection_manager), "Forward_Open");
}

TEST(cip_codes, identity_status_word_in_words) {
  EXPECT_EQ(describe_identity_status(0x0000), "0x0000 (self-testing or unknown)");
  EXPECT_EQ(describe_identity_status(0x0465),
            "0x0465 (owned, configured, major recoverable fault, at least one I/O connection in run mode)");
  EXPECT_EQ(describe_identity_status(0x00F0), "0x00F0");  // states 8-15 have no words
  EXPECT_EQ(device_state_of(with_device_state(0x0401, device_state::io_idle)), device_state::io_idle);
}

}  // namespace
}  // namespace edsc::cip
