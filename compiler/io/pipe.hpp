#pragma once

namespace edsc::io {

// Asks for the largest pipe an unprivileged process may have
// (fs/pipe-max-size, 1 MB by default) when `fd` is a pipe, so that a whole
// document crosses it in one piece instead of 64 kB at a time, each piece a
// wake-up of both ends. Either end of a pipe may resize it. Anything that is
// not a pipe, and any refusal, leaves `fd` as it was.
void widen_pipe(int fd);

}  // namespace edsc::io
