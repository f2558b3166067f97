#pragma once
// Internal to the capture judge: the pieces enip_match.cpp, enip_judge.cpp,
// enip_writes.cpp and enip_timeline.cpp share.
#include <optional>
#include <span>
#include <vector>

#include "capture/trace.hpp"
#include "cip/connection_manager.hpp"
#include "verify/enip_capture.hpp"

namespace edsc::verify {

// The devices of the capture, each matched to a file where one describes it.
[[nodiscard]] std::vector<capture_device> find_devices(const capture::tracker& t, std::span<const capture_eds> files);

// The electronic key segment of a Forward_Open's path, if it has one.
[[nodiscard]] std::optional<cip::electronic_key> key_in(const cip::forward_open_request& fo);

// The explicit writes that set a parameter of a matched device to a value
// outside its EDS's limits (capture-write-limits).
[[nodiscard]] std::vector<capture_finding> judge_writes(const capture::tracker& t,
                                                        std::span<const capture_device> devices,
                                                        std::span<const capture_eds> files);

}  // namespace edsc::verify
