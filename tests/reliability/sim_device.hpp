#pragma once
// A device on loopback for the commands that need one to write (probe
// --upload-eds): the simulator's own request handling (sim/state.hpp) behind a
// TCP server on a port the system picks, serving one EDS. No fixed port, no
// UDP, nothing but 127.0.0.1.
#include <memory>
#include <mutex>
#include <string>

#include "edit/analyze.hpp"
#include "live/loopback_server.hpp"
#include "sim/state.hpp"

namespace edsc::reliability_test {

class sim_device {
 public:
  explicit sim_device(const std::string& eds_text) {
    const auto a = edit::analyze("device.eds", eds_text);
    state_.dev = sim::build_device(a->dev, 1);
    state_.dev.file.content.assign(eds_text.begin(), eds_text.end());
    state_.dev.file.name = "device.eds";
    server_ = std::make_unique<live_test::loopback_server>([this](int conn, const std::atomic<bool>& stop) {
      sim::link l;
      l.peer_ip = 0x0100007F;
      for (;;) {
        const auto msg = live_test::read_message(conn, stop);
        if (msg.size() < cip::encap_header_size) return;
        const std::lock_guard lock(mutex_);
        const auto out = sim::handle_encap(state_, l, msg, true, sim::clock::now());
        if (out.reply) live_test::send_bytes(conn, *out.reply);
        if (out.close) return;
      }
    });
  }
  // HOST:PORT, as probe takes it.
  [[nodiscard]] std::string address() const { return server_->address(); }

 private:
  std::mutex mutex_;
  sim::state state_;
  std::unique_ptr<live_test::loopback_server> server_;
};

}  // namespace edsc::reliability_test
