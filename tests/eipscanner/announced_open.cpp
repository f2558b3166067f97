#include "announced_open.hpp"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <regex>
#include <sstream>
#include <thread>

#include "ConnectionManager.h"
#include "SessionInfo.h"
#include "time_scale.hpp"

namespace edsc::scanner_test {

namespace {

using namespace std::chrono_literals;
using eipScanner::ConnectionManager;
using eipScanner::IOConnection;
using eipScanner::SessionInfo;

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The last line of `log` holding `needle`, or "".
std::string last_line_with(const std::string& log, const std::string& needle) {
  const auto at = log.rfind(needle);
  if (at == std::string::npos) return {};
  const auto begin = log.rfind('\n', at);
  const auto from = begin == std::string::npos ? 0 : begin + 1;
  return log.substr(from, log.find('\n', at) - from);
}

// The serial and the ConnectionN of the last connection the simulator
// opened (-1 and 0 when none). Several ConnectionN may share one path and
// sizes (an input-only and a listen-only connection of the same point): the
// simulator names the first that fits, so the number can differ from the
// one asked for; its checks of the sizes are the same.
std::pair<long, unsigned> last_open(const std::string& log) {
  const std::regex open(R"(\{"event":"open","serial":([0-9]+),[^\n]*"connection":([0-9]+),)");
  std::pair<long, unsigned> last{-1, 0};
  for (std::sregex_iterator it(log.begin(), log.end(), open), e; it != e; ++it)
    last = {std::stol((*it)[1]), static_cast<unsigned>(std::stoul((*it)[2]))};
  return last;
}

// "consumed" of the close line of `serial`, or -1 while there is none.
long consumed_of(const std::string& log, long serial) {
  const std::regex close("\\{\"event\":\"close\",\"serial\":" + std::to_string(serial) +
                         ",[^\\n]*\"consumed\":([0-9]+)");
  std::smatch m;
  return std::regex_search(log, m, close) ? std::stol(m[1]) : -1;
}

// The data of the first `output` line of ConnectionN, or "" when none.
std::string output_of(const std::string& log, unsigned number) {
  const std::regex output("\\{\"event\":\"output\",\"instance\":[0-9]+,\"connection\":" + std::to_string(number) +
                          ",[^\\n]*\"data\":\"([0-9a-f]*)\"");
  std::smatch m;
  return std::regex_search(log, m, output) ? std::string(m[1]) : std::string();
}

bytes pattern(std::size_t n) {
  bytes b(n);
  for (std::size_t i = 0; i < n; ++i) b[i] = static_cast<std::uint8_t>(0xA0 + i);
  return b;
}

std::string hex(const bytes& b) {
  static const char* digits = "0123456789abcdef";
  std::string s;
  for (const auto x : b) s += {digits[x >> 4], digits[x & 15]};
  return s;
}

// Frames seen on EIPScanner's side; T->O frames of another data size counted apart.
struct frames {
  std::size_t received = 0, sent = 0, wrong = 0, wrong_size = 0;
};

IOConnection::WPtr open_one(ConnectionManager& cm, const std::shared_ptr<SessionInfo>& si,
                            const announced_connection& c, std::string& failure) {
  const auto s = scanner_parameters(c);
  if (!s.cannot.empty()) {
    failure = "EIPScanner cannot express Connection" + std::to_string(c.number) + ": " + s.cannot;
    return {};
  }
  auto io = cm.forwardOpen(si, s.params, c.large);
  if (auto p = io.lock()) p->setDataToSend(pattern(c.ot.data_size));
  return io;
}

void count(const IOConnection::WPtr& io, frames& f, unsigned data_size) {
  auto p = io.lock();
  if (!p) return;
  p->setReceiveDataListener([&f, data_size](auto, auto, const std::vector<std::uint8_t>& data) {
    ++f.received;
    if (data.size() != data_size) ++f.wrong, f.wrong_size = data.size();
  });
  p->setSendDataListener([&f](std::vector<std::uint8_t>&) { ++f.sent; });
}

// I/O until three frames went each way the connection uses (at most a
// second and five RPIs, scaled: a loaded machine's late first frame is no
// failure, and the frames end the wait long before).
void run_until_frames(ConnectionManager& cm, const announced_connection& c, const frames& f) {
  const auto rpi = std::chrono::microseconds(std::max(c.ot.rpi_us, c.to.rpi_us));
  const auto end = std::chrono::steady_clock::now() + test_time::scaled(1000ms + 5 * rpi);
  while (std::chrono::steady_clock::now() < end && cm.hasOpenConnections()) {
    if (f.received >= 3 && (f.sent >= 3 || !c.ot.used)) break;
    cm.handleConnections(2ms);
  }
}

// The log once the close line of the last connection opened is in it (at most 5 s, scaled).
std::string log_after_close(const std::string& path, std::pair<long, unsigned>& opened) {
  std::string log;
  for (int i = 0; i < 250 * test_time::scale; ++i) {
    log = read_file(path);
    opened = last_open(log);
    if (opened.first >= 0 && consumed_of(log, opened.first) >= 0) break;
    std::this_thread::sleep_for(20ms);
  }
  return log;
}

}  // namespace

std::string simulator_took(const std::string& path, const announced_connection& c) {
  std::pair<long, unsigned> opened;
  const auto log = log_after_close(path, opened);
  const auto [serial, number] = opened;
  const auto tag = "Connection" + std::to_string(c.number) + ": ";
  if (serial < 0) return tag + "no open line in the simulator's log";
  const auto wrong = last_line_with(log, "{\"event\":\"wrong-size\",\"connection\":" + std::to_string(number) + ",");
  if (!wrong.empty()) return tag + "the simulator took O->T frames for the wrong size: " + wrong;
  const auto consumed = consumed_of(log, serial);
  if (consumed < 0) return tag + "no close line in the simulator's log";
  if (c.ot.used && consumed < 1) return tag + "the simulator consumed no O->T frame";
  if (c.ot.data_size > 0 && output_of(log, number) != hex(pattern(c.ot.data_size)))
    return tag + "the simulator logged O->T data \"" + output_of(log, number) + "\", sent " +
           hex(pattern(c.ot.data_size));
  return {};
}

namespace {

// Opens `c` (after `owner`), runs I/O and closes; the failure or "".
std::string open_run_close(const std::string& ip, const announced_connection& c, const announced_connection* owner,
                           frames& f) {
  const auto si = std::make_shared<SessionInfo>(ip, 0xAF12, std::chrono::milliseconds(test_time::scaled(3000)));
  ConnectionManager cm;
  std::string failure;
  IOConnection::WPtr first;
  if (owner != nullptr) {
    first = open_one(cm, si, *owner, failure);
    if (first.expired())
      return failure.empty() ? "its owner Connection" + std::to_string(owner->number) + " is refused" : failure;
  }
  auto io = open_one(cm, si, c, failure);
  if (io.expired()) {
    if (owner != nullptr) cm.forwardClose(si, first);
    return failure.empty() ? "Connection" + std::to_string(c.number) + " is refused" : failure;
  }
  count(io, f, c.to.data_size);
  run_until_frames(cm, c, f);
  cm.forwardClose(si, io);
  if (owner != nullptr) cm.forwardClose(si, first);
  return {};
}

}  // namespace

open_outcome open_announced(const std::string& ip, const announced_connection& c, const announced_connection* owner,
                            const std::string& sim_log) {
  open_outcome out;
  frames f;
  try {
    out.failure = open_run_close(ip, c, owner, f);
  } catch (const std::exception& e) {
    out.failure = std::string("EIPScanner: ") + e.what();
  }
  out.received = f.received;
  out.sent = f.sent;
  const auto tag = "Connection" + std::to_string(c.number) + ": ";
  if (!out.failure.empty()) {
    const auto refused = last_line_with(read_file(sim_log), "\"event\":\"refused\"");
    if (!refused.empty()) out.failure += "; the simulator's last refusal: " + refused;
  } else if (f.received < 2) {
    out.failure = tag + std::to_string(f.received) + " T->O frames arrived in a second and five RPIs";
  } else if (f.wrong > 0) {
    out.failure = tag + std::to_string(f.wrong) + " T->O frames of " + std::to_string(f.wrong_size) +
                  " data bytes, announced " + std::to_string(c.to.data_size);
  } else if (!sim_log.empty()) {
    out.failure = simulator_took(sim_log, c);
  }
  return out;
}

}  // namespace edsc::scanner_test
