// The libraries a developer would use instead (issue 29), run on pdbench's pairs
// in the same process: FCL's signed distance (GJK + EPA) and Bullet's
// btGjkEpaSolver2. Each is compiled in only when its Debian package is found
// (CMakeLists.txt); scripts/setup.sh installs neither: measurement only.
#pragma once

#include <string>
#include <vector>

#include "geometry/types.h"

namespace pdbench {

/// One peer query: the depth it reports (world units, 0 when it says apart or
/// touching), the time of the query alone (its shapes are built before the clock
/// starts, as an engine builds them once per part), and why it gave no depth.
struct PeerRun {
  double depth = 0.0;
  double ms = 0.0;
  std::string failure;  ///< empty, or what went wrong (an exception, NaN, EPA failed)
};

struct Peer {
  std::string name;
  PeerRun (*run)(const pd::Points& a, const pd::Points& b);
};

/// The peers compiled into this pdbench (none, FCL, Bullet or both).
std::vector<Peer> available_peers();

/// Runs one query in a child process: FCL's libccd aborts on an assertion on
/// some contacts, which must cost only that pair (counted as failed, depth 0).
PeerRun run_isolated(const Peer& peer, const pd::Points& a, const pd::Points& b);

}  // namespace pdbench
