#include "peers.h"

namespace pdbench {

#ifdef PDBENCH_HAVE_FCL
PeerRun fcl_signed_distance(const pd::Points& a, const pd::Points& b);
#endif
#ifdef PDBENCH_HAVE_BULLET
PeerRun bullet_gjk_epa(const pd::Points& a, const pd::Points& b);
#endif

std::vector<Peer> available_peers() {
  std::vector<Peer> peers;
#ifdef PDBENCH_HAVE_FCL
  peers.push_back({"fcl", fcl_signed_distance});
#endif
#ifdef PDBENCH_HAVE_BULLET
  peers.push_back({"bullet", bullet_gjk_epa});
#endif
  return peers;
}

}  // namespace pdbench
