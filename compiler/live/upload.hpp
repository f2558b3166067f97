#pragma once
// "Upload EDS from device": the file a device keeps in its File object
// (class 0x37, instance 0xC8 by convention), read by Initiate_Upload and
// Upload_Transfer as a configuration tool does. The facts and what is
// unconfirmed about them: compiler/sim/file_object.cpp and docs/sim.md; the
// wire format: cip/file_transfer.hpp.
#include <cstdint>

#include "cip/bytes.hpp"
#include "cip/file_transfer.hpp"
#include "live/client.hpp"

namespace edsc::live {

using cip::eds_file_instance;

// The whole file, its checksum checked; a refusal or a broken transfer is a
// error in words.
[[nodiscard]] result<cip::bytes> upload_file(client& s, std::uint32_t instance = eds_file_instance);

}  // namespace edsc::live
