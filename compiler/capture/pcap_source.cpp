#include "capture/pcap_source.hpp"

#include <pcap/pcap.h>

#include <cstdio>

namespace edsc::capture {

void pcap_source::closer::operator()(pcap* p) const { pcap_close(p); }

result<pcap_source, capture_error> pcap_source::open(const std::string& path) {
  char errbuf[PCAP_ERRBUF_SIZE] = {};
  // Nanoseconds asked for: libpcap scales microsecond files up, never down.
  pcap_t* p = pcap_open_offline_with_tstamp_precision(path.c_str(), PCAP_TSTAMP_PRECISION_NANO, errbuf);
  if (p == nullptr) return fail(capture_error{path + ": " + errbuf, 0});
  std::unique_ptr<pcap, closer> handle(p);
  const int link = pcap_datalink(p);
  return pcap_source(std::move(handle), link);
}

result<pcap_source, capture_error> pcap_source::open_memory(std::span<const std::uint8_t> bytes) {
  // libpcap reads a FILE; fmemopen makes one of the bytes without a copy.
  FILE* f = bytes.empty() ? nullptr : fmemopen(const_cast<std::uint8_t*>(bytes.data()), bytes.size(), "rb");
  if (f == nullptr) return fail(capture_error{"an empty capture", 0});
  char errbuf[PCAP_ERRBUF_SIZE] = {};
  pcap_t* p = pcap_fopen_offline_with_tstamp_precision(f, PCAP_TSTAMP_PRECISION_NANO, errbuf);
  if (p == nullptr) {
    std::fclose(f);  // libpcap closes the FILE only with the handle it made of it
    return fail(capture_error{errbuf, 0});
  }
  std::unique_ptr<pcap, closer> handle(p);
  const int link = pcap_datalink(p);
  return pcap_source(std::move(handle), link);
}

result<std::optional<frame>, capture_error> pcap_source::next() {
  pcap_pkthdr* header = nullptr;
  const u_char* data = nullptr;
  const int rc = pcap_next_ex(handle_.get(), &header, &data);
  if (rc == PCAP_ERROR_BREAK) return std::optional<frame>{};  // end of file
  if (rc != 1) {
    // libpcap names the fault ("truncated dump file; tried to read ...").
    return fail(capture_error{pcap_geterr(handle_.get()), read_ + 1});
  }
  ++read_;
  frame f;
  f.number = read_;
  f.time = {static_cast<std::int64_t>(header->ts.tv_sec), static_cast<std::uint32_t>(header->ts.tv_usec)};
  f.link_type = link_type_;
  f.captured_length = header->caplen;
  f.original_length = header->len;
  f.bytes = {data, header->caplen};
  return std::optional<frame>{f};
}

}  // namespace edsc::capture
