#pragma once
// Mapping an input instead of reading it: the page cache's pages are used in
// place, with no copy and no fresh pages to fault in (about 2 µs a page on
// the reference machine). The largest corpus file is ready in 0.05 ms
// instead of 0.25-0.5 ms, and 16 400 of the 64 MB file's 78 200 page faults
// go (docs/performance.md, fifth round).
//
// A mapped file that another process truncates meanwhile raises SIGBUS when
// the vanished pages are touched. edsc does not die of that: a handler puts
// zero pages where the file's were and marks the mapping changed, the reader
// carries on over zeros, and its caller, seeing changed(), reports that the
// file changed while it was read and drops what it made of it
// (source_file::changed()).
#include <cstdint>
#include <string>

#include "io/read_file.hpp"
#include "source/source_file.hpp"

namespace edsc::io {

// read_source's checks and errors, then the bytes mapped where that pays
// (files of 16 kB and more that do not end on a page boundary, so that a NUL
// follows the bytes as it does a read file's), read otherwise. A caller that
// acts on what it made of the bytes asks the source's changed() first.
[[nodiscard]] read_result map_source(const std::string& path, std::uint64_t max_bytes = default_max_input_bytes);

// What a caller reports for a source whose changed() is true.
[[nodiscard]] io_error changed_while_read(const std::string& path);

}  // namespace edsc::io
