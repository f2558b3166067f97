#pragma once
// EIPScanner (../shared/eipscanner, MIT), a scanner no one on this project
// wrote, talking to a device on a test network. EIPScanner binds UDP 2222
// on every address of its host, so the host's end of the network is a
// namespace of its own (netns/test_network.hpp, scanner_namespace), and the
// test's thread enters it while EIPScanner runs: no other test's scanner is
// there. Only EIPScanner and bytes on the wire are on the test's side.
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ConnectionManager.h"
#include "SessionInfo.h"
#include "cip/connectionManager/NetworkConnectionParametersBuilder.h"
#include "cip/connectionManager/NetworkConnectionParams.h"
#include "netns/test_network.hpp"
#include "sim/sim_wire.hpp"
#include "utils/Logger.h"

namespace edsc::scanner_test {

using eipScanner::cip::connectionManager::ConnectionParameters;
using eipScanner::cip::connectionManager::NetworkConnectionParametersBuilder;
using eipScanner::cip::connectionManager::NetworkConnectionParams;
using sim_test::running_sim;

// This folder's names; /30s shared with tests/sim, the lock files keep them apart.
inline live_test::network_options scanner_net() {
  live_test::network_options o{"edsc-eips-", "ep", 16, 31};
  o.scanner_namespace = true;
  return o;
}

// The networks of the tests that run a generated OpENer device: tests/stack's
// /30s under names of this folder's own, the scanner's end in its own namespace.
inline live_test::network_options opener_net() {
  live_test::network_options o{"edsc-eipstack-", "eq", 32, 62};
  o.scanner_namespace = true;
  return o;
}

// `edsc sim EDS` with the scanner's end in its own namespace.
inline running_sim start_sim(const std::string& eds, const std::vector<std::string>& extra = {},
                             const running_sim::files& written = {}) {
  eipScanner::utils::Logger::setLogLevel(eipScanner::utils::LogLevel::WARNING);
  return running_sim::start(eds, extra, written, scanner_net());
}

// One direction of a class 1 connection as EIPScanner takes it: the data
// size (it adds the sequence count, and the run/idle header where
// `run_idle`), the connection type.
struct direction {
  unsigned data = 0;
  NetworkConnectionParametersBuilder::ConnectionType type = NetworkConnectionParametersBuilder::P2P;
  std::uint32_t rpi_us = 30000;
  bool run_idle = false;
};

// The parameters of a class 1 connection to `path`, in the 16-bit form or,
// when `large`, the 32-bit form of Large_Forward_Open.
inline ConnectionParameters class1(const std::vector<std::uint8_t>& path, const direction& ot, const direction& to,
                                   bool large = false) {
  ConnectionParameters p;
  p.connectionPath = path;
  p.originatorVendorId = 0x0457;
  p.originatorSerialNumber = 0x00EC5CA1;
  p.connectionTimeoutMultiplier = 3;  // x32: a busy machine's late frame closes nothing
  p.o2tRPI = ot.rpi_us;
  p.t2oRPI = to.rpi_us;
  p.o2tRealTimeFormat = ot.run_idle;
  p.t2oRealTimeFormat = to.run_idle;
  p.o2tNetworkConnectionParams =
      NetworkConnectionParametersBuilder(0, large).setConnectionType(ot.type).setConnectionSize(ot.data).build();
  p.t2oNetworkConnectionParams =
      NetworkConnectionParametersBuilder(0, large).setConnectionType(to.type).setConnectionSize(to.data).build();
  p.transportTypeTrigger = NetworkConnectionParams::CLASS1;
  return p;
}

// Frames counted on the scanner's side of one connection.
struct counted {
  std::size_t received = 0, sent = 0;
  std::vector<std::uint8_t> last;  // the data of the last T->O frame
};

// Registers listeners that count on `c`.
inline void count_frames(const eipScanner::IOConnection::WPtr& io, counted& c) {
  if (auto p = io.lock()) {
    p->setReceiveDataListener([&c](auto, auto, const std::vector<std::uint8_t>& data) {
      ++c.received;
      c.last = data;
    });
    p->setSendDataListener([&c](std::vector<std::uint8_t>&) { ++c.sent; });
  }
}

// Runs EIPScanner's connection loop for `how_long` (scaled).
inline void run_io(eipScanner::ConnectionManager& cm, std::chrono::milliseconds how_long) {
  const auto end = std::chrono::steady_clock::now() + how_long;
  while (std::chrono::steady_clock::now() < end && cm.hasOpenConnections())
    cm.handleConnections(std::chrono::milliseconds(2));
}

}  // namespace edsc::scanner_test
