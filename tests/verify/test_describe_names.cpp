// The words the --decode table and the findings use for services and
// statuses: those of the one code table, the class deciding what a
// class-specific service code means.
#include <gtest/gtest.h>

#include "verify/decode.hpp"

namespace {

using edsc::verify::service_name;
using edsc::verify::status_name;

TEST(VerifyDescribe, ClassSpecificServiceNamedByItsClass) {
  EXPECT_EQ(service_name(0x4B, 0x03), "Allocate_Master/Slave_Connection_Set");
  EXPECT_EQ(service_name(0x4C, 0x03), "Release_Group_2_Identifier_Set");
  EXPECT_EQ(service_name(0x4B, 0x01), "service 0x4B");  // not the DeviceNet object's service
  EXPECT_EQ(service_name(0x0E, 0x05), "Get_Attribute_Single");
  EXPECT_EQ(service_name(0x7E, 0x01), "service 0x7E");
}

TEST(VerifyDescribe, GeneralStatusInWordsWithItsCode) {
  EXPECT_EQ(status_name(0x00), "success");
  EXPECT_EQ(status_name(0x14), "attribute not supported (0x14)");
  EXPECT_EQ(status_name(0x0B), "already in requested mode/state (0x0B)");
  EXPECT_EQ(status_name(0x23), "general status 0x23");
}

}  // namespace
