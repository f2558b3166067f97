#pragma once
// An EtherNet/IP capture judged against EDS files (docs/capture.md): each
// device the capture shows matched to an EDS by its identity or by the
// electronic key of its Forward_Opens, then each connection held against the
// ConnectionN its path selects (connections::check_fit, the simulator's own
// checks), its I/O against what was granted, and each write of a ParamN
// against the parameter's limits. Findings are diagnostics at the EDS field,
// with the capture's frame numbers (as Wireshark numbers them) in the words.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "capture/trace.hpp"
#include "diag/diagnostic.hpp"
#include "model/device.hpp"
#include "source/source_file.hpp"

namespace edsc::verify {

struct capture_eds {
  const model::device* dev = nullptr;
  const source_file* src = nullptr;
};

enum class matched_by : std::uint8_t { none, identity, key, only_file };

// One address the capture shows as a target (it answered ListIdentity or
// the Identity object, or was sent a Forward_Open).
struct capture_device {
  std::uint32_t address = 0;
  std::optional<cip::identity> identity;
  std::uint64_t identity_frame = 0;
  std::optional<std::size_t> eds;  // index into the EDS files
  matched_by how = matched_by::none;
  std::vector<std::size_t> connections;  // indices into tracker::connections()
};

// What one connection came to, for the timeline and the JSON report.
struct connection_verdict {
  std::size_t index = 0;               // into tracker::connections()
  std::optional<std::uint32_t> point;  // N of the ConnectionN its path selects
  std::string outcome;                 // "open", "refused 0x01/0x0127", "no reply"
  std::string fit;                     // why the EDS's ConnectionN does not take it; empty: it does
  std::string keying;                  // the electronic key and its verdict against [Device]; empty: no key
  // The ConnectionN's formats carry the run/idle header: the bit the tracker
  // follows means run or idle only then.
  bool ot_run_idle = false, to_run_idle = false;
};

struct capture_finding {
  std::size_t eds = 0;  // the file it is located in
  diagnostic d;
};

struct capture_verdict {
  std::vector<capture_device> devices;
  std::vector<connection_verdict> connections;
  std::vector<capture_finding> findings;
};

[[nodiscard]] capture_verdict judge_capture(const capture::tracker& t, std::span<const capture_eds> files);

// The per-device, per-connection timeline (text output).
[[nodiscard]] std::string render_timeline(const capture::tracker& t, const capture_verdict& v,
                                          std::span<const std::string> file_names);

// Dotted-quad text of a host-order IPv4 address.
[[nodiscard]] std::string address_text(std::uint32_t address);

}  // namespace edsc::verify
