// The program a user of `edsc connection --format eipscanner` writes,
// compiled by eipscanner_generated_run.* against the generated header, conn.hpp, and
// pick.hpp, which that test writes: `pick(n, params, large)` calls the
// header's connectionN() and connectionN_large, false for an N it lacks.
//
//   driver IP N OWNER T2O_BYTES WAIT_MS
//
// opens ConnectionN at IP (after ConnectionOWNER unless OWNER is 0), sends
// O->T data 0xA0, 0xA1, ... of the size the header's O->T parameters carry,
// runs I/O until three frames went each way or WAIT_MS passed, closes what
// it opened and says so on one line. Exit status: 0 opened and T->O frames
// of T2O_BYTES data arrived; 2 usage; 3 the owner refused; 4 ConnectionN
// refused; 5 fewer than two T->O frames; 6 a T->O frame of another size;
// 7 EIPScanner threw.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include "ConnectionManager.h"
#include "SessionInfo.h"
#include "pick.hpp"
#include "utils/Logger.h"

namespace {

using edsc_connections::ConnectionParameters;
using eipScanner::ConnectionManager;
using eipScanner::IOConnection;
using eipScanner::SessionInfo;

struct frames {
  std::size_t received = 0, sent = 0, other_size = 0, last_other = 0;
};

// ConnectionN opened with the scanner's own originator, its data set; expired when refused.
IOConnection::WPtr open(ConnectionManager& cm, const std::shared_ptr<SessionInfo>& si, unsigned n) {
  ConnectionParameters p;
  bool large = false;
  if (!pick(n, p, large)) return {};
  p.originatorVendorId = 0x0457;
  p.originatorSerialNumber = 0x00EC5CA2;
  auto io = cm.forwardOpen(si, p, large);
  if (auto c = io.lock()) {
    // The data size is the parameter word's size field (9 bits, or 16 of the large form).
    const auto size = large ? p.o2tNetworkConnectionParams & 0xFFFF : p.o2tNetworkConnectionParams & 0x1FF;
    std::vector<std::uint8_t> data(size);
    for (std::size_t i = 0; i < data.size(); ++i) data[i] = static_cast<std::uint8_t>(0xA0 + i);
    c->setDataToSend(data);
  }
  return io;
}

void count(const IOConnection::WPtr& io, frames& f, std::size_t t2o_bytes) {
  auto c = io.lock();
  if (!c) return;
  c->setReceiveDataListener([&f, t2o_bytes](auto, auto, const std::vector<std::uint8_t>& data) {
    ++f.received;
    if (data.size() != t2o_bytes) ++f.other_size, f.last_other = data.size();
  });
  c->setSendDataListener([&f](std::vector<std::uint8_t>&) { ++f.sent; });
}

int run(const std::string& ip, unsigned n, unsigned owner, std::size_t t2o_bytes, std::chrono::milliseconds wait) {
  const auto si = std::make_shared<SessionInfo>(ip, 0xAF12, std::chrono::milliseconds(3000));
  ConnectionManager cm;
  IOConnection::WPtr first;
  if (owner != 0 && (first = open(cm, si, owner)).expired()) return std::printf("Connection%u refused\n", owner), 3;
  const auto io = open(cm, si, n);
  if (io.expired()) {
    if (owner != 0) cm.forwardClose(si, first);
    return std::printf("Connection%u refused\n", n), 4;
  }
  frames f;
  count(io, f, t2o_bytes);
  const auto end = std::chrono::steady_clock::now() + wait;
  while (std::chrono::steady_clock::now() < end && cm.hasOpenConnections() && (f.received < 3 || f.sent < 3))
    cm.handleConnections(std::chrono::milliseconds(2));
  cm.forwardClose(si, io);
  if (owner != 0) cm.forwardClose(si, first);
  std::printf("Connection%u: %zu T->O frames, %zu O->T\n", n, f.received, f.sent);
  if (f.received < 2) return 5;
  if (f.other_size > 0) return std::printf("%zu T->O frames of %zu bytes\n", f.other_size, f.last_other), 6;
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 6) return std::fprintf(stderr, "usage: driver IP N OWNER T2O_BYTES WAIT_MS\n"), 2;
  eipScanner::utils::Logger::setLogLevel(eipScanner::utils::LogLevel::WARNING);
  try {
    return run(argv[1], unsigned(std::atoi(argv[2])), unsigned(std::atoi(argv[3])), std::size_t(std::atoi(argv[4])),
               std::chrono::milliseconds(std::atoi(argv[5])));
  } catch (const std::exception& e) {
    std::printf("EIPScanner: %s\n", e.what());
    return 7;
  }
}
