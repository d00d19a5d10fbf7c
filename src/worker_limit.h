// How many worker processes the open-file limit allows.
#pragma once

#include <string>

namespace pd {

/// Each worker holds two pipe ends in the parent (four while it starts). Raises
/// the soft RLIMIT_NOFILE toward the hard one when `wanted` workers need it,
/// and returns how many fit (1 … wanted); `why` says why fewer, if fewer.
int workers_within_fd_limit(int wanted, std::string& why);

}  // namespace pd
