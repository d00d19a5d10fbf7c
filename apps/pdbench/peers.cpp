#include "peers.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstring>

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

PeerRun run_isolated(const Peer& peer, const pd::Points& a, const pd::Points& b) {
  int fd[2];
  if (pipe(fd) != 0) return {0.0, 0.0, "pipe failed"};
  const pid_t pid = fork();
  if (pid < 0) return {0.0, 0.0, "fork failed"};
  if (pid == 0) {
    close(fd[0]);
    // Twice, the second timed: the first resolves the library's symbols and
    // warms its caches in this fresh process, as an engine's loop would have.
    peer.run(a, b);
    const PeerRun r = peer.run(a, b);
    const double out[3] = {r.depth, r.ms, r.failure.empty() ? 0.0 : 1.0};
    const ssize_t n = write(fd[1], out, sizeof out);
    _exit(n == sizeof out ? 0 : 1);
  }
  close(fd[1]);
  double in[3] = {0, 0, 0};
  const ssize_t n = read(fd[0], in, sizeof in);
  close(fd[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  if (WIFSIGNALED(status))
    return {0.0, 0.0, std::string("crashed: ") + strsignal(WTERMSIG(status))};
  if (n != sizeof in) return {0.0, 0.0, "no answer"};
  return {in[0], in[1], in[2] != 0 ? "failed" : ""};
}

}  // namespace pdbench
