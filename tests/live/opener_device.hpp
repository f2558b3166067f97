#pragma once
// A fixture whose test runs against OpENer (../shared/opener) started in a
// test network of its own (tests/netns/test_network.hpp).
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>

#include "netns/test_network.hpp"
#include "test_paths.hpp"

namespace edsc::live_test {

class opener_device_test : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string why;
    net_ = test_network::make(why);
    if (!net_) GTEST_SKIP() << why;
    if (!std::filesystem::exists(EDSC_OPENER_BINARY))
      GTEST_SKIP() << "OpENer was not built (" << EDSC_OPENER_BINARY << ")";
    ASSERT_TRUE(net_->start_opener(EDSC_OPENER_BINARY, why)) << why;
  }
  [[nodiscard]] std::string device() const { return net_->device_ip; }
  std::unique_ptr<test_network> net_;
};

}  // namespace edsc::live_test
