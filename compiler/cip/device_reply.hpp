#pragma once
// The device side of the wire format, replies out: the encapsulation replies
// a target sends (ListIdentity, ListServices, errors), CIP replies with
// their status, and the Connection Manager's replies. Each is the inverse of
// a decoder the client uses, so the two are tested against each other.
#include <cstdint>
#include <span>

#include "cip/bytes.hpp"
#include "cip/connection_manager.hpp"
#include "cip/encap.hpp"

namespace edsc::cip {

// A reply header with `status` (requests always carry 0) and `data`.
[[nodiscard]] inline encoded encode_encap_reply(command cmd, std::uint32_t session, encap_status status,
                                                const sender_context& context, byte_view data) {
  return encode_encap(cmd, session, context, data, status);
}
// An error reply: the header alone, with `status`.
[[nodiscard]] bytes encap_reply_header_only(command cmd, std::uint32_t session, encap_status status,
                                            const sender_context& context);

// Identity attributes 1-7 in wire order, then the state (attribute 8).
void put_identity_fields(bytes& b, const identity& id);
// ListIdentity reply data: one identity item with the socket address.
[[nodiscard]] bytes list_identity_reply(const identity& id);
// ListServices reply data: the one "Communications" service, CIP over TCP and UDP class 0/1.
[[nodiscard]] bytes list_services_reply();

// Reply service (request | 0x80), reserved, general status, no additional
// status, data.
[[nodiscard]] bytes encode_reply(service request_service, general_status general, byte_view data = {});
// The same with additional status words (an extended status first); refused
// when there are more than its size byte counts (255).
[[nodiscard]] encoded encode_reply_with_status(service request_service, general_status general,
                                               std::span<const std::uint16_t> additional, byte_view data = {});

// Refused when the application reply is longer than its size byte says (255 words).
[[nodiscard]] encoded forward_open_ok_data(const forward_open_reply& r);
// The data of a refused Forward_Open or Forward_Close and of a Forward_Close
// reply: connection serial, originator vendor and serial, then a size byte
// (remaining path, application reply) of 0 and a reserved byte.
[[nodiscard]] bytes connection_triple_data(std::uint16_t serial, std::uint16_t vendor, std::uint32_t originator_serial);

}  // namespace edsc::cip
