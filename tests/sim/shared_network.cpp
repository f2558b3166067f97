// tests/live's namespace helper, compiled into this suite too: one source of
// truth for building and removing test networks (tests/sim picks its own
// names and addresses through network_options).
#include "live/test_network.cpp"  // NOLINT(bugprone-suspicious-include)
